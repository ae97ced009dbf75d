import { PI, TWO_PI } from '../solver';
import type { AngleInterval, InputRange } from '../solver';
import { Closure, newPoint } from './point';
import { planRSSR, rssrAt } from './rssr';
import type { RSSRPlan } from './rssr';
import { planSpherical, sphericalAt } from './spherical';
import type { SphericalPlan } from './spherical';
import type { RSSRLinkage, SpatialClassification, SpatialLinkageType, SphericalLinkage } from './types';

const HALF_TURN = PI;
const FULL_TURN = TWO_PI;
const EPS = Number.EPSILON;
const FULL_RANGE: InputRange = { full: true, intervals: [{ lo: -PI, hi: PI }] };
const EMPTY_RANGE: InputRange = { full: false, intervals: [] };

/**
 * Angles t (radians, [0, pi]) at which the arc from the arm's tip to the far pivot is `target`, for an arm of arc
 * `arm` on a ground of arc `ground` (t = 0 towards the far pivot): from sin^2(d/2) = sin^2((g - r)/2) + sin g sin r
 * sin^2(t/2) and its cosine twin, written as products so the angle keeps its digits at both ends.
 */
function armAngleAt(ground: number, arm: number, target: number): number {
  const s = Math.max(0, Math.sin((target - ground + arm) / 2) * Math.sin((target + ground - arm) / 2));
  const c = Math.max(0, Math.sin((ground + arm - target) / 2) * Math.sin((ground + arm + target) / 2));
  return 2 * Math.atan2(Math.sqrt(s), Math.sqrt(c));
}

/**
 * Where an arm of arc `arm` on a ground of arc `ground` can turn (its angle from the far pivot's direction) when the
 * other two arcs f1, f2 close the loop: the arc d from the arm's tip to the far pivot grows monotonically with |t| from
 * |g - r| to min(g + r, 2 pi - g - r) and must lie in [|f1 - f2|, min(f1 + f2, 2 pi - f1 - f2)].
 */
function armRange(ground: number, arm: number, f1: number, f2: number): InputRange {
  const dMin = Math.abs(ground - arm);
  const dMax = Math.min(ground + arm, FULL_TURN - ground - arm);
  const lo = Math.abs(f1 - f2);
  const hi = Math.min(f1 + f2, FULL_TURN - f1 - f2);
  if (hi < dMin || lo > dMax || hi < lo) return EMPTY_RANGE;
  const capped = hi < dMax;
  const holed = lo > dMin;
  if (!capped && !holed) return FULL_RANGE;
  const tMax = capped ? armAngleAt(ground, arm, hi) : HALF_TURN;
  const tMin = holed ? armAngleAt(ground, arm, lo) : 0;
  if (!holed) return { full: false, intervals: [{ lo: -tMax, hi: tMax }] };
  if (!capped) return { full: false, intervals: [{ lo: tMin, hi: FULL_TURN - tMin }] };
  return {
    full: false,
    intervals: [
      { lo: -tMax, hi: -tMin },
      { lo: tMin, hi: tMax },
    ],
  };
}

/** An endpoint moved towards `towards` in ulp steps (doubling) until the solver closes the loop there; null if none. */
function inward(closes: (t: number) => boolean, t: number, towards: number): number | null {
  const dir = towards >= t ? 1 : -1;
  let step = Math.max(Number.MIN_VALUE, Math.abs(t) * EPS * 0.5);
  let x = t;
  for (let k = 0; k < 64; k++) {
    if (dir * (towards - x) < 0) return null;
    if (closes(x)) return x;
    x += dir * step;
    step *= 2;
  }
  return null;
}

/** A range with every finite endpoint rounded inward to an angle the solver closes (the sweeps' own test). */
function roundInward(range: InputRange, closes: (t: number) => boolean): InputRange {
  if (range.full) return range;
  const intervals: AngleInterval[] = [];
  for (const iv of range.intervals) {
    const lo = inward(closes, iv.lo, iv.hi);
    const hi = lo === null ? null : inward(closes, iv.hi, lo);
    if (lo !== null && hi !== null) intervals.push({ lo, hi });
  }
  return { full: false, intervals };
}

/** Either joint's closure test at one angle, on the open branch (both branches close together). */
function sphericalCloses(plan: SphericalPlan): (t: number) => boolean {
  const p = newPoint();
  return (t) => sphericalAt(plan, t, -1, p) !== Closure.Unreachable;
}

/** Reachable crank angles theta2 of a spherical four-bar (radians; throws an Error naming the field for bad arcs). */
export function sphericalInputRange(l: SphericalLinkage): InputRange {
  const plan = planSpherical(l);
  return roundInward(armRange(l.a1, l.a2, l.a3, l.a4), sphericalCloses(plan));
}

/** Reachable rocker angles theta4 of a spherical four-bar (radians): the rocker as an arm seen from O4, turned by pi. */
export function sphericalOutputRange(l: SphericalLinkage): InputRange {
  planSpherical(l);
  const r = armRange(l.a1, l.a4, l.a3, l.a2);
  if (r.full) return r;
  // theta4 = pi - t (t measured from O4 towards O2): |t| <= tMax becomes [pi - tMax, pi + tMax]; lo kept in (-pi, pi].
  const intervals = r.intervals.map((iv) => {
    const shift = HALF_TURN - iv.hi > HALF_TURN ? FULL_TURN : 0;
    return { lo: HALF_TURN - iv.hi - shift, hi: HALF_TURN - iv.lo - shift };
  });
  return { full: false, intervals: intervals.sort((a, b) => a.lo - b.lo) };
}

/**
 * The arcs the spherical Grashof sums use: every arc over pi/2 replaced by its supplement; when an odd number of arcs
 * were over pi/2, the one then closest to pi/2 goes back to its supplement (an even number of supplements is an
 * equivalent linkage, antipodal pins; one stays over pi/2). Checked against every joint's exact range in the tests.
 */
export function effectiveArcs(l: SphericalLinkage): [number, number, number, number] {
  const arcs = [l.a1, l.a2, l.a3, l.a4];
  const over = arcs.filter((a) => a > HALF_TURN / 2).length;
  const e = arcs.map((a) => (a > HALF_TURN / 2 ? HALF_TURN - a : a));
  if (over % 2 === 1) {
    let k = 0;
    for (let j = 1; j < 4; j++) if (e[j] > e[k]) k = j;
    e[k] = HALF_TURN - e[k];
  }
  return [e[0], e[1], e[2], e[3]];
}

function typeOf(inputIsCrank: boolean, outputIsCrank: boolean, grashof: boolean, empty: boolean): SpatialLinkageType {
  if (empty) return 'cannot-assemble';
  if (inputIsCrank && outputIsCrank) return 'double-crank';
  if (inputIsCrank) return 'crank-rocker';
  if (outputIsCrank) return 'rocker-crank';
  return grashof ? 'double-rocker' : 'triple-rocker';
}

/**
 * Classifies a spherical four-bar: the Grashof sums S + L <= P + Q on the effective arcs (supplement rule), change
 * point at equality (within rounding), and the exact reachable ranges of theta2 and theta4. Throws for bad arcs.
 */
export function classifySpherical(l: SphericalLinkage): SpatialClassification {
  const inputRange = sphericalInputRange(l);
  const outputRange = sphericalOutputRange(l);
  const e = effectiveArcs(l);
  const [s, p, q, L] = [...e].sort((x, y) => x - y);
  const margin = p + q - (s + L);
  return {
    type: typeOf(inputRange.full, outputRange.full, margin >= 0, inputRange.intervals.length === 0),
    grashof: margin >= 0,
    changePoint: Math.abs(margin) <= 8 * EPS * FULL_TURN,
    inputIsCrank: inputRange.full,
    outputIsCrank: outputRange.full,
    inputRange,
    outputRange,
    effectiveArcs: e,
  };
}

/** Samples of the RSSR range scan over a turn; intervals narrower than about 2 pi / SCAN_SAMPLES may be missed. */
export const SCAN_SAMPLES = 1440;

/**
 * The set where closes(t) holds over a turn, from SCAN_SAMPLES samples and bisection of every change to the double
 * (so each endpoint is an angle the test accepts). Intervals wrap past pi as one interval [lo, hi], hi up to lo + 2 pi.
 */
export function scanRange(closes: (t: number) => boolean): InputRange {
  const n = SCAN_SAMPLES;
  const at = (k: number) => -HALF_TURN + (FULL_TURN * k) / n;
  const ok: boolean[] = [];
  for (let k = 0; k < n; k++) ok.push(closes(at(k)));
  const firstOff = ok.indexOf(false);
  if (firstOff < 0) return FULL_RANGE;
  if (!ok.includes(true)) return EMPTY_RANGE;
  // The boundary in (lo, hi) between closes(lo) === loOk and the other value, bisected to the double; the closing side.
  const edge = (lo: number, hi: number, loOk: boolean): number => {
    let a = lo;
    let b = hi;
    for (let i = 0; i < 80; i++) {
      const m = a + (b - a) / 2;
      if (m <= a || m >= b) break;
      if (closes(m) === loOk) a = m;
      else b = m;
    }
    return loOk ? a : b;
  };
  // Walk a turn from a sample that does not close, on unwrapped angles u_j = t(firstOff) + j h.
  const h = FULL_TURN / n;
  const u = (j: number) => at(firstOff) + j * h;
  const intervals: AngleInterval[] = [];
  let lo = 0;
  for (let j = 0; j < n; j++) {
    const here = ok[(firstOff + j) % n];
    const next = ok[(firstOff + j + 1) % n];
    if (!here && next) lo = edge(u(j), u(j + 1), false);
    if (here && !next) {
      const hi = edge(u(j), u(j + 1), true);
      const shift = lo > HALF_TURN ? FULL_TURN : 0;
      intervals.push({ lo: lo - shift, hi: hi - shift });
    }
  }
  intervals.sort((x, y) => x.lo - y.lo);
  return { full: false, intervals };
}

function rssrCloses(plan: RSSRPlan): (t: number) => boolean {
  const p = newPoint();
  return (t) => rssrAt(plan, t, -1, p) !== Closure.Unreachable;
}

/** Reachable crank angles theta2 of an RSSR linkage (radians), by scanRange on the solver's own closure test. */
export function rssrInputRange(l: RSSRLinkage): InputRange {
  return scanRange(rssrCloses(planRSSR(l)));
}

/**
 * Reachable rocker angles theta4 of an RSSR linkage (radians): B closes the loop when r3 lies between its least and
 * greatest distance to the crank pin's circle (centre (0, 0, h2), radius r2, about z).
 */
export function rssrOutputRange(l: RSSRLinkage): InputRange {
  const plan = planRSSR(l);
  const { r2, r3, r4, a, h2, h4, cb, sb } = plan;
  return scanRange((t4) => {
    const c4 = Math.cos(t4);
    const s4 = Math.sin(t4);
    const bx = a + r4 * c4;
    const by = -h4 * sb + r4 * s4 * cb;
    const bz = h4 * cb + r4 * s4 * sb - h2;
    const radial = Math.hypot(bx, by);
    const near = Math.hypot(radial - r2, bz);
    const far = Math.hypot(radial + r2, bz);
    const tol = 4 * EPS * (far + r3);
    return near <= r3 + tol && r3 <= far + tol;
  });
}

/** Classifies an RSSR linkage: the crank condition (theta2 turns fully), the output's, and both reachable ranges. */
export function classifyRSSR(l: RSSRLinkage): SpatialClassification {
  const inputRange = rssrInputRange(l);
  const outputRange = rssrOutputRange(l);
  return {
    type: typeOf(inputRange.full, outputRange.full, true, inputRange.intervals.length === 0),
    grashof: inputRange.full,
    changePoint: false,
    inputIsCrank: inputRange.full,
    outputIsCrank: outputRange.full,
    inputRange,
    outputRange,
  };
}
