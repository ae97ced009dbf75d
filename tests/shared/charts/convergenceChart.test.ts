import { describe, expect, it } from 'vitest';
import {
  CONVERGENCE_SIZE,
  convergenceFrame,
  formatPowerOfTen,
  residualDomain,
} from '../../../src/shared/charts/convergenceChart';
import { chartSize, plotArea } from '../../../src/shared/charts/chart';

describe('residualDomain', () => {
  it('spans whole decades with room for exact zeros below the smallest residual', () => {
    const run = { label: '', color: '', iterations: [0, 1, 2, 3], residuals: [0.5, 2e-4, 3e-10, 0] };
    expect(residualDomain([run])).toEqual([1e-11, 1]);
  });
  it('includes the tolerance line', () => {
    const run = { label: '', color: '', iterations: [0], residuals: [1e-3] };
    const [lo] = residualDomain([run], 1e-12);
    expect(lo).toBeCloseTo(1e-13, 25);
  });
  it('falls back to a fixed range without data', () => {
    expect(residualDomain([])).toEqual([1e-16, 1]);
  });
});

describe('formatPowerOfTen', () => {
  it('labels powers of ten only', () => {
    expect(formatPowerOfTen(1e-3)).toBe('1e\u22123');
    expect(formatPowerOfTen(1)).toBe('1e0');
    expect(formatPowerOfTen(3e-3)).toBe('');
  });
});

describe('convergenceFrame', () => {
  const size = (width: number, height: number) => plotArea(chartSize({ ...CONVERGENCE_SIZE, width, height }));
  const runs = [
    {
      label: '',
      color: '',
      iterations: [0, 1, 2, 3, 4, 5, 6, 7],
      residuals: [1, 0.1, 1e-3, 1e-6, 1e-9, 1e-12, 1e-15, 0],
    },
  ];
  it('labels whole iterations only, spaced for the width', () => {
    for (const width of [200, 320, 560, 900]) {
      const f = convergenceFrame({ runs }, size(width, 300));
      expect(f.xTicks.every((t) => Number.isInteger(t) && t >= 0 && t <= 7)).toBe(true);
      const px = f.xTicks.map((t) => f.x(t));
      for (let i = 1; i < px.length; i++) expect(px[i] - px[i - 1]).toBeGreaterThanOrEqual(20);
    }
  });
  it('labels powers of ten on the residual axis, the floor decade included', () => {
    const f = convergenceFrame({ runs, tolerance: 1e-12 }, size(560, 300));
    expect(f.y.domain()).toEqual([1e-16, 1]);
    expect(f.yTicks.every((t) => formatPowerOfTen(t) !== '')).toBe(true);
    // The floor decade is a tick, so its ≤ label shows where exact zeros are drawn.
    expect(f.yFloor).toBe(1e-16);
    expect(f.yTicks[0]).toBe(1e-16);
    const py = f.yTicks.map((t) => f.y(t));
    for (let i = 1; i < py.length; i++) expect(py[i - 1] - py[i]).toBeGreaterThanOrEqual(14);
  });
  it("keeps the floor at the domain's foot whether or not a run reaches exactly zero (no flip between layouts)", () => {
    const last = (r: number) => [{ ...runs[0], residuals: [...runs[0].residuals.slice(0, -1), r] }];
    const zero = convergenceFrame({ runs: last(0) }, size(560, 300));
    const tiny = convergenceFrame({ runs: last(1e-17) }, size(560, 300));
    expect(zero.yFloor).toBe(zero.y.domain()[0]);
    expect(tiny.yFloor).toBe(tiny.y.domain()[0]);
  });
});
