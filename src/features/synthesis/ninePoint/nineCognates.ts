import type { DrawContext } from '../../../shared/canvas/drawContext';
import type { ViewTransform } from '../../../shared/canvas/view';
import { wrapAngle } from '../../../solver/angles';
import type { NinePointLinkage } from '../../../synthesis/ninePoint/ninePointSynthesis';
import { placedJoints } from '../../../synthesis/placed';
import type { PlacedJoints } from '../../../synthesis/types';
import { drawPlacedPose } from '../drawPlacedPose';

/**
 * How a Roberts cognate follows the moving linkage: every link of a cognate stays parallel to a line of the original
 * (its crank, its coupler or its rocker), so the cognate's input angle is one of the original's three angles in the
 * plane (which one, `source`) plus a constant: theta2 = theta2At0 + (angle − angleAt0).
 */
export interface CognateFollower {
  cognate: NinePointLinkage;
  /** The original's angle the cognate's input turns with: 0 crank, 1 coupler, 2 rocker (radians in the plane). */
  source: 0 | 1 | 2;
  /** The cognate's input angle and the original's source angle at the first point. */
  theta2At0: number;
  angleAt0: number;
}

/** The original's crank, coupler and rocker angles in the plane at a pose. */
function anglesOf(j: PlacedJoints): [number, number, number] {
  return [Math.atan2(j.A.y - j.O2.y, j.A.x - j.O2.x), wrapAngle(j.theta3), wrapAngle(j.theta4)];
}

function jointsAt(d: NinePointLinkage, k: number): PlacedJoints | null {
  return placedJoints({ ...d, branch: d.branches[k] }, d.theta2[k]);
}

/** Largest difference of two angle lists after removing the first difference (radians). */
function spread(a: number[], b: number[]): number {
  const off = a[0] - b[0];
  return Math.max(...a.map((x, k) => Math.abs(wrapAngle(x - b[k] - off))));
}

/**
 * The followers of the other cognates of a class when `moving` (one of `cognates`, as drawn) moves: for each other
 * cognate the angle of the original whose turning over the nine points matches its input's (within 1e-6 rad), or
 * none when no angle matches (then that cognate is not drawn).
 */
export function cognateFollowers(moving: NinePointLinkage, cognates: NinePointLinkage[]): CognateFollower[] {
  const n = moving.theta2.length;
  const own = Array.from({ length: n }, (_, k) => jointsAt(moving, k));
  if (own.some((j) => !j)) return [];
  const angles = own.map((j) => anglesOf(j!));
  const out: CognateFollower[] = [];
  for (const c of cognates) {
    if (c === moving) continue;
    const js = Array.from({ length: n }, (_, k) => jointsAt(c, k));
    if (js.some((j) => !j)) continue;
    // The cognate's input link in the plane at each point.
    const input = js.map((j) => Math.atan2(j!.A.y - j!.O2.y, j!.A.x - j!.O2.x));
    let best: { source: 0 | 1 | 2; err: number } | null = null;
    for (const source of [0, 1, 2] as const) {
      const err = spread(
        input,
        angles.map((a) => a[source]),
      );
      if (!best || err < best.err) best = { source, err };
    }
    if (best && best.err <= 1e-6) {
      out.push({ cognate: c, source: best.source, theta2At0: c.theta2[0], angleAt0: angles[0][best.source] });
    }
  }
  return out;
}

/**
 * The poses of the followers when the original is at pose j (its coupler point j.P): each on the assembly that puts
 * its coupler point on j.P (within 1e-6 of the linkage's size); a follower with neither is left out.
 */
export function cognatePoses(j: PlacedJoints, followers: CognateFollower[]): PlacedJoints[] {
  const now = anglesOf(j);
  const out: PlacedJoints[] = [];
  for (const f of followers) {
    const theta2 = wrapAngle(f.theta2At0 + now[f.source] - f.angleAt0);
    const { r1, r2, r3, r4 } = f.cognate.links;
    const tol = 1e-6 * Math.max(r1, r2, r3, r4, f.cognate.pDist);
    let best: PlacedJoints | null = null;
    let bestD = tol;
    for (const branch of ['open', 'crossed'] as const) {
      const q = placedJoints({ ...f.cognate, branch }, theta2);
      const d = q ? Math.hypot(q.P.x - j.P.x, q.P.y - j.P.y) : Infinity;
      if (q && d <= bestD) {
        best = q;
        bestD = d;
      }
    }
    if (best) out.push(best);
  }
  return out;
}

/** The followers' poses drawn as the moving linkage is (ground dashed), fainter, under the same view. */
export function drawCognatePoses(ctx: DrawContext, v: ViewTransform, poses: PlacedJoints[]): void {
  ctx.save();
  ctx.globalAlpha = 0.45;
  for (const p of poses) drawPlacedPose(ctx, v, p, { dashedGround: true });
  ctx.restore();
}
