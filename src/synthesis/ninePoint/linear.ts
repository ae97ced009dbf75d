/** Dense complex linear algebra on Float64Array (re, im interleaved), without allocation. */

/**
 * Factors an n×n complex M (row-major) in place into L U with partial pivoting, the row swaps in piv; false when a
 * pivot is exactly zero or not finite. luSolve then solves with it as many times as needed (a chord corrector).
 */
export function luFactor(M: Float64Array, piv: Int32Array, n: number): boolean {
  const w = 2 * n;
  for (let k = 0; k < n; k++) {
    const kk = k * w + 2 * k;
    let best = k;
    let bestAbs = -1;
    for (let i = k, at = kk; i < n; i++, at += w) {
      const m = M[at] * M[at] + M[at + 1] * M[at + 1];
      if (m > bestAbs) {
        bestAbs = m;
        best = i;
      }
    }
    if (!(bestAbs > 0) || !Number.isFinite(bestAbs)) return false;
    piv[k] = best;
    if (best !== k) {
      for (let c = k * w, d = best * w, end = c + w; c < end; c++, d++) {
        const t = M[c];
        M[c] = M[d];
        M[d] = t;
      }
    }
    const ir = M[kk] / bestAbs;
    const ii = -M[kk + 1] / bestAbs;
    for (let ik = kk + w; ik < n * w; ik += w) {
      const ar = M[ik];
      const ai = M[ik + 1];
      const fr = ar * ir - ai * ii;
      const fi = ar * ii + ai * ir;
      // The multiplier stays in L's place below the diagonal; row i minus f times row k right of it.
      M[ik] = fr;
      M[ik + 1] = fi;
      for (let c = 2, end = w - 2 * k; c < end; c += 2) {
        const br = M[kk + c];
        const bi = M[kk + c + 1];
        M[ik + c] -= fr * br - fi * bi;
        M[ik + c + 1] -= fr * bi + fi * br;
      }
    }
  }
  return true;
}

/** Solves L U w = rhs with luFactor's factors and swaps; w overwrites rhs. */
export function luSolve(M: Float64Array, piv: Int32Array, rhs: Float64Array, n: number): void {
  // The swaps first, in order (whole rows were swapped while factoring, as LAPACK's getrf/getrs do), then L and U.
  for (let k = 0; k < n; k++) {
    const b = piv[k];
    if (b !== k) {
      for (let c = 0; c < 2; c++) {
        const t = rhs[2 * k + c];
        rhs[2 * k + c] = rhs[2 * b + c];
        rhs[2 * b + c] = t;
      }
    }
  }
  for (let k = 0; k < n; k++) {
    const rr = rhs[2 * k];
    const ri = rhs[2 * k + 1];
    for (let i = k + 1; i < n; i++) {
      const fr = M[2 * (i * n + k)];
      const fi = M[2 * (i * n + k) + 1];
      rhs[2 * i] -= fr * rr - fi * ri;
      rhs[2 * i + 1] -= fr * ri + fi * rr;
    }
  }
  for (let k = n - 1; k >= 0; k--) {
    let sr = rhs[2 * k];
    let si = rhs[2 * k + 1];
    for (let c = k + 1; c < n; c++) {
      const mr = M[2 * (k * n + c)];
      const mi = M[2 * (k * n + c) + 1];
      sr -= mr * rhs[2 * c] - mi * rhs[2 * c + 1];
      si -= mr * rhs[2 * c + 1] + mi * rhs[2 * c];
    }
    const pr = M[2 * (k * n + k)];
    const pi = M[2 * (k * n + k) + 1];
    const m = pr * pr + pi * pi;
    rhs[2 * k] = (sr * pr + si * pi) / m;
    rhs[2 * k + 1] = (si * pr - sr * pi) / m;
  }
}

/** Euclidean norm of a complex vector stored as 2n floats. */
export function norm(v: Float64Array): number {
  let s = 0;
  for (let i = 0; i < v.length; i++) s += v[i] * v[i];
  return Math.sqrt(s);
}
