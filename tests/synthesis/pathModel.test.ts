/**
 * The path stage's model (src/synthesis/pathModel.ts) and the problem built on it (pathProblem.ts), against the
 * 50-digit oracle of couplerOracle.ts. Tolerances: P is a few roundings of quantities of the links' size, so
 * 1e-13 of the size; a derivative's analytic formula divides by r3 sin μ, so it is held to 1e-10 relative with
 * the cases kept at |sin μ| > 0.1 (the conditioning is then at most ~10 times the benign case).
 */
import { describe, expect, it } from 'vitest';
import { MODEL_SIZE, couplerLocal } from '../../src/synthesis/pathModel';
import { createPathProblem, projectCappedSimplex, turnsFully } from '../../src/synthesis/pathProblem';
import { normaliseTask } from '../../src/synthesis/pathTask';
import { createRandom } from '../../src/synthesis/random';
import { oracleLocalDerivatives, oracleLocalPoint } from './couplerOracle';

const NAMES = ['r1', 'r2', 'r3', 'r4', 'u', 'v', 'theta2'];

/** Random well-conditioned cases: both branches, crank-rockers and others, |sin μ| > 0.1. */
function cases(count: number) {
  const rand = createRandom(17);
  const out: Array<{
    l: { r1: number; r2: number; r3: number; r4: number; u: number; v: number };
    t: number;
    s: 1 | -1;
  }> = [];
  const m = new Float64Array(MODEL_SIZE);
  while (out.length < count) {
    const l = {
      r1: 0.5 + 4 * rand(),
      r2: 0.3 + 3 * rand(),
      r3: 0.5 + 4 * rand(),
      r4: 0.5 + 4 * rand(),
      u: -2 + 4 * rand(),
      v: -2 + 4 * rand(),
    };
    const t = -4 + 8 * rand();
    const s: 1 | -1 = rand() < 0.5 ? 1 : -1;
    if (!couplerLocal(l.r1, l.r2, l.r3, l.r4, l.u, l.v, t, s, m)) continue;
    // sin μ from the derivative ∂P/∂r4 = w / (r3 sin μ) would be circular; recompute from the oracle's B instead:
    const d = oracleLocalDerivatives(l, t, s);
    const big = Math.max(...d.flat().map(Math.abs));
    if (big > 50 * (1 + Math.hypot(l.u, l.v))) continue; // near a limit: ill-conditioned, not this test's subject
    out.push({ l, t, s });
  }
  return out;
}

describe('couplerLocal', () => {
  const list = cases(40);

  it('gives the coupler point of the 50-digit oracle to 1e-13 of the size', () => {
    const m = new Float64Array(MODEL_SIZE);
    for (const { l, t, s } of list) {
      expect(couplerLocal(l.r1, l.r2, l.r3, l.r4, l.u, l.v, t, s, m)).toBe(true);
      const ref = oracleLocalPoint(l, t, s)!;
      const size = l.r1 + l.r2 + l.r3 + l.r4 + Math.hypot(l.u, l.v);
      expect(Math.abs(m[0] - ref[0])).toBeLessThan(1e-13 * size);
      expect(Math.abs(m[1] - ref[1])).toBeLessThan(1e-13 * size);
    }
  });

  it('has analytic derivatives equal to 50-digit central differences (1e-10 relative)', () => {
    const m = new Float64Array(MODEL_SIZE);
    for (const { l, t, s } of list) {
      couplerLocal(l.r1, l.r2, l.r3, l.r4, l.u, l.v, t, s, m);
      const ref = oracleLocalDerivatives(l, t, s);
      const scale = 1 + Math.max(...ref.flat().map(Math.abs));
      ref.forEach(([dx, dy], j) => {
        const ctx = `∂P/∂${NAMES[j]} at ${JSON.stringify({ ...l, t, s })}`;
        expect(Math.abs(m[2 + 2 * j] - dx), ctx).toBeLessThan(1e-10 * scale);
        expect(Math.abs(m[3 + 2 * j] - dy), ctx).toBeLessThan(1e-10 * scale);
      });
    }
  });

  it('reports a pose that cannot close', () => {
    const m = new Float64Array(MODEL_SIZE);
    // Triple rocker 4-3-3.5-3 cannot reach θ2 = π (|A O4| = 7 > r3 + r4 = 6.5).
    expect(couplerLocal(4, 3, 3.5, 3, 1, 0, 3.14159, 1, m)).toBe(false);
  });
});

describe('createPathProblem', () => {
  it('assembles a Jacobian equal to central differences of its residuals (free timing, both directions)', () => {
    const task = normaliseTask({
      targets: [
        { x: 0, y: 0 },
        { x: 1, y: 0.4 },
        { x: 2, y: 1.1 },
        { x: 2.5, y: 2 },
      ],
      timing: { kind: 'free' },
      input: 'any',
    });
    for (const dir of [1, -1]) {
      for (const sigma of [1, -1]) {
        const p = createPathProblem(task, sigma, dir);
        const x = Float64Array.from([0.1, -0.2, 0.3, 2.1, 0.7, 1.9, 1.6, 0.5, 0.4, 0.2, 0.3, 0.5, 0.4]);
        const { m, k } = p.lsq;
        expect(m).toBe(x.length);
        const r = new Float64Array(k);
        const J = new Float64Array(k * m);
        expect(p.lsq.evaluate(x, r, J)).toBe(true);
        const rp = new Float64Array(k);
        const rm = new Float64Array(k);
        const h = 1e-6;
        for (let j = 0; j < m; j++) {
          const xp = Float64Array.from(x);
          const xm = Float64Array.from(x);
          xp[j] += h;
          xm[j] -= h;
          p.lsq.evaluate(xp, rp, null);
          p.lsq.evaluate(xm, rm, null);
          for (let i = 0; i < k; i++) {
            // Central differences in doubles: truncation ~h² and rounding ~1e-16/h, so 1e-7 absolute suffices.
            expect(Math.abs((rp[i] - rm[i]) / (2 * h) - J[i * m + j]), `J[${i}][${j}] dir ${dir}`).toBeLessThan(1e-7);
          }
        }
      }
    }
  });
});

describe('projectCappedSimplex', () => {
  it('leaves a point inside alone and projects one outside onto Σδ = cap', () => {
    const x = Float64Array.from([9, 1, 2, 3]);
    projectCappedSimplex(x, 1, 3, 10);
    expect(Array.from(x)).toEqual([9, 1, 2, 3]);
    const y = Float64Array.from([4, 5, 6]);
    projectCappedSimplex(y, 0, 3, 6);
    expect(y[0] + y[1] + y[2]).toBeCloseTo(6, 14);
    expect(Array.from(y).map((v) => +v.toFixed(12))).toEqual([1, 2, 3]);
  });
});

describe('turnsFully', () => {
  it('is true for crank-rockers and drag links, false for rockers and change points', () => {
    expect(turnsFully(6, 2, 5, 5)).toBe(true);
    expect(turnsFully(1, 2, 2.3, 1.5)).toBe(true); // r1 shortest: a drag link, the input turns fully
    expect(turnsFully(4, 3, 3.5, 3)).toBe(false); // triple rocker
    expect(turnsFully(4, 2, 4, 2)).toBe(false); // change point (parallelogram)
  });
});
