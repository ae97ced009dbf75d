/** The bounded, projected Levenberg–Marquardt method on small problems with known answers. */
import { describe, expect, it } from 'vitest';
import { levenbergMarquardt } from '../../src/synthesis/levenbergMarquardt';
import type { LeastSquaresProblem } from '../../src/synthesis/levenbergMarquardt';

/** Rosenbrock as residuals (10 (y − x²), 1 − x), optionally boxed. */
function rosenbrock(lo: number[], hi: number[]): LeastSquaresProblem {
  return {
    m: 2,
    k: 2,
    lo: Float64Array.from(lo),
    hi: Float64Array.from(hi),
    evaluate(x, r, J) {
      r[0] = 10 * (x[1] - x[0] * x[0]);
      r[1] = 1 - x[0];
      if (J) {
        J[0] = -20 * x[0];
        J[1] = 10;
        J[2] = -1;
        J[3] = 0;
      }
      return true;
    },
  };
}

describe('levenbergMarquardt', () => {
  it('solves a zero-residual problem to rounding', () => {
    const r = levenbergMarquardt(
      rosenbrock([-Infinity, -Infinity], [Infinity, Infinity]),
      Float64Array.from([-1.2, 1]),
    );
    expect(r.f).toBeLessThan(1e-28);
    expect(Math.abs(r.x[0] - 1)).toBeLessThan(1e-14);
  });

  it('stops exactly on an active bound, with the other variable optimal on that face', () => {
    // x ≤ 0.5: the minimum on the face is x = 0.5, y = 0.25 (r0 = 0), f = 0.25.
    const r = levenbergMarquardt(rosenbrock([-Infinity, -Infinity], [0.5, Infinity]), Float64Array.from([-1.2, 1]));
    expect(r.x[0]).toBe(0.5);
    // The solve stops once f stalls at its rounding (relative 1e-12), which leaves y within ~1e-7 of the face optimum.
    expect(Math.abs(r.x[1] - 0.25)).toBeLessThan(1e-6);
    expect(Math.abs(r.f - 0.25)).toBeLessThan(1e-15);
  });

  it('rejects infeasible points and reports an unevaluable start', () => {
    const p = {
      ...rosenbrock([-Infinity, -Infinity], [Infinity, Infinity]),
      feasible: (x: Float64Array) => x[1] <= 0.64,
    };
    const r = levenbergMarquardt(p, Float64Array.from([0, 0]));
    expect(r.x[1]).toBeLessThanOrEqual(0.64);
    const bad = { ...p, evaluate: () => false };
    expect(levenbergMarquardt(bad, Float64Array.from([0, 0])).f).toBe(Infinity);
  });
});
