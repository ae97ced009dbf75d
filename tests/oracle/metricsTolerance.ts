/**
 * Tolerances for the design metrics, from how the solver computes them (src/solver/triangle.ts,
 * deadCentres.ts, instantCenters.ts) and how well conditioned each step is.
 *
 * Angles from the half-angle form: each factor (c - a + b etc.) is a signed sum of the exact input
 * lengths, rounded once (relative error <= eps). tan(g/2) = sqrt(f1 f2 / (f3 f4)) then carries <= 2 eps
 * from the factors plus about 3 eps of its own roundings, and d g = (d tau / tau) sin g <= g (d tau / tau),
 * so the angle (and its supplement, computed the same way) has relative error of a few eps, however
 * needle-thin the triangle: conditioning with respect to the factors is at most 1. Allowed: 16 eps |g|.
 * Differences (swing, quick-return angle) come from x = (exact ratio) / sin(half-sum) and 2 asin(x) with
 * |x| <= sin(pi / 4), where asin's condition is <= 1.2: allowed 32 eps times the value.
 * Instant centres: every factor (sin, cos, the exactly kept difference hi + lo of two angles) is
 * relatively accurate for the double inputs, so each coordinate is: allowed 16 eps |coordinate|. The one
 * exception is sin(hi + lo) = sin(hi) + lo cos(hi) when it is far below ulp(hi) (I24 next to O2, at a
 * dead centre): sin(hi) ~ lo is rounded to eps |lo| <= eps^2 |hi|, an absolute error that
 * sinDifferenceFloor carries (a plain sin(a - b) would be off by eps |hi| instead).
 */
import { EPS } from './tolerance';

/** Allowance (in eps times the value) for an angle from the exact half-angle form. */
export const ANGLE_K = 16;
/** Allowance (in eps times the value) for a difference of such angles (swing, quick-return angle). */
export const DIFFERENCE_K = 32;
/** Allowance (in eps times the coordinate) for an instant centre. */
export const CENTER_K = 16;
/** Absolute floor for values that are exactly 0 (an angle cannot be relatively accurate at 0 if it is not 0). */
const FLOOR = 1e-300;

/** Tolerance (rad) for an angle computed from exact triangle factors. */
export function angleTol(ref: number): number {
  return ANGLE_K * EPS * Math.abs(ref) + FLOOR;
}

/** Tolerance (rad) for the swing or another difference of two triangle angles. */
export function differenceTol(ref: number): number {
  return DIFFERENCE_K * EPS * Math.abs(ref) + FLOOR;
}

/**
 * Tolerance for the time ratio Q = 1 + 2 d / (pi - d): d carries DIFFERENCE_K eps relative error, which
 * moves Q - 1 by that fraction (times at most 2 for d up to pi / 2 through the denominator); Q itself is
 * rounded once more.
 */
export function timeRatioTol(ref: number): number {
  return 2 * DIFFERENCE_K * EPS * Math.abs(ref - 1) + 2 * EPS * ref;
}

/** Tolerance (length unit) for one coordinate of an instant centre, plus an absolute floor if given. */
export function centerTol(ref: number, floor = 0): number {
  return CENTER_K * EPS * Math.abs(ref) + floor + FLOOR;
}

/**
 * Absolute floor (length unit) for r sin(a - b) / sinBetween where sin(a - b) is tiny: the rounding of
 * sin at the exactly kept difference, eps^2 (|a| + |b|), scaled by r / |sinBetween|.
 */
export function sinDifferenceFloor(r: number, a: number, b: number, sinBetween: number): number {
  return (CENTER_K * EPS * EPS * r * (Math.abs(a) + Math.abs(b))) / Math.abs(sinBetween);
}

/**
 * Bound on |d theta4 / d theta2| at a dead centre solved to within e3 (rad) in theta3 and e2 in theta2:
 * d theta4 / d theta2 = r2 sin(theta2 - theta3) / (r4 sin(theta4 - theta3)) and sin(theta2 - theta3) = 0
 * there, so an error e in theta2 - theta3 gives r2 e / (r4 |sin mu|); K = 10 as in tolerance.ts.
 */
export function omega4AtDeadCentreTol(r2: number, r4: number, sinMu: number, e3: number, e2: number): number {
  return (10 * r2 * (e3 + e2 + EPS)) / (r4 * Math.abs(sinMu));
}
