import { TWO_PI } from '../../solver';

import { NV, evaluate } from './equations';

/** Standard complex normal-ish numbers (Box–Muller) from a uniform generator, into v. */
export function randomComplex(rand: () => number, v: Float64Array): void {
  for (let i = 0; i < v.length; i += 2) {
    const r = Math.sqrt(-2 * Math.log(1 - rand()));
    const t = TWO_PI * rand();
    v[i] = r * Math.cos(t) * Math.SQRT1_2;
    v[i + 1] = r * Math.sin(t) * Math.SQRT1_2;
  }
}

/**
 * A generic parameter point with one known root: random z and δ_j, then δ̂_j by Newton on the quartic E_j(δ̂_j) = 0
 * from random starts. Returns null when Newton keeps failing (it does not for generic draws).
 */
export function seedRoot(rand: () => number): { z: Float64Array; p: Float64Array } | null {
  const z = new Float64Array(2 * NV);
  const p = new Float64Array(4 * NV);
  randomComplex(rand, z);
  randomComplex(rand, p);
  const F = new Float64Array(2 * NV);
  const Fp = new Float64Array(2 * NV);
  const dp = new Float64Array(4 * NV);
  for (let j = 0; j < 8; j++) {
    dp.fill(0);
    dp[16 + 2 * j] = 1;
    let done = false;
    for (let attempt = 0; attempt < 50 && !done; attempt++) {
      p[16 + 2 * j] = 2 * rand() - 1;
      p[17 + 2 * j] = 2 * rand() - 1;
      for (let it = 0; it < 60; it++) {
        evaluate(z, p, F, undefined, dp, Fp);
        const fr = F[2 * j],
          fi = F[2 * j + 1],
          gr = Fp[2 * j],
          gi = Fp[2 * j + 1];
        const m = gr * gr + gi * gi;
        if (!(m > 0)) break;
        const sr = (fr * gr + fi * gi) / m;
        const si = (fi * gr - fr * gi) / m;
        p[16 + 2 * j] -= sr;
        p[17 + 2 * j] -= si;
        if (Math.hypot(sr, si) < 1e-15 * (1 + Math.hypot(p[16 + 2 * j], p[17 + 2 * j]))) {
          done = true;
          break;
        }
      }
    }
    if (!done) return null;
  }
  return { z, p };
}
