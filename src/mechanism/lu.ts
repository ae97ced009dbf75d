/**
 * A small dense LU with partial pivoting, in place on a row-major n×n Float64Array: P A = L U with L unit lower
 * (below the diagonal) and U upper (on and above it); perm[i] is the row of A that became row i. No allocation.
 */

/**
 * Factors a in place; returns det(A) (0 when a pivot is exactly zero; the factors are then unusable).
 * minPivot[0] receives min |U_ii| / max |U_ii|, a cheap measure of how close A is to singular.
 */
export function luFactor(a: Float64Array, n: number, perm: Int32Array, minPivot: Float64Array): number {
  let det = 1;
  let lo = Infinity;
  let hi = 0;
  for (let i = 0; i < n; i++) perm[i] = i;
  for (let k = 0; k < n; k++) {
    let p = k;
    let best = Math.abs(a[k * n + k]);
    for (let i = k + 1; i < n; i++) {
      const v = Math.abs(a[i * n + k]);
      if (v > best) {
        best = v;
        p = i;
      }
    }
    if (best === 0) {
      minPivot[0] = 0;
      return 0;
    }
    if (p !== k) {
      const rk = k * n;
      const rp = p * n;
      for (let c = 0; c < n; c++) {
        const t = a[rk + c];
        a[rk + c] = a[rp + c];
        a[rp + c] = t;
      }
      const t = perm[k];
      perm[k] = perm[p];
      perm[p] = t;
      det = -det;
    }
    const rk = k * n;
    const pivot = a[rk + k];
    det *= pivot;
    if (best < lo) lo = best;
    if (best > hi) hi = best;
    for (let i = k + 1; i < n; i++) {
      const ri = i * n;
      const f = a[ri + k];
      if (f === 0) continue;
      const m = f / pivot;
      a[ri + k] = m;
      for (let c = k + 1; c < n; c++) a[ri + c] -= m * a[rk + c];
    }
  }
  minPivot[0] = lo / hi;
  return det;
}

/** Solves A x = b with the factors of luFactor; b is overwritten by x (tmp: n scratch entries). */
export function luSolve(a: Float64Array, n: number, perm: Int32Array, b: Float64Array, tmp: Float64Array): void {
  for (let i = 0; i < n; i++) tmp[i] = b[perm[i]];
  for (let i = 0; i < n; i++) {
    const ri = i * n;
    let s = tmp[i];
    for (let c = 0; c < i; c++) s -= a[ri + c] * tmp[c];
    tmp[i] = s;
  }
  for (let i = n - 1; i >= 0; i--) {
    const ri = i * n;
    let s = tmp[i];
    for (let c = i + 1; c < n; c++) s -= a[ri + c] * tmp[c];
    tmp[i] = s / a[ri + i];
  }
  for (let i = 0; i < n; i++) b[i] = tmp[i];
}

/** Solves Aᵀ x = b with the factors of luFactor (A = Pᵀ L U, so Aᵀ = Uᵀ Lᵀ P); b is overwritten by x. */
export function luSolveTransposed(
  a: Float64Array,
  n: number,
  perm: Int32Array,
  b: Float64Array,
  tmp: Float64Array,
): void {
  for (let i = 0; i < n; i++) {
    let s = b[i];
    for (let c = 0; c < i; c++) s -= a[c * n + i] * tmp[c];
    tmp[i] = s / a[i * n + i];
  }
  for (let i = n - 1; i >= 0; i--) {
    let s = tmp[i];
    for (let c = i + 1; c < n; c++) s -= a[c * n + i] * tmp[c];
    tmp[i] = s;
  }
  for (let i = 0; i < n; i++) b[perm[i]] = tmp[i];
}
