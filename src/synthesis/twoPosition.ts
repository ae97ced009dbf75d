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
import { PI, designMetrics, wrapAngle } from '../solver';
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
 * sees the positions at the needed angle with both dead centres on one assembly branch (for Q = 1 the ground must
 * exceed the rocker). Each design's own swing and time ratio (designMetrics) are the task's. Works at any scale
 * (the construction is done with the rocker as the unit). Throws for bad input, naming it (|swing| in (0, π),
 * Q ≥ 1, positive lengths).
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
  // The construction is done in the rocker's frame: O4 at the origin, the rocker as the unit of length, the
  // chord B1B2 upright and bisected by the x axis, so nothing squares a length of the task (no overflow at 1e200)
  // and a start angle of 1e16 rad does not swallow the swing (the frame turns by the start, then by half the swing).
  const h = task.swing / 2;
  const cs = Math.cos(task.startAngle);
  const ss = Math.sin(task.startAngle);
  const ch = Math.cos(h);
  const sh = Math.sin(h);
  const frame = { c: cs * ch - ss * sh, s: ss * ch + cs * sh };
  const B1 = { x: ch, y: -sh };
  const B2 = { x: ch, y: sh };
  // Q − 1 is exact (Sterbenz), so α keeps every digit as Q → 1.
  const alpha = (PI * (Q - 1)) / (Q + 1);
  const g = r1 / r4;
  const results: TwoPositionRocker[] = [];
  for (const O2 of crankPivots(g, Math.abs(h), alpha)) {
    const built = crankRocker(O2, B1, B2, Q, Math.abs(task.swing));
    if (!built) continue;
    const { local, theta2, swing, timeRatio, transmission } = built;
    const toPlane = (p: Point): Point => ({
      x: O4.x + r4 * (frame.c * p.x - frame.s * p.y),
      y: O4.y + r4 * (frame.s * p.x + frame.c * p.y),
    });
    const design: PlacedFourBar = {
      // r1 and r4 are the task's own; r2, r3 and |AP| scale with the rocker.
      links: { r1, r2: local.links.r2 * r4, r3: local.links.r3 * r4, r4 },
      branch: local.branch,
      O2: toPlane(O2),
      groundAngle: wrapAngle(local.groundAngle + Math.atan2(frame.s, frame.c)),
      pDist: local.links.r3 * r4,
      pAngle: 0,
    };
    results.push({ design, theta2, swing, timeRatio, transmission });
  }
  const margin = (r: TwoPositionRocker) => Math.min(r.transmission.min, PI - r.transmission.max);
  return results.sort((a, b) => margin(b) - margin(a));
}

/**
 * Crank pivots in the rocker's frame (O4 at the origin, rocker 1, B1,2 = (cos h, ∓sin h), h = |swing|/2 > 0) at
 * distance g from O4 that see the chord B1B2 under the angle α (radians, in [0, π)).
 *
 * The circles through B1 and B2 have their centre (c, 0) on the x axis; as B1 and B2 lie on the unit circle, such
 * a circle is x² + y² − 2cx + 2c cos h − 1 = 0, and on x² + y² = g² it meets x = cos h + (g² − 1)/(2c). The one
 * whose arc on the side s = ±1 of the chord sees B1B2 under α has c = cos h + s sin h cot α, so
 * 1/c = sin α / sin(α + s h): no cot α, whose radius runs to infinity as Q → 1, and no cancellation; at α = 0 this
 * is Q = 1's line x = cos h. The arc is the side s of the chord: s (x − cos h) > 0, or |y| > sin h when α = 0.
 */
function crankPivots(g: number, h: number, alpha: number): Point[] {
  const ch = Math.cos(h);
  const sh = Math.sin(h);
  const out: Point[] = [];
  const sides = alpha === 0 ? [0] : [1, -1];
  for (const side of sides) {
    const t = alpha === 0 ? 0 : Math.sin(alpha) / (2 * Math.sin(alpha + side * h));
    const off = (g - 1) * t * (g + 1);
    const x = ch + off;
    if (!Number.isFinite(x)) continue;
    const y2 = (g - x) * (g + x);
    if (!(y2 >= 0)) continue;
    const y = Math.sqrt(y2);
    for (const p of y === 0
      ? [{ x, y }]
      : [
          { x, y },
          { x, y: -y },
        ]) {
      const onArc = alpha === 0 ? Math.abs(p.y) > sh : side * off > 0;
      if (onArc) out.push(p);
    }
  }
  return out;
}

/**
 * The crank-rocker with crank pivot O2 (rocker's frame) whose dead centres put the rocker pin at B1 and B2, its
 * θ2 there and its metrics; null when r2 would be 0, when the two dead centres lie on opposite branches (the
 * design never reaches one of the positions), or when its own swing or time ratio is not the task's.
 */
function crankRocker(
  O2: Point,
  B1: Point,
  B2: Point,
  Q: number,
  swing: number,
): (Omit<TwoPositionRocker, 'design'> & { local: PlacedFourBar }) | null {
  const d1 = Math.hypot(B1.x - O2.x, B1.y - O2.y);
  const d2 = Math.hypot(B2.x - O2.x, B2.y - O2.y);
  // d1² − d2² = 4 y sin h (B1,2 = (cos h, ∓sin h)), so d1 − d2 without the cancellation of two near distances.
  const r2 = Math.abs((2 * O2.y * (B2.y - B1.y)) / (d1 + d2)) / 2;
  if (!(r2 > 1e-12 * (d1 + d2))) return null;
  // Extended at the farther position (crank along O2→B), folded at the nearer (crank pointing away from B).
  const pin = (B: Point, d: number, extended: boolean): Point => {
    const k = (extended ? r2 : -r2) / d;
    return { x: O2.x + k * (B.x - O2.x), y: O2.y + k * (B.y - O2.y) };
  };
  const O4 = { x: 0, y: 0 };
  const one = fourBarFromJoints({ O2, A: pin(B1, d1, d1 > d2), B: B1, O4, P: B1 });
  const two = fourBarFromJoints({ O2, A: pin(B2, d2, d2 > d1), B: B2, O4, P: B2 });
  if (one.design.branch !== two.design.branch) return null;
  const m = designMetrics(one.design.links, one.design.branch);
  if (!m.output || m.timeRatio === null) return null;
  // A safety net on the construction: the design's own stroke must be the task's (to far more than rounding).
  if (Math.abs(m.output.swing - swing) > 1e-9 * swing || Math.abs(m.timeRatio - Q) > 1e-9 * Q) return null;
  return {
    local: one.design,
    theta2: [one.theta2, two.theta2],
    swing: m.output.swing,
    timeRatio: m.timeRatio,
    transmission: { min: m.transmission.min, max: m.transmission.max },
  };
}
