/**
 * Small dense linear algebra for the closed-form syntheses: a least-squares solve by Householder QR (backward
 * stable, so an exactly determined system is solved to rounding) and a square solve by Gaussian elimination
 * with partial pivoting (the Newton polish of the Burmester points). Matrices are arrays of rows.
 */

/** Least-squares solution of A x ≈ b, or null when the columns are dependent to rounding. */
export interface LeastSquares {
  x: number[];
  /** ‖A x − b‖₂, in the units of b. */
  residual: number;
}

/**
 * x minimising ‖A x − b‖₂ for an m×n A with m ≥ n (rows of numbers), by Householder QR with the columns scaled
 * to unit norm first (the solution is invariant, the rank test is not fooled by units); null when a column is
 * dependent on the others to within 1e3 ε of its norm. The residual is recomputed from A, x and b.
 */
export function leastSquares(A: readonly (readonly number[])[], b: readonly number[]): LeastSquares | null {
  const m = A.length;
  const n = A[0].length;
  const scale = new Array<number>(n).fill(0);
  for (let j = 0; j < n; j++) {
    let s = 0;
    for (let i = 0; i < m; i++) s = Math.hypot(s, A[i][j]);
    if (!(s > 0) || !Number.isFinite(s)) return null;
    scale[j] = s;
  }
  const R = A.map((row) => row.map((v, j) => v / scale[j]));
  const y = b.slice();
  for (let k = 0; k < n; k++) {
    let norm = 0;
    for (let i = k; i < m; i++) norm = Math.hypot(norm, R[i][k]);
    // A column that was unit before the first k reflections and has almost nothing left below row k is dependent.
    if (norm <= 1e3 * Number.EPSILON) return null;
    // Reflect onto −sign(R_kk) e_k so that v_k = R_kk + sign(R_kk) norm has no cancellation.
    const alpha = R[k][k] >= 0 ? -norm : norm;
    const v = new Array<number>(m - k);
    for (let i = k; i < m; i++) v[i - k] = R[i][k];
    v[0] -= alpha;
    let vv = 0;
    for (const t of v) vv += t * t;
    for (let j = k; j < n; j++) {
      let d = 0;
      for (let i = k; i < m; i++) d += v[i - k] * R[i][j];
      const f = (2 * d) / vv;
      for (let i = k; i < m; i++) R[i][j] -= f * v[i - k];
    }
    let d = 0;
    for (let i = k; i < m; i++) d += v[i - k] * y[i];
    const f = (2 * d) / vv;
    for (let i = k; i < m; i++) y[i] -= f * v[i - k];
  }
  const z = new Array<number>(n).fill(0);
  for (let k = n - 1; k >= 0; k--) {
    let s = y[k];
    for (let j = k + 1; j < n; j++) s -= R[k][j] * z[j];
    z[k] = s / R[k][k];
  }
  const x = z.map((v, j) => v / scale[j]);
  let residual = 0;
  for (let i = 0; i < m; i++) {
    let r = -b[i];
    for (let j = 0; j < n; j++) r += A[i][j] * x[j];
    residual = Math.hypot(residual, r);
  }
  return { x, residual };
}

/** Solution of the square system A x = b by Gaussian elimination with partial pivoting; null when a pivot is 0. */
export function solveSquare(A: readonly (readonly number[])[], b: readonly number[]): number[] | null {
  const n = A.length;
  const M = A.map((row, i) => [...row, b[i]]);
  for (let k = 0; k < n; k++) {
    let p = k;
    for (let i = k + 1; i < n; i++) if (Math.abs(M[i][k]) > Math.abs(M[p][k])) p = i;
    if (!(Math.abs(M[p][k]) > 0)) return null;
    [M[k], M[p]] = [M[p], M[k]];
    for (let i = k + 1; i < n; i++) {
      const f = M[i][k] / M[k][k];
      for (let j = k; j <= n; j++) M[i][j] -= f * M[k][j];
    }
  }
  const x = new Array<number>(n).fill(0);
  for (let k = n - 1; k >= 0; k--) {
    let s = M[k][n];
    for (let j = k + 1; j < n; j++) s -= M[k][j] * x[j];
    x[k] = s / M[k][k];
  }
  return x.every(Number.isFinite) ? x : null;
}
