import { describe, expect, it } from 'vitest';
import { angleDomain, plotIndices, wrappedSegments } from '../../src/charts/angleChart';

describe('wrappedSegments', () => {
  it('turns NaN samples into gaps', () => {
    const pts = wrappedSegments([0, 1, 2], [10, Number.NaN, 12]);
    expect(pts.map((p) => Number.isNaN(p[1]))).toEqual([false, true, false]);
  });

  it('runs to the +-180 edge and breaks where the angle wraps, so no stroke crosses the plot', () => {
    const pts = wrappedSegments([0, 2], [179, -179]);
    expect(pts).toHaveLength(5);
    expect(pts[1]).toEqual([1, 180]);
    expect(Number.isNaN(pts[2][1])).toBe(true);
    expect(pts[3]).toEqual([1, -180]);
    expect(pts[4]).toEqual([2, -179]);
  });

  it('wraps the other way too', () => {
    const pts = wrappedSegments([0, 4], [-178, 178]);
    expect(pts[1][1]).toBe(-180);
    expect(pts[3][1]).toBe(180);
    expect(pts[1][0]).toBeCloseTo(2, 12);
  });
});

describe('angleDomain', () => {
  it('pads the data to 30 degree steps within [-180, 180]', () => {
    expect(angleDomain([{ label: '', color: '', valuesDeg: [31, 79] }])).toEqual([0, 90]);
    expect(angleDomain([{ label: '', color: '', valuesDeg: [-179, 179] }])).toEqual([-180, 180]);
  });
  it('shows the full range when there is no data', () => {
    expect(angleDomain([{ label: '', color: '', valuesDeg: [Number.NaN] }])).toEqual([-180, 180]);
  });
});

describe('plotIndices', () => {
  it('keeps every sample when they fit', () => {
    expect(plotIndices([1, 2, 3], 10)).toEqual([0, 1, 2]);
  });
  it('thins long series but keeps run ends, gap starts, wraps and the last sample', () => {
    const y = Array.from({ length: 101 }, (_, i) =>
      i >= 40 && i <= 52 ? Number.NaN : i === 70 ? 179 : i === 71 ? -179 : i,
    );
    const idx = plotIndices(y, 10);
    expect(idx.length).toBeLessThan(30);
    for (const must of [0, 39, 40, 53, 70, 71, 100]) expect(idx).toContain(must);
  });
});
