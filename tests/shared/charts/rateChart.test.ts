import { describe, expect, it } from 'vitest';
import { clipMarks, rateDomain } from '../../../src/shared/charts/rateChart';

const series = (values: number[]) => [{ label: 'ω3', color: '#000', values }];

describe('rateDomain', () => {
  it('holds every value of a compact curve, padded and on round ticks', () => {
    const values = Array.from({ length: 361 }, (_, i) => 4 * Math.sin((i * Math.PI) / 180));
    const [lo, hi] = rateDomain(series(values), 6);
    expect(lo).toBeLessThanOrEqual(-4);
    expect(hi).toBeGreaterThanOrEqual(4);
    expect(hi - lo).toBeLessThanOrEqual(12);
    expect([lo, hi].every((v) => Number.isInteger(v))).toBe(true);
  });

  it('cuts a few runaway samples off (a limit position), keeping the bulk readable', () => {
    const values = Array.from({ length: 361 }, (_, i) => (i === 90 ? 1e6 : i === 91 ? -5e5 : Math.cos(i / 30)));
    const [lo, hi] = rateDomain(series(values), 6);
    expect(hi).toBeLessThan(10);
    expect(lo).toBeGreaterThan(-10);
  });

  it('gives [-1, 1] without finite data and a band around a constant curve', () => {
    expect(rateDomain(series([Number.NaN, Number.NaN]))).toEqual([-1, 1]);
    const [lo, hi] = rateDomain(series([3, 3, 3]));
    expect(lo).toBeLessThan(3);
    expect(hi).toBeGreaterThan(3);
  });
});

describe('rateDomain with a floor', () => {
  const near0 = Array.from({ length: 361 }, (_, i) => 1 + 100 * Math.abs(Math.sin((i * Math.PI) / 360)));

  it('starts at exactly the floor where the padding would reach below it, the top still padded and nice', () => {
    // Without a floor the 6 % padding takes the axis below 0 (the pin-force chart's complaint).
    expect(rateDomain(series(near0), 6)[0]).toBeLessThan(0);
    const [lo, hi] = rateDomain(series(near0), 6, 0);
    expect(lo).toBe(0);
    expect(hi).toBeGreaterThanOrEqual(101);
    expect(Number.isInteger(hi / 20)).toBe(true); // nice for about 6 ticks over [0, 107]: steps of 20
  });

  it('starts at the floor also when the data stay far above it', () => {
    const high = near0.map((v) => v + 1000);
    expect(rateDomain(series(high), 6)[0]).toBeGreaterThan(900);
    const [lo, hi] = rateDomain(series(high), 6, 0);
    expect(lo).toBe(0);
    expect(hi).toBeGreaterThanOrEqual(1101);
    expect(Number.isInteger(hi / 200)).toBe(true); // nice for about 6 ticks over [0, 1100]: steps of 200
  });

  it('holds a floor off the tick lattice, which nice alone would step down past', () => {
    expect(rateDomain(series([0.37, 5]), 6, 0.3)[0]).toBe(0.3);
  });

  it('gives [floor, floor + 1] without finite data and a top above a curve at the floor', () => {
    expect(rateDomain(series([Number.NaN]), 6, 0)).toEqual([0, 1]);
    const [lo, hi] = rateDomain(series([0, 0, 0]), 6, 0);
    expect(lo).toBe(0);
    expect(hi).toBeGreaterThan(0);
  });
});

describe('clipMarks', () => {
  it('marks a crossing at the interpolated θ2 and an outside run once, on its side', () => {
    const theta2 = [0, 10, 20, 30, 40, 50];
    const values = [0, 4, 12, 20, 6, Number.NaN];
    // Leaves [-10, 10] between 10° (4) and 20° (12): at 10 + 10 * (10 - 4) / (12 - 4) = 17.5°.
    expect(clipMarks(theta2, values, [-10, 10])).toEqual([{ theta2Deg: 17.5, side: 'above' }]);
  });

  it('marks a run that starts outside, after a gap or at the first sample', () => {
    expect(clipMarks([0, 1, 2, 3], [-50, -40, Number.NaN, -60], [-10, 10])).toEqual([
      { theta2Deg: 0, side: 'below' },
      { theta2Deg: 3, side: 'below' },
    ]);
  });
});
