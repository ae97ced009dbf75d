import { describe, expect, it } from 'vitest';
import { formatPowerOfTen, residualDomain } from '../../src/charts/convergenceChart';

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
