/**
 * Approximate motion generation: 6 to 20 poses, more than Burmester's five that a four-bar can meet exactly, met
 * in the least-squares sense. Each dyad is a moving pivot Z (coupler frame) and a fixed pivot C with a crank length R
 * minimising Σ (|P_i(Z) − C| − R)², the geometric distances of Z's positions P_i(Z) = R_i Z + d_i from a circle
 * (as MotionGen does for more than five poses, Purwar & Ge); every two of the best dyads make a four-bar, and each
 * four-bar's error at each pose is where its coupler really is when its crank points through the pose's crank pin.
 */
import { angleDiff } from '../solver';
import type { Point } from '../solver';
import { leastSquares } from './dense';
import { burmesterFourBars } from './burmester';
import type { BurmesterFourBar, BurmesterPair } from './burmester';
import { levenbergMarquardt } from './levenbergMarquardt';
import type { LeastSquaresProblem } from './levenbergMarquardt';
import { placedJoints } from './placed';
import { toPlane } from './poseFrame';
import type { Pose } from './types';
import { checkArray, checkPose } from './validate';

/** Fewest and most poses approximateMotion takes (five or fewer have exact methods). */
export const MIN_APPROX_POSES = 6;
export const MAX_APPROX_POSES = 20;
/** Most dyads kept (their pairs make at most 15 four-bars). */
export const MAX_APPROX_DYADS = 6;

/** Starts per side of the grid of moving pivots (GRID² Levenberg–Marquardt runs). */
const GRID = 5;

/** A least-squares dyad: the circle fitted to the moving pivot's positions, and how far they are from it. */
export interface ApproxDyad extends BurmesterPair {
  /** Crank (or rocker) length R, the fitted circle's radius. */
  radius: number;
  /** √(Σ (|P_i(Z) − C| − R)² / n): the pivot's root-mean-square distance from its circle, length unit. */
  rms: number;
}

/** A four-bar's error at one pose: its coupler point's distance from the pose's point and its angle's difference. */
export interface PoseError {
  /** Length unit; Infinity when the loop cannot close at that θ2. */
  position: number;
  /** Radians, wrapped to (−π, π]; NaN when the loop cannot close. */
  angle: number;
}

/** A four-bar of two least-squares dyads: as burmesterFourBars gives it, with its error at each pose. */
export interface ApproxFourBar extends BurmesterFourBar {
  errors: PoseError[];
  /** √(mean position error²) over the poses, length unit (Infinity when some pose cannot be assembled). */
  rms: number;
}

/** approximateMotion's answer: the dyads (best first) and their four-bars (fewest defects, then smallest rms). */
export interface ApproxMotion {
  dyads: ApproxDyad[];
  fourBars: ApproxFourBar[];
}

/** The mean of the poses' points and their spread (largest distance from it; 1 when the points coincide). */
function centre(poses: readonly Pose[]): { c: Point; spread: number } {
  const n = poses.length;
  const c = { x: poses.reduce((a, p) => a + p.x, 0) / n, y: poses.reduce((a, p) => a + p.y, 0) / n };
  const spread = Math.max(...poses.map((p) => Math.hypot(p.x - c.x, p.y - c.y)));
  return { c, spread: spread > 0 ? spread : 1 };
}

/** Kåsa's algebraic circle through points (linear least squares): a start for the geometric fit; null if collinear. */
function kasaCircle(points: readonly Point[]): { c: Point; r: number } | null {
  const fit = leastSquares(
    points.map((p) => [2 * p.x, 2 * p.y, 1]),
    points.map((p) => p.x * p.x + p.y * p.y),
  );
  if (!fit) return null;
  const [cx, cy, k] = fit.x;
  const r2 = k + cx * cx + cy * cy;
  return r2 > 0 ? { c: { x: cx, y: cy }, r: Math.sqrt(r2) } : null;
}

/** The geometric fit of one dyad from a start Z, by Levenberg–Marquardt on (Zx, Zy, Cx, Cy, R); null if it fails. */
function fitDyad(
  poses: readonly Pose[],
  z0: Point,
  box: { c: Point; reach: number; spread: number },
): ApproxDyad | null {
  const start = kasaCircle(poses.map((p) => toPlane(p, z0)));
  if (!start) return null;
  const n = poses.length;
  const cos = poses.map((p) => Math.cos(p.angle));
  const sin = poses.map((p) => Math.sin(p.angle));
  const { c, reach, spread } = box;
  const problem: LeastSquaresProblem = {
    m: 5,
    k: n,
    lo: Float64Array.from([-reach, -reach, c.x - reach, c.y - reach, 1e-6 * spread]),
    hi: Float64Array.from([reach, reach, c.x + reach, c.y + reach, reach]),
    evaluate(x, r, J) {
      for (let i = 0; i < n; i++) {
        const px = poses[i].x + cos[i] * x[0] - sin[i] * x[1] - x[2];
        const py = poses[i].y + sin[i] * x[0] + cos[i] * x[1] - x[3];
        const d = Math.hypot(px, py);
        if (!(d > 0)) return false;
        r[i] = d - x[4];
        if (J) {
          const ux = px / d;
          const uy = py / d;
          // d|P − C|/dZ = uᵀ R_i; d/dC = −u; d/dR = −1.
          J[i * 5] = ux * cos[i] + uy * sin[i];
          J[i * 5 + 1] = -ux * sin[i] + uy * cos[i];
          J[i * 5 + 2] = -ux;
          J[i * 5 + 3] = -uy;
          J[i * 5 + 4] = -1;
        }
      }
      return true;
    },
  };
  const clamp = (v: number, lo: number, hi: number) => Math.min(hi, Math.max(lo, v));
  const x0 = Float64Array.from([z0.x, z0.y, start.c.x, start.c.y, start.r]).map((v, i) =>
    clamp(v, problem.lo[i], problem.hi[i]),
  );
  const out = levenbergMarquardt(problem, x0, { maxIterations: 40 });
  if (!Number.isFinite(out.f)) return null;
  const [zx, zy, cx, cy, radius] = out.x;
  return { circle: { x: zx, y: zy }, center: { x: cx, y: cy }, radius, rms: Math.sqrt(out.f / n) };
}

/**
 * The least-squares dyads of 6 to 20 poses, best (smallest rms) first, at most MAX_APPROX_DYADS and each unlike the
 * others (moving and fixed pivots more than 1 % of the poses' spread apart): Levenberg–Marquardt from a 5 × 5 grid of
 * moving pivots over three spreads about the coupler frame's origin, pivots and radii kept within 50 spreads.
 * Throws for bad poses, naming them.
 */
export function approximateDyads(poses: readonly Pose[]): ApproxDyad[] {
  checkArray('poses', poses, MIN_APPROX_POSES, MAX_APPROX_POSES);
  poses.forEach((p, i) => checkPose(`poses[${i}]`, p));
  const { c, spread } = centre(poses);
  const box = { c, reach: 50 * spread, spread };
  const found: ApproxDyad[] = [];
  for (let i = 0; i < GRID; i++) {
    for (let j = 0; j < GRID; j++) {
      const at = (k: number) => (3 * spread * (2 * k - GRID + 1)) / (GRID - 1);
      const d = fitDyad(poses, { x: at(i), y: at(j) }, box);
      if (d) found.push(d);
    }
  }
  found.sort((a, b) => a.rms - b.rms);
  const near = (a: Point, b: Point) => Math.hypot(a.x - b.x, a.y - b.y) <= 0.01 * spread;
  const distinct: ApproxDyad[] = [];
  for (const d of found) {
    // A dyad at the box's edge is a straight line's stand-in (a slider), not a pivot to build.
    const atEdge = d.radius >= 0.999 * box.reach;
    if (atEdge || distinct.some((e) => near(e.center, d.center) && near(e.circle, d.circle))) continue;
    distinct.push(d);
    if (distinct.length === MAX_APPROX_DYADS) break;
  }
  return distinct;
}

/** A four-bar's error at each pose: its coupler where the crank points through the pose's crank pin. */
export function poseErrors(poses: readonly Pose[], bar: BurmesterFourBar, crank: Point, rocker: Point): PoseError[] {
  // The coupler frame's angle is the angle of A→B less its angle in the frame.
  const inFrame = Math.atan2(rocker.y - crank.y, rocker.x - crank.x);
  return poses.map((pose, i) => {
    const j = placedJoints(bar.design, bar.theta2[i]);
    if (!j) return { position: Infinity, angle: NaN };
    const angle = Math.atan2(j.B.y - j.A.y, j.B.x - j.A.x) - inFrame;
    return { position: Math.hypot(j.P.x - pose.x, j.P.y - pose.y), angle: angleDiff(angle, pose.angle) };
  });
}

/**
 * Approximate motion generation for 6 to 20 poses: the least-squares dyads and the four-bars of every two of them
 * (placed with the coupler point at the poses' frame origin, screened for defects as burmesterFourBars screens),
 * each with its error at every pose; four-bars with fewer defects first, then the smaller rms. Throws for bad poses.
 */
export function approximateMotion(poses: readonly Pose[]): ApproxMotion {
  const dyads = approximateDyads(poses);
  const fourBars = burmesterFourBars(poses, dyads)
    .map((bar): ApproxFourBar => {
      const errors = poseErrors(poses, bar, dyads[bar.pairs[0]].circle, dyads[bar.pairs[1]].circle);
      const rms = Math.sqrt(errors.reduce((a, e) => a + e.position * e.position, 0) / errors.length);
      return { ...bar, errors, rms };
    })
    .sort((a, b) => a.defects.length - b.defects.length || a.rms - b.rms);
  return { dyads, fourBars };
}
