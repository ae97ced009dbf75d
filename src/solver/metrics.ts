/**
 * Design metrics a designer reads after Grashof: the transmission angle's extremes over the cycle, the
 * dead centres with the rocker's swing, and the quick-return time ratio.
 *
 * Transmission angle: mu is the interior angle at B of the triangle A B O4 (sides r3, r4 and s = |A O4|),
 * the same quantity as kinematics.ts transmissionAngle, |theta4 - theta3| folded into [0, pi]:
 * cos mu = (r3^2 + r4^2 - s^2) / (2 r3 r4) with s^2 = r1^2 + r2^2 - 2 r1 r2 cos theta2. mu grows with s and
 * s with |theta2| in [0, pi], and the reachable |theta2| is one interval [a, b] (the loop closes iff
 * cos theta2 lies in a band), so the extremes sit at its ends: at theta2 = 0 (s = |r1 - r2|) or at a lower
 * limit (s = |r3 - r4|, mu = 0), and at theta2 = pi (s = r1 + r2) or at an upper limit (s = r3 + r4,
 * mu = pi). mu does not depend on the branch: both branches close the same triangle.
 */
import { PI, TWO_PI } from './angles';
import { inputRange } from './classify';
import { branchSign } from './closedForm';
import { crankRockerStroke, isCrankRocker } from './deadCentres';
import type { DeadCentre } from './deadCentres';
import { triangleAngle } from './triangle';
import type { Branch, InputRange, Linkage } from './types';
import { normalizeLinkage, validateLinkage } from './validate';

export type { DeadCentre } from './deadCentres';

/** Extremes of the transmission angle mu (rad, in [0, pi]) and the input angle theta2 (rad, in [0, pi]) of each. */
export interface TransmissionExtremes {
  min: number;
  max: number;
  /** theta2 where mu is least; -theta2 gives the same mu (mirror pose). */
  theta2AtMin: number;
  /** theta2 where mu is greatest; -theta2 gives the same mu (mirror pose). */
  theta2AtMax: number;
}

/** What designMetrics reports for one linkage and branch (all angles in radians). */
export interface DesignMetrics {
  /** Transmission angle mu in [0, pi] over the assembled part of the cycle on this branch, and where it occurs. */
  transmission: TransmissionExtremes;
  /** When the input turns fully and the output rocks: the dead-centre poses (crank and coupler collinear,
   *  extended and folded) and the rocker's swing angle. Otherwise null. */
  output: { extended: DeadCentre; folded: DeadCentre; swing: number } | null;
  /** Quick-return time ratio (>= 1) of a crank driving a rocker at constant speed; null otherwise. */
  timeRatio: number | null;
}

/**
 * The reachable |theta2| (rad) as one interval [lo, hi] within [0, pi], or null when nothing assembles.
 * Each bound is an end of inputRange as it is (an input angle the closed form assembles at), never a
 * wrapped one: an end beyond pi is 2 pi - t for the other end t of its interval (the range is symmetric),
 * and wrapping it would round at the ulp of 2 pi, far from t when t is small and possibly unreachable.
 */
function reachableAbs(range: InputRange): { lo: number; hi: number } | null {
  if (range.full) return { lo: 0, hi: PI };
  if (range.intervals.length === 0) return null;
  let lo = Infinity;
  let hi = -Infinity;
  for (const iv of range.intervals) {
    const contains = (x: number) => iv.lo <= x && x <= iv.hi;
    if (contains(0) || contains(TWO_PI) || contains(-TWO_PI)) lo = 0;
    if (contains(PI) || contains(-PI)) hi = PI;
    for (const end of [iv.lo, iv.hi]) {
      if (!(end >= -PI && end <= PI)) continue;
      const a = Math.abs(end);
      lo = Math.min(lo, a);
      hi = Math.max(hi, a);
    }
  }
  return { lo, hi };
}

/**
 * Extremes of the transmission angle over the reachable input angles (see the module comment); NaN in
 * every field when the linkage cannot be assembled at any theta2. l must be a valid linkage.
 */
export function transmissionExtremes(l: Linkage, range: InputRange): TransmissionExtremes {
  const abs = reachableAbs(range);
  if (!abs) return { min: NaN, max: NaN, theta2AtMin: NaN, theta2AtMax: NaN };
  const { r1, r2, r3, r4 } = normalizeLinkage(l);
  // mu is the angle opposite s in the triangle (r3, r4, s); s = |r1 - r2| and r1 + r2 are summed exactly.
  const inner = r1 >= r2 ? [r1, -r2] : [r2, -r1];
  const min = abs.lo === 0 ? triangleAngle([r3], [r4], inner).angle : 0;
  const max = abs.hi === PI ? triangleAngle([r3], [r4], [r1, r2]).angle : PI;
  return { min, max, theta2AtMin: abs.lo, theta2AtMax: abs.hi };
}

/**
 * Transmission-angle extremes, dead centres, rocker swing and time ratio of a linkage on one branch
 * (radians; see DesignMetrics). Exact to rounding: every angle comes from cancellation-free triangle
 * factors. Throws an Error naming the field and value for a bad length or a branch other than
 * 'open' / 'crossed'.
 */
export function designMetrics(l: Linkage, branch: Branch): DesignMetrics {
  validateLinkage(l);
  const sigma = branchSign(branch);
  const range = inputRange(l);
  const transmission = transmissionExtremes(l, range);
  if (!isCrankRocker(l, range.full)) return { transmission, output: null, timeRatio: null };
  const { extended, folded, swing, timeRatio } = crankRockerStroke(l, sigma);
  return { transmission, output: { extended, folded, swing }, timeRatio };
}
