import type { Branch, Linkage, Point } from '../solver';

/**
 * A four-bar placed in the task's plane. O2 is the crank pivot; groundAngle is the direction O2→O4 (radians).
 * The coupler point P is given as in couplerPoint: |AP| (pDist, length unit) and its angle from AB (pAngle, radians).
 */
export interface PlacedFourBar {
  links: Linkage;
  branch: Branch;
  O2: Point;
  groundAngle: number;
  pDist: number;
  pAngle: number;
}

/** A coupler pose: where the coupler's reference point is (length unit), and how far its frame is rotated (radians). */
export interface Pose {
  x: number;
  y: number;
  angle: number;
}

/** Joint and coupler-point positions of a placed four-bar at one input angle, in the task's plane. */
export interface PlacedJoints {
  O2: Point;
  A: Point;
  B: Point;
  O4: Point;
  P: Point;
  /** Coupler and rocker angles in the task's plane (radians, from +x). */
  theta3: number;
  theta4: number;
}

/** A path-synthesis task: targets in the plane, their timing, optional placement, bounds and input constraint. */
export interface PathTask {
  targets: Point[];
  timing: { kind: 'free' } | { kind: 'step'; step: number } | { kind: 'given'; theta2: number[] };
  /** Fixed when given: the crank pivot and the ground line's direction (radians). */
  placement?: { O2: Point; groundAngle: number };
  /** length bounds r1..r4 (length unit), |AP| at most coupler, O2 inside the pivot box. */
  bounds?: { length?: [number, number]; coupler?: number; pivot?: { min: Point; max: Point } };
  /** Default 'crank': the input turns fully. */
  input?: 'crank' | 'any';
}

/** One path-synthesis answer: the design, θ2 at each target (radians, from the design's ground line), Σd² and max d. */
export interface PathSolution {
  design: PlacedFourBar;
  theta2: number[];
  error: number;
  maxDistance: number;
}
