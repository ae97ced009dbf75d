import { describe, expect, it } from 'vitest';
import { evaluate } from '../../src/synthesis/ninePoint/equations';
import { norm } from '../../src/synthesis/ninePoint/linear';
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
