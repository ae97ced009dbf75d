/**
 * Two-position synthesis with a rocker output (Norton, "Design of Machinery", ch. 5): a crank-rocker whose rocker
 * O4B swings between two given positions B1 and B2, with a chosen quick-return time ratio Q.
 *
 * At the rocker's two extremes crank and coupler are collinear: |O2 B| = r3 + r2 (extended) at one and r3 − r2
 * (folded) at the other, so r2 = (|O2 Bext| − |O2 Bfold|) / 2 and r3 = (|O2 Bext| + |O2 Bfold|) / 2. Between them
 * the crank turns π + α one way and π − α the other, α being the angle B1 O2 B2, so Q = (π + α) / (π − α) and
 * α = π (Q − 1) / (Q + 1). O2 therefore lies where B1B2 subtends α: for Q = 1 on the line B1B2 outside the segment
 * (Norton's Example 5-1), otherwise on the circular arc of that inscribed angle (Norton's quick-return
 * construction, a line through B1 and one through B2 at α to it). The designer fixes the one free choice left by
 * the ground length |O2 O4|; every such O2 (up to four) is returned, best transmission angle first. The result is
 * always a Grashof crank-rocker: the two dead-centre triangles give r2 + r_i ≤ r_j + r_k for each arrangement.
 */
import { PI, designMetrics } from '../solver';
import type { Point } from '../solver';
import { fourBarFromJoints } from './placed';
import type { PlacedFourBar } from './types';
import { checkFiniteNumber, checkPoint, checkPositive, show } from './validate';

/** The job: rocker pivot, rocker length, its first position and signed swing (radians), time ratio and ground length. */
export interface TwoPositionRockerTask {
  /** The rocker's fixed pivot in the plane. */
  O4: Point;
  /** Rocker length |O4 B| (r4). */
  rocker: number;
  /** Direction of O4→B at the first position (radians, from +x). */
  startAngle: number;
  /** Signed turn of the rocker from the first position to the second (radians), 0 < |swing| < π. */
  swing: number;
  /** Ground length |O2 O4| (r1); the one free choice of the construction. */
  ground: number;
  /** Quick-return time ratio Q ≥ 1 (default 1: the crank takes as long to swing the rocker out as back). */
  timeRatio?: number;
}

/** One crank-rocker doing the job, with the facts that check it (from the solver's designMetrics). */
export interface TwoPositionRocker {
  /** The design; its coupler point P is the rocker pin B. */
  design: PlacedFourBar;
  /** θ2 (radians, from the design's ground line) at the first and second rocker positions (the dead centres). */
  theta2: [number, number];
  /** The rocker's swing (radians) and the time ratio, as designMetrics finds them on the design. */
  swing: number;
  timeRatio: number;
  /** Extremes of the transmission angle over the cycle (radians). */
  transmission: { min: number; max: number };
}

/**
 * Every crank-rocker (up to four) whose rocker swings between the task's two positions with its time ratio and
 * ground length, best minimum transmission angle (nearest 90°) first; empty when no crank pivot at that distance
 * sees the positions at the needed angle (for Q = 1 the ground must exceed the rocker). Throws for bad input,
 * naming it (|swing| in (0, π), Q ≥ 1, positive lengths).
 */
export function twoPositionRocker(task: TwoPositionRockerTask): TwoPositionRocker[] {
  if (typeof task !== 'object' || task === null) throw new Error(`task must be an object, got ${show(task)}`);
  checkPoint('O4', task.O4);
  checkPositive('rocker', task.rocker, 'length');
  checkFiniteNumber('startAngle', task.startAngle, 'angle in radians');
  checkFiniteNumber('swing', task.swing, 'angle in radians');
  if (!(Math.abs(task.swing) > 0 && Math.abs(task.swing) < PI)) {
    throw new Error(`swing must be a turn between 0 and π radians either way, got ${show(task.swing)}`);
  }
  checkPositive('ground', task.ground, 'length');
  const Q = task.timeRatio ?? 1;
  if (typeof Q !== 'number' || !Number.isFinite(Q) || Q < 1) {
    throw new Error(`timeRatio must be a finite number ≥ 1, got ${show(Q)}`);
  }
  const { O4, rocker: r4, ground: r1 } = task;
  const at = (angle: number): Point => ({ x: O4.x + r4 * Math.cos(angle), y: O4.y + r4 * Math.sin(angle) });
  const B1 = at(task.startAngle);
  const B2 = at(task.startAngle + task.swing);
  const alpha = (PI * (Q - 1)) / (Q + 1);
  const results: TwoPositionRocker[] = [];
  for (const O2 of crankPivots(O4, B1, B2, r1, alpha)) {
    const built = crankRocker(O2, O4, B1, B2);
    if (built) results.push(built);
  }
  const margin = (r: TwoPositionRocker) => Math.min(r.transmission.min, PI - r.transmission.max);
  return results.sort((a, b) => margin(b) - margin(a));
}

/** Points at distance r1 from O4 that see the chord B1B2 under the angle alpha (radians, in [0, π)). */
function crankPivots(O4: Point, B1: Point, B2: Point, r1: number, alpha: number): Point[] {
  const M = { x: (B1.x + B2.x) / 2, y: (B1.y + B2.y) / 2 };
  const c = Math.hypot(B2.x - B1.x, B2.y - B1.y);
  const u = { x: (B2.x - B1.x) / c, y: (B2.y - B1.y) / c };
  const n = { x: -u.y, y: u.x };
  const out: Point[] = [];
  if (alpha === 0) {
    // O2 on the line B1B2, outside the segment: |O2 M| > c/2.
    const h = (O4.x - M.x) * u.x + (O4.y - M.y) * u.y;
    const foot = { x: M.x + h * u.x, y: M.y + h * u.y };
    const d2 = (O4.x - foot.x) ** 2 + (O4.y - foot.y) ** 2;
    const t = Math.sqrt(r1 * r1 - d2);
    if (!Number.isFinite(t)) return out;
    for (const s of [t, -t]) {
      const p = { x: foot.x + s * u.x, y: foot.y + s * u.y };
      if (Math.abs((p.x - M.x) * u.x + (p.y - M.y) * u.y) > c / 2) out.push(p);
    }
    return out;
  }
  // The inscribed-angle circles: centre on the chord's bisector at (c/2) cot α either side, radius c / (2 sin α).
  const R = c / (2 * Math.sin(alpha));
  const k = c / 2 / Math.tan(alpha);
  for (const side of [1, -1]) {
    const K = { x: M.x + side * k * n.x, y: M.y + side * k * n.y };
    for (const p of circleCircle(K, R, O4, r1)) {
      const ax = B1.x - p.x;
      const ay = B1.y - p.y;
      const bx = B2.x - p.x;
      const by = B2.y - p.y;
      const seen = Math.atan2(Math.abs(ax * by - ay * bx), ax * bx + ay * by);
      if (Math.abs(seen - alpha) < 1e-9 * (1 + alpha)) out.push(p);
    }
  }
  return out;
}

/** Intersections of two circles (none, one when tangent, or two). */
function circleCircle(P: Point, R: number, Q: Point, r: number): Point[] {
  const dx = Q.x - P.x;
  const dy = Q.y - P.y;
  const d = Math.hypot(dx, dy);
  if (!(d > 0) || d > R + r || d < Math.abs(R - r)) return [];
  const a = (R * R - r * r + d * d) / (2 * d);
  const h = Math.sqrt(Math.max(0, R * R - a * a));
  const mx = P.x + (a * dx) / d;
  const my = P.y + (a * dy) / d;
  if (h === 0) return [{ x: mx, y: my }];
  return [
    { x: mx - (h * dy) / d, y: my + (h * dx) / d },
    { x: mx + (h * dy) / d, y: my - (h * dx) / d },
  ];
}

/** The crank-rocker with crank pivot O2 whose dead centres put the rocker pin at B1 and B2; null if r2 would be 0. */
function crankRocker(O2: Point, O4: Point, B1: Point, B2: Point): TwoPositionRocker | null {
  const d1 = Math.hypot(B1.x - O2.x, B1.y - O2.y);
  const d2 = Math.hypot(B2.x - O2.x, B2.y - O2.y);
  const r2 = Math.abs(d1 - d2) / 2;
  if (!(r2 > 1e-12 * (d1 + d2))) return null;
  // Extended at the farther position (crank along O2→B), folded at the nearer (crank pointing away from B).
  const pin = (B: Point, d: number, extended: boolean): Point => {
    const k = (extended ? r2 : -r2) / d;
    return { x: O2.x + k * (B.x - O2.x), y: O2.y + k * (B.y - O2.y) };
  };
  const A1 = pin(B1, d1, d1 > d2);
  const A2 = pin(B2, d2, d2 > d1);
  const { design, theta2: t1 } = fourBarFromJoints({ O2, A: A1, B: B1, O4, P: B1 });
  const t2 = fourBarFromJoints({ O2, A: A2, B: B2, O4, P: B2 }).theta2;
  const m = designMetrics(design.links, design.branch);
  return {
    design,
    theta2: [t1, t2],
    swing: m.output?.swing ?? NaN,
    timeRatio: m.timeRatio ?? NaN,
    transmission: { min: m.transmission.min, max: m.transmission.max },
  };
}
