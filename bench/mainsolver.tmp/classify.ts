import { PI, TWO_PI } from './angles';
import { sumOfProducts } from './exact';
import type { AngleInterval, Classification, InputRange, Linkage, LinkageType } from './types';
import { normalizeLinkage, validateLinkage } from './validate';

/** Exact-sign sum of four lengths with the signs given (double-double, so the sign is right). */
function signedSum(a: number, b: number, c: number, d: number): number {
  const s = sumOfProducts([a, b, c, d]);
  return s.hi + s.lo;
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
 * Reachable input angles (radians) from the limit conditions of hard-cases.md, with
 * T1 = r1 + r3 - r2 - r4, T2 = r1 + r4 - r2 - r3, T3 = r3 + r4 - r1 - r2.
 */
export function inputRange(l: Linkage): InputRange {
  validateLinkage(l);
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
  if (hasMax && !hasMin) return { full: false, intervals: [{ lo: -tMax, hi: tMax }] };
  if (!hasMax && hasMin) return { full: false, intervals: [{ lo: tMin, hi: TWO_PI - tMin }] };
  if (tMin > tMax) return { full: false, intervals: [] };
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
 * reachable range. Change point means S + L = P + Q within a few ulps of the total length.
 * Throws an Error naming the field and value when l is not four positive finite lengths.
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
  const assemblyGap = signedSum(ns[3], -ns[0], -ns[1], -ns[2]); // L - S - P - Q
  const range = inputRange(l);
  const base = { S, L, P, Q, inputRange: range, inputIsCrank: range.full };
  if (assemblyGap >= 0) {
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
