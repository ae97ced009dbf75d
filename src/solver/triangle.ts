/**
 * Interior angles of triangles whose sides are signed sums of link lengths, to full relative accuracy.
 * The half-angle form tan^2(g/2) = (c - a + b)(c + a - b) / ((a + b - c)(a + b + c)) (Kahan, "Miscalculating
 * Area and Angles of a Needle-like Triangle") is evaluated with each factor summed term by term in
 * double-double (exact.ts), so a factor that cancels to 1e-12 of the links still carries all its digits:
 * the law of cosines with acos would lose half of them near 0 and pi.
 */
import { sumOfProducts } from './exact';

/** A side length given as the exact sum of signed terms (link lengths), e.g. [r2, r3] for r2 + r3. */
export type SideTerms = readonly number[];

/** An interior angle (rad, in [0, pi]) and its supplement pi - angle, each to full relative accuracy. */
export interface TriangleAngle {
  angle: number;
  supplement: number;
  /** False when a factor is negative beyond rounding: the three sides do not close (angle clamped to 0 or pi). */
  closes: boolean;
}

function exactSum(terms: readonly number[]): number {
  const s = sumOfProducts(terms);
  return s.hi + s.lo;
}

function negated(terms: SideTerms): number[] {
  return terms.map((t) => -t);
}

/**
 * Interior angle (rad) opposite side c in the triangle with sides a, b, c (each a signed sum of lengths
 * already normalised so squares cannot overflow). Angle and supplement come from two atan2 calls on the
 * same square roots, so neither is obtained by subtracting from pi. A factor that is negative means the
 * sides do not close; it is clamped to 0 (a flat triangle) and flagged.
 */
export function triangleAngle(a: SideTerms, b: SideTerms, c: SideTerms): TriangleAngle {
  const cMinusAPlusB = exactSum([...c, ...negated(a), ...b]);
  const cPlusAMinusB = exactSum([...c, ...a, ...negated(b)]);
  const aPlusBMinusC = exactSum([...a, ...b, ...negated(c)]);
  const perimeter = exactSum([...a, ...b, ...c]);
  const closes = cMinusAPlusB >= 0 && cPlusAMinusB >= 0 && aPlusBMinusC >= 0;
  // sqrt of each factor separately: the products could underflow for needle-thin triangles.
  const num = Math.sqrt(Math.max(0, cMinusAPlusB)) * Math.sqrt(Math.max(0, cPlusAMinusB));
  const den = Math.sqrt(Math.max(0, aPlusBMinusC)) * Math.sqrt(Math.max(0, perimeter));
  return { angle: 2 * Math.atan2(num, den), supplement: 2 * Math.atan2(den, num), closes };
}
