/**
 * Accuracy a backward-stable solver can reach, from docs/hard-cases.md "Conditioning".
 *
 * A backward-stable solve is exact for coordinates perturbed by about ea = 2 eps Lmax (A, B and O4 all
 * live at that scale). In the triangle A B O4 that moves the angle at A by about ea / (r3 |sin mu|) and
 * the angle at O4 by ea / (r4 |sin mu|) (law of sines; mu = t4 - t3 is the angle at B), and the
 * direction of A -> O4 by ea / s. Near a fold sin mu -> 0 and the first-order term is replaced by
 * the square-root law of acos: K ea / (r sqrt(sin^2 mu + g)) with g = ea / min(r3, r4), which is the
 * section's "K eps / sqrt(d + eps)" (sin^2 mu grows like the distance d to the limit) and saturates
 * at K sqrt(ea / r), i.e. K times the ~1e-8 rad of a limit position for links of comparable size.
 * With very unequal links the ratio Lmax / r gives "eps * (longest / shortest)".
 * K = 10 is the "about 10 eps * condition" allowance of that section.
 */
import type { LinkLengths, ReferencePose } from './reference';

export const EPS = Number.EPSILON;
/** Safety factor of the conditioning section ("about 10 eps * condition"). */
export const K = 10;
/** Floor used where the problem is well conditioned (|sin mu| >= 0.1, comparable links). */
export const BENIGN_TOL = 1e-12;

/** Conditioning bound (rad) for theta3 and theta4 at the reference pose, without any floor. */
export function conditioningBound(l: LinkLengths, pose: ReferencePose): { theta3: number; theta4: number } {
  const lMax = Math.max(l.r1, l.r2, l.r3, l.r4);
  const ea = 2 * EPS * lMax;
  const g = ea / Math.min(l.r3, l.r4);
  const damp = Math.sqrt(pose.sinMu * pose.sinMu + g);
  const direction = (K * ea) / pose.s;
  return {
    theta3: (K * ea) / (l.r3 * damp) + direction,
    theta4: (K * ea) / (l.r4 * damp) + direction,
  };
}

/** Test tolerance (rad): the conditioning bound, but never tighter than the benign 1e-12. */
export function angleTolerance(l: LinkLengths, pose: ReferencePose): { theta3: number; theta4: number } {
  const b = conditioningBound(l, pose);
  return { theta3: Math.max(BENIGN_TOL, b.theta3), theta4: Math.max(BENIGN_TOL, b.theta4) };
}

/**
 * Tolerance (rad) for an input-range limit acos(c): c carries a rounding error of about
 * dc = eps (r1^2 + r2^2 + (r3 + r4)^2) / (2 r1 r2), which moves acos by dc / sqrt(1 - c^2),
 * saturating at sqrt(2 dc) when c is near +-1 (a limit near 0 or 180 deg is ill-conditioned).
 */
export function limitTolerance(l: LinkLengths, c: number): number {
  const m = Math.max(l.r1, l.r2, l.r3, l.r4); // normalise so the squares cannot overflow
  const [a, b, c3, c4] = [l.r1 / m, l.r2 / m, l.r3 / m, l.r4 / m];
  const dc = (EPS * (a * a + b * b + (c3 + c4) ** 2)) / (2 * a * b);
  return Math.max(BENIGN_TOL, (K * dc) / Math.sqrt(Math.max(0, 1 - c * c) + K * dc));
}

/** Unit roundoff of binary64, 2^-53. */
export const U = 2 ** -53;

/**
 * The error bound of issue 7 for every full-precision method (rad): 1e-12 + 50 u (L / min(r3, r4)) / |sin mu|,
 * with L the longest link and mu the transmission angle at the reference pose. The closed form meets it on
 * over a million adversarial points; the NR continuation methods must meet it wherever the closed form does.
 */
export function errorBound(l: LinkLengths, pose: ReferencePose): number {
  const lMax = Math.max(l.r1, l.r2, l.r3, l.r4);
  return 1e-12 + (50 * U * (lMax / Math.min(l.r3, l.r4))) / Math.abs(pose.sinMu);
}

/**
 * How far (length unit) the loop's slack may be from zero and still get either reachability verdict:
 * 4 ulps of the longest link, plus what the solver's own rounding of m = s^2 - (r1 - r2)^2 (8 eps |m|,
 * doubled) and theta2's rounding radius h (s^2 moves by 2 r1 r2 (|sin t2| + h) h within it) do to
 * s^2, turned into a slack by dividing by s + |r3 - r4| (the smaller cofactor of the two factors).
 * m is 2 r1 r2 (1 - cos t2) near t2 = 0, -2 r1 r2 cos t2 in the middle, -2 r1 r2 (1 + cos t2) near pi.
 * Beyond this the verdict must follow the exact geometry; within it, either verdict is right.
 */
export function slackTolerance(l: LinkLengths, theta2: number, s: number): number {
  const lMax = Math.max(l.r1, l.r2, l.r3, l.r4);
  const c = Math.cos(theta2);
  const k2 = 2 * l.r1 * l.r2;
  const m = k2 * (c > 0.5 ? 1 - c : c < -0.5 ? 1 + c : Math.abs(c));
  const h = Math.abs(theta2) * EPS * 0.5 + Number.MIN_VALUE; // >= half an ulp of theta2
  const s2Error = 16 * EPS * m + k2 * (Math.abs(Math.sin(theta2)) + h) * h;
  return 4 * U * lMax + s2Error / Math.max(s + Math.abs(l.r3 - l.r4), Number.MIN_VALUE);
}
