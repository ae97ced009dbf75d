import { describe, expect, it } from 'vitest';
import type { SynFunctionState } from '../../../../src/shared/state/slices/synFunctionSlice';
import { DEFAULT_SYN_FUNCTION } from '../../../../src/shared/state/slices/synFunctionSlice';
import { generatedAt, solveFunction } from '../../../../src/features/synthesis/function/functionSolve';
import { functionGenerator } from '../../../../src/synthesis';

const fn = (patch: Partial<SynFunctionState>): SynFunctionState => ({ ...DEFAULT_SYN_FUNCTION, ...patch });

/** Chebyshev points on [1, 10] written out here, not taken from the module under test. */
const CHEBYSHEV_3 = [1, 3, 5].map((k) => 5.5 - 4.5 * Math.cos((k * Math.PI) / 6));

describe('solveFunction', () => {
  it('makes log10 on [1, 10] exact at the Chebyshev points, with a small error between (docs/synthesis.md)', () => {
    const r = solveFunction(DEFAULT_SYN_FUNCTION, Math.log10);
    if (!r.ok) throw new Error(JSON.stringify(r.problem));
    const { precision, result } = r.value;
    precision.forEach((p, i) => {
      expect(p.x).toBeCloseTo(CHEBYSHEV_3[i], 12);
      // Three exact pairs solved to rounding: the error there is rounding of y's range (1) times a few ulps of θ4.
      expect(Math.abs(p.error)).toBeLessThan(1e-12);
    });
    expect(result.maxError).toBeGreaterThan(0.005);
    expect(result.maxError).toBeLessThan(0.008);
    expect(result.defects).toEqual([]);
  });

  it('reads the generated y back at any x: f(x) at a precision point, within the largest error elsewhere', () => {
    const s = DEFAULT_SYN_FUNCTION;
    const r = solveFunction(s, Math.log10);
    if (!r.ok) throw new Error('no design');
    const at = generatedAt(s, r.value, Math.log10, CHEBYSHEV_3[1]);
    expect(at.got).toBeCloseTo(Math.log10(CHEBYSHEV_3[1]), 12);
    expect(at.theta2).toBeCloseTo(((30 + ((CHEBYSHEV_3[1] - 1) / 9) * 60) * Math.PI) / 180, 14);
    const mid = generatedAt(s, r.value, Math.log10, 7.7);
    expect(Math.abs(mid.got - mid.want)).toBeLessThanOrEqual(r.value.result.maxError * 1.05);
  });

  it('fits more points by least squares: no longer exact, but a smaller largest error', () => {
    const three = solveFunction(DEFAULT_SYN_FUNCTION, Math.log10);
    const five = solveFunction(fn({ precisionPoints: 5 }), Math.log10);
    if (!three.ok || !five.ok) throw new Error('no design');
    expect(five.value.result.maxError).toBeLessThan(three.value.result.maxError);
    expect(Math.max(...five.value.precision.map((p) => Math.abs(p.error)))).toBeGreaterThan(1e-6);
  });

  it('says where f has no finite value, and when f(x0) = f(x1)', () => {
    expect(solveFunction(fn({ xRange: [-1, 10] }), Math.log10)).toEqual({
      ok: false,
      problem: { code: 'notFinite', x: expect.any(Number) },
    });
    const bad = solveFunction(fn({ xRange: [-1, 10] }), Math.log10);
    if (bad.ok || bad.problem.code !== 'notFinite') throw new Error('expected notFinite');
    expect(Math.log10(bad.problem.x)).toBeNaN();
    expect(solveFunction(fn({ xRange: [-1, 1] }), (x) => x * x)).toEqual({
      ok: false,
      problem: { code: 'sameEnds', y: 1 },
    });
  });

  it('says when no real linkage fits the pairs', () => {
    const r = solveFunction(fn({ theta2RangeDeg: [0, 10], theta4RangeDeg: [0, 170] }), Math.log10);
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.problem.code).toBe('noLinkage');
  });

  it('passes on the defects functionGenerator finds (here a precision point on the other branch)', () => {
    const s = fn({ xRange: [0, 3], theta2RangeDeg: [40, 140], theta4RangeDeg: [60, 120] });
    const f = (x: number) => Math.sin(x) + x / 10;
    const r = solveFunction(s, f);
    if (!r.ok) throw new Error(JSON.stringify(r.problem));
    const direct = functionGenerator({
      f,
      x: [0, 3],
      theta2: [(40 * Math.PI) / 180, (140 * Math.PI) / 180],
      theta4: [(60 * Math.PI) / 180, (120 * Math.PI) / 180],
      points: 3,
      samples: 201,
    });
    expect(r.value.result.defects).toEqual(direct.defects);
    expect(r.value.result.defects).toContain('branch');
  });
});
