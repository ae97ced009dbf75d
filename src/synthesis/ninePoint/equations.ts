/**
 * The nine-point path-synthesis equations of Wampler, Morgan and Sommese (1992) in isotropic coordinates, with the
 * coupler rotations eliminated: 8 equations of degree 7 in 8 complex unknowns. See docs/synthesis.md.
 *
 * Unknowns z (8 complex numbers, re/im interleaved in a Float64Array of 16): x, a, y, b, x̂, â, ŷ, b̂, where a and b
 * are the ground pivots and x and y the vectors from the coupler point to the moving pivots in the first position,
 * all relative to the first precision point; x̂ … b̂ stand for their conjugates but are independent unknowns.
 * Parameters p (16 complex numbers, Float64Array of 32): δ_1 … δ_8 then δ̂_1 … δ̂_8, δ_j = P_j − P_0.
 * With the coupler rotation θ_j = 1 + γ_j, each dyad gives γ p + γ̂ q + r = 0 (linear in γ, γ̂); Cramer's rule on the
 * two dyads and θ_j θ̂_j = 1 (γγ̂ + γ + γ̂ = 0) times the determinant squared give E_j = N1 N2 + D (N1 + N2).
 */

/** Number of complex unknowns and equations. */
export const NV = 8;
/** Index of each unknown (complex) in z. */
export const X = 0;
export const A = 1;
export const Y = 2;
export const B = 3;
export const XH = 4;
export const AH = 5;
export const YH = 6;
export const BH = 7;

// Products without allocation: the result of the last cm() lands in T (a typed array, so no number is boxed, as a
// module-level `let` would be on every write).
const T = new Float64Array(2);
function cm(ar: number, ai: number, br: number, bi: number): void {
  T[0] = ar * br - ai * bi;
  T[1] = ar * bi + ai * br;
}

/** Scratch for one equation's intermediates: p1 q1 r1 p2 q2 r2 N1 N2 D and the partials Ep1 … Er2 (complex each). */
const S = new Float64Array(2 * 16);
const P1 = 0,
  Q1 = 2,
  R1 = 4,
  P2 = 6,
  Q2 = 8,
  R2 = 10,
  EP1 = 12,
  EQ1 = 14,
  ER1 = 16,
  EP2 = 18,
  EQ2 = 20,
  ER2 = 22;

/**
 * Evaluates the 8 equations at z for parameters p into F (16 floats); when J is given, the 8×8 Jacobian ∂F/∂z
 * (row-major, 128 floats); when dp and Fp are given, the directional derivative ∂F/∂p · dp into Fp (16 floats).
 */
export function evaluate(
  z: Float64Array,
  p: Float64Array,
  F: Float64Array,
  J?: Float64Array,
  dp?: Float64Array,
  Fp?: Float64Array,
): void {
  const xr = z[0],
    xi = z[1],
    ar = z[2],
    ai = z[3],
    yr = z[4],
    yi = z[5],
    br = z[6],
    bi = z[7];
  const Xr = z[8],
    Xi = z[9],
    Ar = z[10],
    Ai = z[11],
    Yr = z[12],
    Yi = z[13],
    Br = z[14],
    Bi = z[15];
  for (let j = 0; j < 8; j++) {
    const dr = p[2 * j],
      di = p[2 * j + 1],
      Dr = p[16 + 2 * j],
      Di = p[17 + 2 * j];
    cm(dr, di, Dr, Di);
    const ddr = T[0],
      ddi = T[1];
    // p1 = x (â − δ̂), q1 = x̂ (a − δ), r1 = (â − x̂) δ + (a − x) δ̂ − δ δ̂; likewise for the second dyad.
    cm(xr, xi, Ar - Dr, Ai - Di);
    S[P1] = T[0];
    S[P1 + 1] = T[1];
    cm(Xr, Xi, ar - dr, ai - di);
    S[Q1] = T[0];
    S[Q1 + 1] = T[1];
    cm(Ar - Xr, Ai - Xi, dr, di);
    let tr = T[0] - ddr,
      ti = T[1] - ddi;
    cm(ar - xr, ai - xi, Dr, Di);
    S[R1] = tr + T[0];
    S[R1 + 1] = ti + T[1];
    cm(yr, yi, Br - Dr, Bi - Di);
    S[P2] = T[0];
    S[P2 + 1] = T[1];
    cm(Yr, Yi, br - dr, bi - di);
    S[Q2] = T[0];
    S[Q2 + 1] = T[1];
    cm(Br - Yr, Bi - Yi, dr, di);
    tr = T[0] - ddr;
    ti = T[1] - ddi;
    cm(br - yr, bi - yi, Dr, Di);
    S[R2] = tr + T[0];
    S[R2 + 1] = ti + T[1];
    const p1r = S[P1],
      p1i = S[P1 + 1],
      q1r = S[Q1],
      q1i = S[Q1 + 1],
      r1r = S[R1],
      r1i = S[R1 + 1];
    const p2r = S[P2],
      p2i = S[P2 + 1],
      q2r = S[Q2],
      q2i = S[Q2 + 1],
      r2r = S[R2],
      r2i = S[R2 + 1];
    // N1 = q1 r2 − r1 q2 (γ·D), N2 = r1 p2 − p1 r2 (γ̂·D), D = p1 q2 − q1 p2.
    cm(q1r, q1i, r2r, r2i);
    tr = T[0];
    ti = T[1];
    cm(r1r, r1i, q2r, q2i);
    const n1r = tr - T[0],
      n1i = ti - T[1];
    cm(r1r, r1i, p2r, p2i);
    tr = T[0];
    ti = T[1];
    cm(p1r, p1i, r2r, r2i);
    const n2r = tr - T[0],
      n2i = ti - T[1];
    cm(p1r, p1i, q2r, q2i);
    tr = T[0];
    ti = T[1];
    cm(q1r, q1i, p2r, p2i);
    const Dtr = tr - T[0],
      Dti = ti - T[1];
    cm(n1r, n1i, n2r, n2i);
    tr = T[0];
    ti = T[1];
    cm(Dtr, Dti, n1r + n2r, n1i + n2i);
    F[2 * j] = tr + T[0];
    F[2 * j + 1] = ti + T[1];
    if (!J && !Fp) continue;
    // ∂E/∂N1 = N2 + D, ∂E/∂N2 = N1 + D, ∂E/∂D = N1 + N2; then the chain rule to p1 … r2.
    const e1r = n2r + Dtr,
      e1i = n2i + Dti,
      e2r = n1r + Dtr,
      e2i = n1i + Dti,
      eDr = n1r + n2r,
      eDi = n1i + n2i;
    cm(eDr, eDi, q2r, q2i);
    tr = T[0];
    ti = T[1];
    cm(e2r, e2i, r2r, r2i);
    S[EP1] = tr - T[0];
    S[EP1 + 1] = ti - T[1];
    cm(e1r, e1i, r2r, r2i);
    tr = T[0];
    ti = T[1];
    cm(eDr, eDi, p2r, p2i);
    S[EQ1] = tr - T[0];
    S[EQ1 + 1] = ti - T[1];
    cm(e2r, e2i, p2r, p2i);
    tr = T[0];
    ti = T[1];
    cm(e1r, e1i, q2r, q2i);
    S[ER1] = tr - T[0];
    S[ER1 + 1] = ti - T[1];
    cm(e2r, e2i, r1r, r1i);
    tr = T[0];
    ti = T[1];
    cm(eDr, eDi, q1r, q1i);
    S[EP2] = tr - T[0];
    S[EP2 + 1] = ti - T[1];
    cm(eDr, eDi, p1r, p1i);
    tr = T[0];
    ti = T[1];
    cm(e1r, e1i, r1r, r1i);
    S[EQ2] = tr - T[0];
    S[EQ2 + 1] = ti - T[1];
    cm(e1r, e1i, q1r, q1i);
    tr = T[0];
    ti = T[1];
    cm(e2r, e2i, p1r, p1i);
    S[ER2] = tr - T[0];
    S[ER2 + 1] = ti - T[1];
    if (J) {
      const row = 16 * j;
      // ∂x = Ep1 (â − δ̂) − Er1 δ̂ ; ∂â = Ep1 x + Er1 δ ; ∂x̂ = Eq1 (a − δ) − Er1 δ ; ∂a = Eq1 x̂ + Er1 δ̂
      sum2(J, row + 2 * X, EP1, Ar - Dr, Ai - Di, ER1, -Dr, -Di);
      sum2(J, row + 2 * AH, EP1, xr, xi, ER1, dr, di);
      sum2(J, row + 2 * XH, EQ1, ar - dr, ai - di, ER1, -dr, -di);
      sum2(J, row + 2 * A, EQ1, Xr, Xi, ER1, Dr, Di);
      sum2(J, row + 2 * Y, EP2, Br - Dr, Bi - Di, ER2, -Dr, -Di);
      sum2(J, row + 2 * BH, EP2, yr, yi, ER2, dr, di);
      sum2(J, row + 2 * YH, EQ2, br - dr, bi - di, ER2, -dr, -di);
      sum2(J, row + 2 * B, EQ2, Yr, Yi, ER2, Dr, Di);
    }
    if (dp && Fp) {
      // ∂δ = −Eq1 x̂ + Er1 (â − x̂ − δ̂) − Eq2 ŷ + Er2 (b̂ − ŷ − δ̂); ∂δ̂ = −Ep1 x + Er1 (a − x − δ) − Ep2 y + Er2 (b − y − δ)
      let gr = 0,
        gi = 0,
        hr = 0,
        hi = 0;
      cm(S[EQ1], S[EQ1 + 1], -Xr, -Xi);
      gr += T[0];
      gi += T[1];
      cm(S[ER1], S[ER1 + 1], Ar - Xr - Dr, Ai - Xi - Di);
      gr += T[0];
      gi += T[1];
      cm(S[EQ2], S[EQ2 + 1], -Yr, -Yi);
      gr += T[0];
      gi += T[1];
      cm(S[ER2], S[ER2 + 1], Br - Yr - Dr, Bi - Yi - Di);
      gr += T[0];
      gi += T[1];
      cm(S[EP1], S[EP1 + 1], -xr, -xi);
      hr += T[0];
      hi += T[1];
      cm(S[ER1], S[ER1 + 1], ar - xr - dr, ai - xi - di);
      hr += T[0];
      hi += T[1];
      cm(S[EP2], S[EP2 + 1], -yr, -yi);
      hr += T[0];
      hi += T[1];
      cm(S[ER2], S[ER2 + 1], br - yr - dr, bi - yi - di);
      hr += T[0];
      hi += T[1];
      cm(gr, gi, dp[2 * j], dp[2 * j + 1]);
      tr = T[0];
      ti = T[1];
      cm(hr, hi, dp[16 + 2 * j], dp[17 + 2 * j]);
      Fp[2 * j] = tr + T[0];
      Fp[2 * j + 1] = ti + T[1];
    }
  }
}

/** J[at] = S[i]·(ur + i ui) + S[k]·(vr + i vi). */
function sum2(J: Float64Array, at: number, i: number, ur: number, ui: number, k: number, vr: number, vi: number) {
  cm(S[i], S[i + 1], ur, ui);
  const tr = T[0],
    ti = T[1];
  cm(S[k], S[k + 1], vr, vi);
  J[at] = tr + T[0];
  J[at + 1] = ti + T[1];
}

/** The coupler rotation θ_j = 1 + γ_j (complex, into out[0..1]) at root z for parameters p; NaN where D = 0. */
export function rotation(z: Float64Array, p: Float64Array, j: number, out: Float64Array): void {
  const c = (k: number) => [z[2 * k], z[2 * k + 1]] as const;
  const [xr, xi] = c(X),
    [ar, ai] = c(A),
    [yr, yi] = c(Y),
    [br, bi] = c(B);
  const [Xr, Xi] = c(XH),
    [Ar, Ai] = c(AH),
    [Yr, Yi] = c(YH),
    [Br, Bi] = c(BH);
  const dr = p[2 * j],
    di = p[2 * j + 1],
    Dr = p[16 + 2 * j],
    Di = p[17 + 2 * j];
  const mul = (u: readonly number[], v: readonly number[]) => [u[0] * v[0] - u[1] * v[1], u[0] * v[1] + u[1] * v[0]];
  const sub = (u: readonly number[], v: readonly number[]) => [u[0] - v[0], u[1] - v[1]];
  const add = (u: readonly number[], v: readonly number[]) => [u[0] + v[0], u[1] + v[1]];
  const d = [dr, di],
    D = [Dr, Di];
  const p1 = mul([xr, xi], [Ar - Dr, Ai - Di]);
  const q1 = mul([Xr, Xi], [ar - dr, ai - di]);
  const r1 = sub(add(mul([Ar - Xr, Ai - Xi], d), mul([ar - xr, ai - xi], D)), mul(d, D));
  const p2 = mul([yr, yi], [Br - Dr, Bi - Di]);
  const q2 = mul([Yr, Yi], [br - dr, bi - di]);
  const r2 = sub(add(mul([Br - Yr, Bi - Yi], d), mul([br - yr, bi - yi], D)), mul(d, D));
  const n1 = sub(mul(q1, r2), mul(r1, q2));
  const det = sub(mul(p1, q2), mul(q1, p2));
  const m = det[0] * det[0] + det[1] * det[1];
  // γ = N1 / D
  out[0] = 1 + (n1[0] * det[0] + n1[1] * det[1]) / m;
  out[1] = (n1[1] * det[0] - n1[0] * det[1]) / m;
}

/** Relative size below which a link or coordinate counts as zero in isDegenerate. */
export const DEGENERATE_TOL = 1e-8;

/**
 * Whether z is a degenerate root: a pivot on the coupler point, two pivots coincident (in either half), or a pose
 * whose rotation is undefined (D = 0). Elimination by Cramer's rule adds such roots to the system (E = 0 wherever
 * N1 N2 = D = 0); they are no linkage and lie off the component of the 8652 genuine roots.
 */
export function isDegenerate(z: Float64Array, p: Float64Array): boolean {
  let size = 0;
  for (let i = 0; i < z.length; i++) size = Math.max(size, Math.abs(z[i]));
  const tol = DEGENERATE_TOL * (1 + size);
  const d = (i: number, k: number) => Math.hypot(z[2 * i] - z[2 * k], z[2 * i + 1] - z[2 * k + 1]);
  const m = (i: number) => Math.hypot(z[2 * i], z[2 * i + 1]);
  for (const o of [0, 4]) {
    if (m(X + o) <= tol || m(Y + o) <= tol) return true;
    if (d(X + o, A + o) <= tol || d(Y + o, B + o) <= tol || d(X + o, Y + o) <= tol || d(A + o, B + o) <= tol)
      return true;
  }
  const out = new Float64Array(2);
  for (let j = 0; j < 8; j++) {
    rotation(z, p, j, out);
    if (!(Math.hypot(out[0], out[1]) < 1 / tol)) return true;
  }
  return false;
}
