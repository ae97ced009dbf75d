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

/**
 * Scratch of one pose j, complex entries (re, im) in a Float64Array: each dyad's (p, q, r) (u₁ = U1, u₂ = U2),
 * c = u₁ × u₂ = (N1, N2, D), e = ∂E/∂c and g_k = ∂E/∂u_k (G1, G2). Module-level: evaluate is not reentrant.
 */
const W = new Float64Array(36);
const U1 = 0,
  U2 = 6,
  C = 12,
  EC = 18,
  G1 = 24,
  G2 = 30;

/** W[o] = W[s]·W[t] − W[u]·W[v] (complex entries at those offsets). */
function det2(s: number, t: number, u: number, v: number, o: number): void {
  const sr = W[s],
    si = W[s + 1],
    tr = W[t],
    ti = W[t + 1],
    ur = W[u],
    ui = W[u + 1],
    vr = W[v],
    vi = W[v + 1];
  W[o] = sr * tr - si * ti - (ur * vr - ui * vi);
  W[o + 1] = sr * ti + si * tr - (ur * vi + ui * vr);
}

/** The complex cross product W[o..o+6) = W[a..a+6) × W[b..b+6) (three complex entries each). */
function cross(a: number, b: number, o: number): void {
  det2(a + 2, b + 4, a + 4, b + 2, o);
  det2(a + 4, b, a, b + 4, o + 2);
  det2(a, b + 2, a + 2, b, o + 4);
}

/**
 * One dyad's coefficients at pose j into W[o..o+6): p = x (â − δ̂), q = x̂ (a − δ), r = (â − x̂) δ + (a − x) δ̂ − δ δ̂,
 * with x, a the dyad's moving and ground unknowns (indices m, g) and x̂, â at m + 4, g + 4.
 */
function dyad(z: Float64Array, m: number, g: number, dr: number, di: number, Dr: number, Di: number, o: number): void {
  const xr = z[2 * m],
    xi = z[2 * m + 1],
    ar = z[2 * g],
    ai = z[2 * g + 1],
    Xr = z[2 * m + 8],
    Xi = z[2 * m + 9],
    Ar = z[2 * g + 8],
    Ai = z[2 * g + 9];
  const ur = Ar - Dr,
    ui = Ai - Di,
    vr = ar - dr,
    vi = ai - di,
    sr = Ar - Xr,
    si = Ai - Xi,
    tr = ar - xr,
    ti = ai - xi;
  W[o] = xr * ur - xi * ui;
  W[o + 1] = xr * ui + xi * ur;
  W[o + 2] = Xr * vr - Xi * vi;
  W[o + 3] = Xr * vi + Xi * vr;
  W[o + 4] = sr * dr - si * di + tr * Dr - ti * Di - (dr * Dr - di * Di);
  W[o + 5] = sr * di + si * dr + tr * Di + ti * Dr - (dr * Di + di * Dr);
}

/** u₁, u₂ and c = (N1, N2, D) of pose j (0-based, for the point P_{j+1}) into W. */
function pose(z: Float64Array, p: Float64Array, j: number): void {
  const dr = p[2 * j],
    di = p[2 * j + 1],
    Dr = p[16 + 2 * j],
    Di = p[17 + 2 * j];
  dyad(z, X, A, dr, di, Dr, Di, U1);
  dyad(z, Y, B, dr, di, Dr, Di, U2);
  cross(U1, U2, C);
}

/**
 * One dyad's share of row j: with (Ep, Eq, Er) = W[G..G+6), ∂x = Ep (â − δ̂) − Er δ̂, ∂â = Ep x + Er δ,
 * ∂x̂ = Eq (a − δ) − Er δ, ∂a = Eq x̂ + Er δ̂ into J; returns nothing. Then, when Fp is wanted, its share of ∂E/∂δ
 * (−Eq x̂ + Er (â − x̂ − δ̂)) and ∂E/∂δ̂ (−Ep x + Er (a − x − δ)) is added to PD[0..4).
 */
function dyadPartials(
  z: Float64Array,
  m: number,
  g: number,
  G: number,
  dr: number,
  di: number,
  Dr: number,
  Di: number,
  J: Float64Array | undefined,
  row: number,
  withP: boolean,
): void {
  const xr = z[2 * m],
    xi = z[2 * m + 1],
    ar = z[2 * g],
    ai = z[2 * g + 1],
    Xr = z[2 * m + 8],
    Xi = z[2 * m + 9],
    Ar = z[2 * g + 8],
    Ai = z[2 * g + 9];
  const pr = W[G],
    pi = W[G + 1],
    qr = W[G + 2],
    qi = W[G + 3],
    rr = W[G + 4],
    ri = W[G + 5];
  if (J) {
    const ur = Ar - Dr,
      ui = Ai - Di,
      vr = ar - dr,
      vi = ai - di;
    J[row + 2 * m] = pr * ur - pi * ui - (rr * Dr - ri * Di);
    J[row + 2 * m + 1] = pr * ui + pi * ur - (rr * Di + ri * Dr);
    J[row + 2 * g + 8] = pr * xr - pi * xi + (rr * dr - ri * di);
    J[row + 2 * g + 9] = pr * xi + pi * xr + (rr * di + ri * dr);
    J[row + 2 * m + 8] = qr * vr - qi * vi - (rr * dr - ri * di);
    J[row + 2 * m + 9] = qr * vi + qi * vr - (rr * di + ri * dr);
    J[row + 2 * g] = qr * Xr - qi * Xi + (rr * Dr - ri * Di);
    J[row + 2 * g + 1] = qr * Xi + qi * Xr + (rr * Di + ri * Dr);
  }
  if (withP) {
    const sr = Ar - Xr - Dr,
      si = Ai - Xi - Di,
      tr = ar - xr - dr,
      ti = ai - xi - di;
    PD[0] += rr * sr - ri * si - (qr * Xr - qi * Xi);
    PD[1] += rr * si + ri * sr - (qr * Xi + qi * Xr);
    PD[2] += rr * tr - ri * ti - (pr * xr - pi * xi);
    PD[3] += rr * ti + ri * tr - (pr * xi + pi * xr);
  }
}
/** ∂E_j/∂δ_j and ∂E_j/∂δ̂_j (complex each), summed over the two dyads by dyadPartials. */
const PD = new Float64Array(4);

/**
 * Evaluates the 8 equations at z for parameters p into F (16 floats); when J is given, the 8×8 Jacobian ∂F/∂z
 * (row-major, 128 floats); when dp and Fp are given, the directional derivative ∂F/∂p · dp into Fp (16 floats).
 * E_j = N1 N2 + D (N1 + N2) with c = (N1, N2, D) = u₁ × u₂, so ∂E/∂u₁ = u₂ × e and ∂E/∂u₂ = e × u₁, e = ∂E/∂c.
 */
export function evaluate(
  z: Float64Array,
  p: Float64Array,
  F: Float64Array,
  J?: Float64Array,
  dp?: Float64Array,
  Fp?: Float64Array,
): void {
  const withP = !!(dp && Fp);
  for (let j = 0; j < 8; j++) {
    pose(z, p, j);
    const n1r = W[C],
      n1i = W[C + 1],
      n2r = W[C + 2],
      n2i = W[C + 3],
      dtr = W[C + 4],
      dti = W[C + 5];
    F[2 * j] = n1r * n2r - n1i * n2i + dtr * (n1r + n2r) - dti * (n1i + n2i);
    F[2 * j + 1] = n1r * n2i + n1i * n2r + dtr * (n1i + n2i) + dti * (n1r + n2r);
    if (!J && !withP) continue;
    // e = ∂E/∂(N1, N2, D) = (N2 + D, N1 + D, N1 + N2)
    W[EC] = n2r + dtr;
    W[EC + 1] = n2i + dti;
    W[EC + 2] = n1r + dtr;
    W[EC + 3] = n1i + dti;
    W[EC + 4] = n1r + n2r;
    W[EC + 5] = n1i + n2i;
    cross(U2, EC, G1);
    cross(EC, U1, G2);
    const dr = p[2 * j],
      di = p[2 * j + 1],
      Dr = p[16 + 2 * j],
      Di = p[17 + 2 * j];
    PD.fill(0);
    dyadPartials(z, X, A, G1, dr, di, Dr, Di, J, 16 * j, withP);
    dyadPartials(z, Y, B, G2, dr, di, Dr, Di, J, 16 * j, withP);
    if (withP) {
      const ar = dp![2 * j],
        ai = dp![2 * j + 1],
        br = dp![16 + 2 * j],
        bi = dp![17 + 2 * j];
      Fp![2 * j] = PD[0] * ar - PD[1] * ai + PD[2] * br - PD[3] * bi;
      Fp![2 * j + 1] = PD[0] * ai + PD[1] * ar + PD[2] * bi + PD[3] * br;
    }
  }
}

/** The coupler rotation θ_j = 1 + γ_j (complex, into out[0..1]) at root z for parameters p; NaN where D = 0. */
export function rotation(z: Float64Array, p: Float64Array, j: number, out: Float64Array): void {
  pose(z, p, j);
  // γ = N1 / D
  const nr = W[C],
    ni = W[C + 1],
    dr = W[C + 4],
    di = W[C + 5];
  const m = dr * dr + di * di;
  out[0] = 1 + (nr * dr + ni * di) / m;
  out[1] = (ni * dr - nr * di) / m;
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
