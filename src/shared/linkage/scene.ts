import { TWO_PI } from '../../solver/angles';
import { couplerPoint, jointPositions } from '../../solver/kinematics';
import type { Point } from '../../solver/kinematics';
import type { Linkage } from '../../solver/types';
import type { SceneVectors } from './motionVectors';
import type { SceneForces } from './forceVectors';
import type { CouplerCurve, PoseAngles } from '../solution';
import type { SceneDesign } from './designOverlay';
import type { Bounds, PlacementTransform, ViewTransform } from '../canvas/view';
import { emptyBounds, extendBounds, extendBoundsCircle, fitView, placeBounds } from '../canvas/view';
import type { ViewOffset } from '../state/appState';

/** Joint positions (length unit) and angles (radians) of one assembled pose. */
export interface ScenePose {
  O2: Point;
  O4: Point;
  A: Point;
  B: Point;
  P: Point;
  theta2: number;
  theta3: number;
  theta4: number;
  mu: number;
}

/** A coupler curve to draw (length unit); current is the circuit the linkage is on, the others are faint. */
export interface SceneCurve {
  x: ArrayLike<number>;
  y: ArrayLike<number>;
  current: boolean;
}

/** Texts drawn on the canvas, already in the UI language. */
export interface SceneText {
  O2: string;
  O4: string;
  A: string;
  B: string;
  P: string;
  /** Shown instead of a torn linkage when it cannot assemble; null when assembled. */
  warning: string | null;
  warningDetail: string | null;
  gridSpacing: (step: string) => string;
  formatAngle: (deg: number) => string;
  formatLength: (x: number) => string;
}

/** Everything drawLinkage needs: lengths, the pose (or null), the ghost branch, curves, toggles and texts. */
export interface LinkageScene {
  linkage: Linkage;
  theta2: number;
  pose: ScenePose | null;
  ghost: ScenePose | null;
  curves: SceneCurve[];
  showGrid: boolean;
  showAngles: boolean;
  showGhost: boolean;
  showTrace: boolean;
  text: SceneText;
  /** World bounds to fit: the crank and rocker circles and the coupler curves (stable while animating). */
  bounds: Bounds;
  /** The design overlay (dead centres, instant centres, the mu band); absent draws none. */
  design?: SceneDesign;
  /** Velocity and acceleration arrows with their scale legend; absent or null when both are off. */
  vectors?: SceneVectors | null;
  /** Pin-force arrows with their scale legend (fed by the app when Forces and its arrows are on); absent or null: none. */
  forces?: SceneForces | null;
  /** Where the linkage's frame sits in the task's plane (a synthesised design's O2 and ground); absent: the world's. */
  placement?: PlacementTransform;
  /** Points of the task to mark (synthesis targets, world coordinates). */
  markers?: readonly Point[];
}

/**
 * The view of a scene: bounds (in the linkage's frame) placed into the world with the scene's placement, grown to
 * hold its markers, fitted to width x height CSS pixels with the user's offset; the view carries the placement as
 * its frame. Without a placement or markers this is fitView(bounds, width, height, offset).
 */
export function fitScene(
  scene: Pick<LinkageScene, 'placement' | 'markers'>,
  bounds: Bounds,
  width: number,
  height: number,
  offset: ViewOffset,
): ViewTransform {
  if (!scene.placement && !scene.markers?.length) return fitView(bounds, width, height, offset);
  const world = placeBounds(bounds, scene.placement);
  for (const m of scene.markers ?? []) extendBounds(world, m.x, m.y);
  const v = fitView(world, width, height, offset);
  return scene.placement ? { ...v, frame: scene.placement } : v;
}

/** Coupler point: distance from A (length unit) and angle from AB (radians). */
export interface CouplerGeometry {
  distance: number;
  angleRad: number;
}

/** Joint positions of a solved pose (length unit); null when there is no pose or a coordinate is not finite. */
export function scenePose(l: Linkage, a: PoseAngles | null, c: CouplerGeometry): ScenePose | null {
  if (!a) return null;
  const { O2, A, B, O4 } = jointPositions(l, a.theta2, a);
  const P = couplerPoint(l, a.theta2, a.theta3, c.distance, c.angleRad);
  for (const v of [A.x, A.y, B.x, B.y, P.x, P.y]) if (!Number.isFinite(v)) return null;
  return { O2, O4, A, B, P, theta2: a.theta2, theta3: a.theta3, theta4: a.theta4, mu: a.mu };
}

/** Picks which curves are current: a branch curve when the input turns fully, else the circuit holding theta2. */
export function sceneCurves(curves: readonly CouplerCurve[], branch: string, theta2Rad: number): SceneCurve[] {
  return curves.map((c) => {
    if (!c.rocking) return { x: c.x, y: c.y, current: c.branch === branch };
    const k = Math.ceil((c.loRad - theta2Rad) / TWO_PI);
    const t = theta2Rad + TWO_PI * k;
    return { x: c.x, y: c.y, current: t <= c.hiRad + 1e-12 };
  });
}

/** The swept cycle of one branch as far as bounds need it: rocker angles (radians) and P (length unit). */
export interface BranchExtent {
  theta4: ArrayLike<number>;
  px: ArrayLike<number>;
  py: ArrayLike<number>;
}

/**
 * Bounds that stay put while the linkage moves (length unit): the crank circle, O4, and over the whole
 * cycle of each given branch the rocker pin B and the coupler point P, plus any extra curves and poses.
 * Without a cycle yet, the rocker's circle stands in for B.
 */
export function sceneBounds(
  l: Linkage,
  branches: readonly BranchExtent[],
  curves: readonly SceneCurve[],
  poses: readonly (ScenePose | null)[],
): Bounds {
  const b = emptyBounds();
  extendBoundsCircle(b, 0, 0, l.r2);
  extendBounds(b, l.r1, 0);
  let any = false;
  for (const br of branches) {
    for (let i = 0; i < br.theta4.length; i++) {
      const t4 = br.theta4[i];
      if (!Number.isFinite(t4)) continue;
      any = true;
      extendBounds(b, l.r1 + l.r4 * Math.cos(t4), l.r4 * Math.sin(t4));
      extendBounds(b, br.px[i], br.py[i]);
    }
  }
  for (const c of curves) {
    const n = Math.min(c.x.length, c.y.length);
    for (let i = 0; i < n; i++) extendBounds(b, c.x[i], c.y[i]);
  }
  for (const p of poses) {
    if (!p) continue;
    any = true;
    extendBounds(b, p.B.x, p.B.y);
    extendBounds(b, p.P.x, p.P.y);
  }
  if (!any) extendBoundsCircle(b, l.r1, 0, l.r4);
  return b;
}
