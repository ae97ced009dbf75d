import type { InputRange } from '../solver';

/** A point or vector in 3D (unit sphere for the spherical linkage, the length unit for RSSR). */
export interface Vec3 {
  x: number;
  y: number;
  z: number;
}

/**
 * A spherical four-bar on the unit sphere: arc lengths in radians, each in (0, pi), of the ground (a1), crank (a2),
 * coupler (a3) and rocker (a4); optional coupler point P at arc pDist (radians, [0, pi]) from the crank pin A, turned
 * by pAngle (radians, right hand about A) from the great circle A -> B.
 */
export interface SphericalLinkage {
  a1: number;
  a2: number;
  a3: number;
  a4: number;
  pDist?: number;
  pAngle?: number;
}

/**
 * An RSSR spatial four-bar: crank r2, coupler r3, rocker r4 (positive lengths), the axes' common normal a (>= 0,
 * along x), the output axis' tilt beta (radians, about x), the crank and rocker pins' offsets h2, h4 along their axes.
 */
export interface RSSRLinkage {
  r2: number;
  r3: number;
  r4: number;
  a: number;
  beta: number;
  h2: number;
  h4: number;
}

/** Positions, output angle and rates of one assembly; rates are zero when no input motion is given. */
export interface SpatialPose {
  A: Vec3;
  B: Vec3;
  P?: Vec3;
  /** Output angle, radians, wrapped to (-pi, pi]. */
  theta4: number;
  /** Output angular velocity (rad/s) and acceleration (rad/s^2) for the input's omega2, alpha2. */
  omega4: number;
  alpha4: number;
  velocity: { A: Vec3; B: Vec3; P?: Vec3 };
  acceleration: { A: Vec3; B: Vec3; P?: Vec3 };
}

/** Assembly branch: 'open' where (A - B) . dB/dtheta4 > 0. */
export type SpatialBranch = 'open' | 'crossed';

/** Input motion: crank angular velocity (rad/s) and acceleration (rad/s^2). */
export interface SpatialInput {
  omega2: number;
  alpha2: number;
}

/** Either spatial linkage, tagged, for the functions that serve both. */
export type SpatialModel = { kind: 'spherical'; linkage: SphericalLinkage } | { kind: 'rssr'; linkage: RSSRLinkage };

/** Motion type from which of the input and output turn fully. */
export type SpatialLinkageType =
  'crank-rocker' | 'double-crank' | 'rocker-crank' | 'double-rocker' | 'triple-rocker' | 'cannot-assemble';

/** Classification of a spatial linkage and the reachable ranges of its input and output angles (radians). */
export interface SpatialClassification {
  type: SpatialLinkageType;
  /** Spherical: the Grashof sum test on the effective arcs (S + L <= P + Q); RSSR: the crank condition (input turns fully). */
  grashof: boolean;
  /** Spherical: S + L = P + Q within rounding (branches meet). Always false for RSSR. */
  changePoint: boolean;
  inputIsCrank: boolean;
  outputIsCrank: boolean;
  /** Reachable input angles theta2. */
  inputRange: InputRange;
  /** Reachable output angles theta4. */
  outputRange: InputRange;
  /** Spherical only: the arcs the Grashof sums use (arcs over pi/2 replaced by their supplements in pairs), radians. */
  effectiveArcs?: [number, number, number, number];
}
