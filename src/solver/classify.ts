import { PI, TWO_PI } from './angles';
import { Assembly, assemblyFactors, newAssemblyFactors, planClosedForm } from './closedForm';
import type { ClosedFormPlan } from './closedForm';
import { exactSumOfProducts, sumOfProducts } from './exact';
import type { AngleInterval, Classification, InputRange, Linkage, LinkageType } from './types';
import { normalizeLinkage, validateLinkage } from './validate';

/** Sum2's error bound for four normalised lengths (< 1 each): below it the sum is formed exactly. */
const EXACT_BELOW = 1e-29;

/** Sum of four lengths with the signs given, its sign exact (Sum2, or BigInt for a near-tie). */
function signedSum(a: number, b: number, c: number, d: number): number {
  let s = sumOfProducts([a, b, c, d]);
  if (Math.abs(s.hi) <= EXACT_BELOW) s = exactSumOfProducts([a, b, c, d]);
  return s.hi + s.lo;
}

/** Most ulp-steps an endpoint is moved inward before the sweep's own test calls it reachable. */
const INWARD_STEPS = 64;

/**
 * The endpoint t moved towards `towards` until the closed form's reachability test (the one sweep
 * uses) accepts it, in steps growing from one ulp; null when none is found before passing `towards`.
 */
function inward(plan: ClosedFormPlan, t: number, towards: number): number | null {
  const f = newAssemblyFactors();
  const dir = towards >= t ? 1 : -1;
  let step = Math.max(Number.MIN_VALUE, Math.abs(t) * Number.EPSILON * 0.5);
  let x = t;
  for (let k = 0; k < INWARD_STEPS; k++) {
    if (dir * (towards - x) < 0) return null;
    if (assemblyFactors(plan, x, f) !== Assembly.Unreachable) return x;
    x += dir * step;
    step *= 2;
  }
  return null;
}

/** An interval with both ends moved inward to inputs sweep calls reachable; null if nothing is left. */
function roundInward(plan: ClosedFormPlan, iv: AngleInterval): AngleInterval | null {
  const lo = inward(plan, iv.lo, iv.hi);
  if (lo === null) return null;
  const hi = inward(plan, iv.hi, lo);
  if (hi === null) return null;
  return { lo, hi };
}

/**
 * Limit angle 2 atan2(sqrt(u v), sqrt(p q)) where u v = 4 r1 r2 sin^2(t/2), p q = 4 r1 r2 cos^2(t/2).
 * The half-angle form keeps full relative accuracy near 0 and pi, where acos of the textbook
 * cosine would lose half the digits.
 */
function limitAngle(u: number, v: number, p: number, q: number): number {
  return 2 * Math.atan2(Math.sqrt(Math.max(0, u * v)), Math.sqrt(Math.max(0, p * q)));
}

/**
 * Reachable input angles (radians) from the limit conditions of docs/hard-cases.md, with
 * T1 = r1 + r3 - r2 - r4, T2 = r1 + r4 - r2 - r3, T3 = r3 + r4 - r1 - r2 (signs exact). Endpoints are
 * rounded inward to angles sweep calls reachable; a flat chain (L = S + P + Q) gets a one-point
 * interval. Empty exactly when the chain cannot close (L > S + P + Q). Throws for a bad linkage.
 */
export function inputRange(l: Linkage): InputRange {
  validateLinkage(l);
  const range = limitRange(l);
  if (range.full || range.intervals.length === 0) return range;
  const plan = planClosedForm(l);
  const intervals: AngleInterval[] = [];
  for (const iv of range.intervals) {
    const r = roundInward(plan, iv);
    if (r) intervals.push(r);
  }
  return { full: false, intervals };
}

/** The input range from the limit formulas, before rounding inward. */
function limitRange(l: Linkage): InputRange {
  const { r1, r2, r3, r4 } = normalizeLinkage(l);
  // sin^2(tmax/2) ~ (r3+r4-r1+r2)(r3+r4+r1-r2); cos^2(tmax/2) ~ (r1+r2-r3-r4)(r1+r2+r3+r4)
  const uMax = signedSum(r3, r4, -r1, r2);
  const vMax = signedSum(r3, r4, r1, -r2);
  const t3 = signedSum(r3, r4, -r1, -r2);
  const sumAll = r1 + r2 + r3 + r4;
  // sin^2(tmin/2) ~ (r3-r4-r1+r2)(r3-r4+r1-r2); cos^2(tmin/2) ~ (r1+r2-r3+r4)(r1+r2+r3-r4)
  const uMin = signedSum(r3, -r4, -r1, r2);
  const vMin = signedSum(r3, -r4, r1, -r2);
  const pMin = signedSum(r1, r2, -r3, r4);
  const qMin = signedSum(r1, r2, r3, -r4);
  const t1 = signedSum(r1, r3, -r2, -r4);
  const t2 = signedSum(r1, r4, -r2, -r3);

  const hasMax = t3 < 0;
  const hasMin = t1 * t2 < 0;
  // Can the loop close at all? (r3 + r4 >= |r1 - r2| and |r3 - r4| <= r1 + r2 at some input angle.)
  if ((hasMax && uMax * vMax < 0) || pMin * qMin < 0) return { full: false, intervals: [] };
  const tMax = hasMax ? limitAngle(uMax, vMax, -t3, sumAll) : PI;
  const tMin = hasMin ? limitAngle(uMin, vMin, pMin, qMin) : 0;
  if (!hasMax && !hasMin) return { full: true, intervals: [{ lo: -PI, hi: PI }] };
  if (hasMax && !hasMin) return { full: false, intervals: [{ lo: 0 - tMax, hi: tMax }] };
  if (!hasMax && hasMin) return { full: false, intervals: [{ lo: tMin, hi: TWO_PI - tMin }] };
  // The chain can close (checked above), so tMin <= tMax up to rounding: meet in the middle if not.
  if (tMin > tMax) {
    const mid = (tMin + tMax) / 2;
    return {
      full: false,
      intervals: [
        { lo: mid, hi: mid },
        { lo: -mid, hi: -mid },
      ],
    };
  }
  const intervals: AngleInterval[] = [
    { lo: tMin, hi: tMax },
    { lo: -tMax, hi: -tMin },
  ];
  return { full: false, intervals };
}

const GRASHOF_NAMES = ['GCCC', 'GCRR', 'GRCR', 'GRRC'];
const CHANGE_NAMES = ['SCCC', 'SCRR', 'SRCR', 'SRRC'];
const GRASHOF_TYPES: LinkageType[] = ['double-crank', 'crank-rocker', 'double-rocker', 'double-rocker'];

/**
 * Grashof condition, linkage type, Barker class (as tabulated in Norton) and the input's
 * reachable range (inputRange). Change point means S + L = P + Q within a few ulps of the total
 * length; a flat chain (L = S + P + Q exactly) is a triple rocker with a one-point range;
 * 'cannot-assemble' exactly when the range is empty. Throws an Error naming the field and value
 * when l is not four positive finite lengths.
 */
export function classify(l: Linkage): Classification {
  validateLinkage(l);
  const lengths = [l.r1, l.r2, l.r3, l.r4];
  const sorted = [...lengths].sort((a, b) => a - b);
  const [S, P, Q, L] = sorted;
  const n = normalizeLinkage(l);
  const ns = [n.r1, n.r2, n.r3, n.r4].sort((a, b) => a - b);
  const total = ns[0] + ns[1] + ns[2] + ns[3];
  const excess = signedSum(ns[0], ns[3], -ns[1], -ns[2]); // S + L - P - Q
  const range = inputRange(l);
  const base = { S, L, P, Q, inputRange: range, inputIsCrank: range.full };
  // One test decides assembly for classify, inputRange and sweep: the range (empty iff L > S + P + Q).
  if (range.intervals.length === 0) {
    return { ...base, grashof: false, type: 'cannot-assemble', barker: 'none' };
  }
  const shortest = lengths.indexOf(S);
  const longest = lengths.indexOf(L);
  if (Math.abs(excess) <= 4 * Number.EPSILON * total) {
    const pairs = (ns[0] === ns[1] && ns[2] === ns[3]) || isTwoPairs(lengths);
    const allEqual = ns[0] === ns[3];
    const barker = allEqual ? 'III-6 S3X' : pairs ? 'III-5 S2X' : `III-${shortest + 1} ${CHANGE_NAMES[shortest]}`;
    return { ...base, grashof: true, type: 'change-point', barker };
  }
  if (excess < 0) {
    return {
      ...base,
      grashof: true,
      type: GRASHOF_TYPES[shortest],
      barker: `I-${shortest + 1} ${GRASHOF_NAMES[shortest]}`,
    };
  }
  return { ...base, grashof: false, type: 'triple-rocker', barker: `II-${longest + 1} RRR${longest + 1}` };
}

/** True when the four lengths form two equal pairs (within a few ulps). */
function isTwoPairs(lengths: number[]): boolean {
  const s = [...lengths].sort((a, b) => a - b);
  const close = (a: number, b: number) => Math.abs(a - b) <= 4 * Number.EPSILON * Math.max(a, b);
  return close(s[0], s[1]) && close(s[2], s[3]);
}
