import { describe, expect, it } from 'vitest';
import {
  decadeLabels,
  detJDomain,
  iterationTicks,
  maxIterations,
  spacedTicks,
  toAxisDeg,
  unassembledRuns,
} from '../../../src/features/lab/cycleChart';

describe('toAxisDeg', () => {
  it('maps limits in (-180, 180] onto the 0..360 axis', () => {
    expect(toAxisDeg(135.95)).toBe(135.95);
    expect(toAxisDeg(-135.95)).toBeCloseTo(224.05, 12);
    expect(toAxisDeg(-90)).toBe(270);
    expect(toAxisDeg(180)).toBe(180);
    expect(toAxisDeg(0)).toBe(0);
  });
  it('keeps angles already on the axis, 360 included, and wraps the rest', () => {
    expect(toAxisDeg(360)).toBe(360);
    expect(toAxisDeg(400)).toBeCloseTo(40, 12);
  });
});

describe('detJDomain', () => {
  it('spans whole decades around the positive values, ignoring NaN and zeros', () => {
    expect(detJDomain(new Float64Array([2.4e-4, 5.6, NaN, 0]))).toEqual([1e-4, 10]);
  });
  it('is at least two decades wide for a nearly constant |det J|', () => {
    const [lo, hi] = detJDomain(new Float64Array([18.3, 25.1]));
    expect(hi).toBe(100);
    expect(lo).toBe(1);
  });
  it('handles an exact power of ten and falls back without data', () => {
    const [lo, hi] = detJDomain(new Float64Array([10]));
    expect(hi / lo).toBeGreaterThanOrEqual(100);
    expect(hi).toBeGreaterThanOrEqual(10);
    expect(detJDomain(new Float64Array([NaN, NaN]))).toEqual([1e-3, 10]);
  });
});

describe('iterationTicks', () => {
  it('counts every integer on a small axis', () => {
    expect(iterationTicks(3)).toEqual([0, 1, 2, 3]);
    expect(iterationTicks(0)).toEqual([0, 1]);
  });
  it('steps so the last tick covers the maximum', () => {
    expect(iterationTicks(13)).toEqual([0, 5, 10, 15]);
    expect(iterationTicks(7)).toEqual([0, 2, 4, 6, 8]);
  });
  it('uses 1-2-5 steps up to the maximum on a symlog axis', () => {
    expect(iterationTicks(100)).toEqual([0, 1, 2, 5, 10, 20, 50, 100]);
    expect(iterationTicks(37)).toEqual([0, 1, 2, 5, 10, 20, 37]);
  });
  it('only ever gives integers', () => {
    for (const m of [1, 4, 9, 19, 23, 250]) expect(iterationTicks(m).every((t) => Number.isInteger(t))).toBe(true);
  });
});

describe('spacedTicks', () => {
  it('drops ticks closer than the gap, keeping the top one', () => {
    const px = (v: number) => 100 - Math.log1p(v) * 20;
    const kept = spacedTicks([0, 1, 2, 5, 10, 20, 50, 100], px, 13);
    expect(kept[kept.length - 1]).toBe(100);
    for (let i = 1; i < kept.length; i++) expect(Math.abs(px(kept[i]) - px(kept[i - 1]))).toBeGreaterThanOrEqual(13);
  });
});

describe('unassembledRuns', () => {
  it('finds the stretches where |det J| is NaN', () => {
    const x = [0, 10, 20, 30, 40, 50];
    expect(unassembledRuns(x, [1, NaN, NaN, 1, 1, NaN])).toEqual([
      [10, 20],
      [50, 50],
    ]);
    expect(unassembledRuns(x, [1, 1, 1, 1, 1, 1])).toEqual([]);
  });
});

describe('maxIterations', () => {
  it('is the largest count over all methods', () => {
    expect(
      maxIterations([
        { method: 'newton', label: '', iterations: Int32Array.from([0, 2, 1]) },
        { method: 'seed', label: '', iterations: Int32Array.from([5, 100]) },
      ]),
    ).toBe(100);
    expect(maxIterations([])).toBe(0);
  });
});

describe('decadeLabels', () => {
  it('labels one axis in one style', () => {
    expect(decadeLabels([1, 10, 100])).toEqual(['1', '10', '100']);
    expect(decadeLabels([0.01, 0.1, 1])).toEqual(['0.01', '0.1', '1']);
    expect(decadeLabels([1e-3, 1e-1, 10])).toEqual(['1e\u22123', '1e\u22121', '1e1']);
  });
});
