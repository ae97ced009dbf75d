import { describe, expect, it } from 'vitest';
import { evaluate } from '../../src/synthesis/ninePoint/equations';
import { luFactor, luSolve, norm } from '../../src/synthesis/ninePoint/linear';
import { randomComplex, seedRoot } from '../../src/synthesis/ninePoint/startRoot';
import { Tracker } from '../../src/synthesis/ninePoint/tracker';
import { createRandom } from '../../src/synthesis/random';

function residual(z: Float64Array, p: Float64Array): number {
  const F = new Float64Array(16);
  evaluate(z, p, F);
  return norm(F);
}

describe('Tracker', () => {
  const rand = createRandom(7);
  const seeds = Array.from({ length: 6 }, () => seedRoot(rand)!);

  it('starts from a root: seedRoot solves E(z; p) = 0 for its random point', () => {
    for (const s of seeds) expect(residual(s.z, s.p)).toBeLessThan(1e-12 * (1 + norm(s.z)) ** 7);
  });

  it('ends each path at a root of the target parameters', () => {
    const t = new Tracker();
    for (const s of seeds) {
      const p1 = new Float64Array(32);
      randomComplex(rand, p1);
      t.setSegment(s.p, p1, 0.6, 0.8);
      const z = s.z.slice();
      const r = t.track(z);
      expect(r.status).toBe('finished');
      // degree-7 equations in |z|: the residual scales like |z|^7 ε
      expect(residual(z, p1)).toBeLessThan(1e-11 * (1 + norm(z)) ** 7);
    }
  });

  it('comes back to the root it left along the same straight path (γ = 1)', () => {
    const t = new Tracker();
    for (const s of seeds) {
      const p1 = new Float64Array(32);
      randomComplex(rand, p1);
      const z = s.z.slice();
      t.setSegment(s.p, p1, 1, 0);
      expect(t.track(z).status).toBe('finished');
      t.setSegment(p1, s.p, 1, 0);
      expect(t.track(z).status).toBe('finished');
      let d = 0;
      for (let i = 0; i < 16; i++) d = Math.max(d, Math.abs(z[i] - s.z[i]));
      expect(d).toBeLessThan(1e-8 * (1 + norm(s.z)));
    }
  });

  it('reports a path that heads to infinity instead of finishing it', () => {
    // All nine points on one line (δ̂ = δ real): the roots go to infinity there.
    const line = new Float64Array(32);
    for (let j = 0; j < 8; j++) {
      line[2 * j] = (j + 1) / 8;
      line[16 + 2 * j] = (j + 1) / 8;
    }
    const t = new Tracker();
    let finite = 0;
    for (const q of seeds) {
      t.setSegment(q.p, line, 0.6, 0.8);
      const z = q.z.slice();
      const r = t.track(z, { maxSteps: 3000 });
      if (r.status === 'finished') finite++;
      else expect(['diverged', 'failed']).toContain(r.status);
    }
    expect(finite).toBe(0);
  });
});

describe('luFactor and luSolve', () => {
  it('solve M w = b for many right-hand sides with one factoring (checked by multiplying back)', () => {
    const rand = createRandom(11);
    const n = 8;
    for (let trial = 0; trial < 20; trial++) {
      const M = Float64Array.from({ length: 2 * n * n }, () => 2 * rand() - 1);
      // A zero leading entry forces a row swap on the first column.
      M[0] = 0;
      M[1] = 0;
      const LU = M.slice();
      const piv = new Int32Array(n);
      expect(luFactor(LU, piv, n)).toBe(true);
      for (let k = 0; k < 3; k++) {
        const b = Float64Array.from({ length: 2 * n }, () => 2 * rand() - 1);
        const w = b.slice();
        luSolve(LU, piv, w, n);
        // Oracle: M w computed directly from the untouched M.
        let worst = 0;
        for (let i = 0; i < n; i++) {
          let re = 0;
          let im = 0;
          for (let j = 0; j < n; j++) {
            const mr = M[2 * (i * n + j)];
            const mi = M[2 * (i * n + j) + 1];
            re += mr * w[2 * j] - mi * w[2 * j + 1];
            im += mr * w[2 * j + 1] + mi * w[2 * j];
          }
          worst = Math.max(worst, Math.hypot(re - b[2 * i], im - b[2 * i + 1]));
        }
        // Random 8×8 matrices are well conditioned to a few hundred: the residual is rounding.
        expect(worst).toBeLessThan(1e-10 * (1 + norm(w)));
      }
    }
  });

  it('refuses a singular matrix', () => {
    const M = new Float64Array(2 * 4 * 4);
    M[0] = 1;
    expect(luFactor(M, new Int32Array(4), 4)).toBe(false);
  });
});
