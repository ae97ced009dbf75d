/**
 * The path stage's model: the coupler point of a four-bar in its own frame (O2 at the origin, O4 at (r1, 0)) and
 * its exact first derivatives with respect to r1..r4, the coupler point's coordinates (u, v) in the coupler frame
 * (u along AB, v to its left) and the input angle θ2. docs/synthesis.md "Path generation" derives them:
 * θ3 follows from the loop closure by implicit differentiation, so every derivative is a closed form in the pose.
 */

/** Layout of couplerLocal's output: P, then ∂P/∂r1, ∂P/∂r2, ∂P/∂r3, ∂P/∂r4, ∂P/∂u, ∂P/∂v, ∂P/∂θ2 (x then y). */
export const MODEL_SIZE = 16;

/**
 * The coupler point P = A + u e3 + v e3⊥ of the four-bar (r1..r4, length unit) at θ2 (radians, from the ground
 * line) on branch sigma (+1 open, -1 crossed), with its 14 partial derivatives, written into out (MODEL_SIZE
 * numbers, layout as MODEL_SIZE says). Returns false where the loop cannot close (out is then untouched beyond
 * what was written). At a limit position (sin μ = 0) the derivatives are infinite: the caller sees non-finite values.
 */
export function couplerLocal(
  r1: number,
  r2: number,
  r3: number,
  r4: number,
  u: number,
  v: number,
  theta2: number,
  sigma: number,
  out: Float64Array,
): boolean {
  const c = Math.cos(theta2);
  const s = Math.sin(theta2);
  const ax = r2 * c;
  const ay = r2 * s;
  const dx = r1 - ax;
  const dy = -ay;
  const s2 = dx * dx + dy * dy;
  // 16 area² of the triangle A B O4 as a product of two factors: each is a sum or difference of squares,
  // formed as products of sums so that the sign near a limit is not lost to cancellation.
  const sum = r3 + r4;
  const diff = r3 - r4;
  const plus = sum * sum - s2;
  const minus = s2 - diff * diff;
  if (!(plus >= 0 && minus >= 0) || s2 === 0) return false;
  const sLen = Math.sqrt(s2);
  const twoR3s = 2 * r3 * sLen;
  const cosPsi = (r3 * r3 - r4 * r4 + s2) / twoR3s;
  const sinPsi = (sigma * Math.sqrt(plus) * Math.sqrt(minus)) / twoR3s;
  // e3: the unit vector A→O4 turned by ψ (left for the open branch, as in the solver).
  const e3x = (dx * cosPsi - dy * sinPsi) / sLen;
  const e3y = (dy * cosPsi + dx * sinPsi) / sLen;
  const bx = ax + r3 * e3x;
  const by = ay + r3 * e3y;
  const e4x = (bx - r1) / r4;
  const e4y = by / r4;
  const sinMu = e3x * e4y - e3y * e4x; // sin(θ4 − θ3)
  const cosMu = e3x * e4x + e3y * e4y;
  const inv = 1 / (r3 * sinMu);
  // dθ3 = −(e4·dA + dr3 cos μ − dr1 cos θ4 − dr4) / (r3 sin μ), dA = dr2 (c, s) + r2 (−s, c) dθ2.
  const t1 = e4x * inv;
  const t2 = -(e4x * c + e4y * s) * inv;
  const t3 = -cosMu * inv;
  const t4 = inv;
  const tt = -r2 * (c * e4y - s * e4x) * inv;
  // w = ∂P/∂θ3 = u e3⊥ − v e3.
  const wx = -u * e3y - v * e3x;
  const wy = u * e3x - v * e3y;
  out[0] = ax + u * e3x - v * e3y;
  out[1] = ay + u * e3y + v * e3x;
  out[2] = wx * t1;
  out[3] = wy * t1;
  out[4] = c + wx * t2;
  out[5] = s + wy * t2;
  out[6] = wx * t3;
  out[7] = wy * t3;
  out[8] = wx * t4;
  out[9] = wy * t4;
  out[10] = e3x;
  out[11] = e3y;
  out[12] = -e3y;
  out[13] = e3x;
  out[14] = -ay + wx * tt;
  out[15] = ax + wy * tt;
  return true;
}
