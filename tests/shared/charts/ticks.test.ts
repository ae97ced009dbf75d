import { describe, expect, it } from 'vitest';
import {
  angleTicks,
  decadeTicks,
  integerTicks,
  logTicks,
  angleAxis,
  fittedTicks,
  niceCountDomain,
  niceLogDomain,
  niceOneTwoFiveDomain,
  oneTwoFiveTicks,
  tickCount,
} from '../../../src/shared/charts/ticks';

/** Oracle: every multiple of step in [lo, hi], by enumeration from an integer index (no accumulated error). */
function multiples(lo: number, hi: number, step: number): number[] {
  const out: number[] = [];
  for (let k = Math.ceil(lo / step - 1e-9); k * step <= hi + 1e-9; k++) out.push(Number((k * step).toPrecision(12)));
  return out;
}

/** Oracle: the sorted 1-2-5 lattice over exponents e0..e1, written as decimal literals. */
function lattice125(e0: number, e1: number): number[] {
  const out: number[] = [];
  for (let e = e0; e <= e1; e++) for (const m of [1, 2, 5]) out.push(Number(`${m}e${e}`));
  return out;
}

const ANGLE_RANGES: Array<[number, number]> = [
  [0, 360],
  [-180, 180],
  [-90, 90],
  [15, 90],
  [20, 90],
  [-37, 12],
  [40, 41.5],
];

describe('tickCount', () => {
  it('gives one tick per spacing and never fewer than two', () => {
    expect(tickCount(600, 60)).toBe(10);
    expect(tickCount(599, 60)).toBe(9);
    expect(tickCount(50, 60)).toBe(2);
  });
});

describe('angleTicks', () => {
  it('lists every multiple of one step in the range, the step being 15, 30, 60, 150 or 300 degrees on a wide axis', () => {
    for (const [lo, hi] of ANGLE_RANGES) {
      for (const count of [2, 3, 5, 8, 12]) {
        const t = angleTicks(lo, hi, count);
        expect(t.length).toBeGreaterThan(0);
        const step = t.length > 1 ? t[1] - t[0] : Number.NaN;
        if (t.length > 1 && step >= 15) expect([15, 30, 60, 150, 300]).toContain(step);
        if (t.length > 1 && step < 15) {
          // Narrow axes step like d3: 1, 2 or 5 times a power of ten degrees.
          const m = step / 10 ** Math.floor(Math.log10(step) + 1e-9);
          expect([1, 2, 5].some((k) => Math.abs(m - k) < 1e-9)).toBe(true);
        }
        if (t.length > 1) expect(t).toEqual(multiples(lo, hi, step));
        // About count ticks: d3 may give up to about twice as many, never a crowd.
        expect(t.length).toBeLessThanOrEqual(2 * count + 1);
      }
    }
  });

  it('steps 60 degrees over the full turn at desktop counts and 150 at the narrowest', () => {
    expect(angleTicks(0, 360, 8)).toEqual([0, 60, 120, 180, 240, 300, 360]);
    expect(angleTicks(0, 360, 4)).toEqual([0, 60, 120, 180, 240, 300, 360]);
    expect(angleTicks(0, 360, 2)).toEqual([0, 150, 300]);
    expect(angleTicks(-180, 180, 8)).toEqual([-180, -120, -60, 0, 60, 120, 180]);
  });
});

describe('angleAxis', () => {
  it('contains the range, ends on ticks of its own step and stays within [-180, 180]', () => {
    const ranges = [...ANGLE_RANGES.slice(1), [-175, 170] as [number, number], [26, 84] as [number, number]];
    for (const [lo, hi] of ranges) {
      for (const count of [3, 5, 8]) {
        const { domain, ticks: t } = angleAxis(lo, hi, count);
        const [a, b] = domain;
        expect(a).toBeLessThanOrEqual(lo);
        expect(b).toBeGreaterThanOrEqual(hi);
        expect(a).toBeGreaterThanOrEqual(-180);
        expect(b).toBeLessThanOrEqual(180);
        // Ends on ticks unless clamped at +-180 (a 150 degree step would otherwise reach 300).
        expect(t).toEqual(multiples(t[0], t[t.length - 1], t[1] - t[0]));
        if (a > -180) expect(t[0]).toBe(a);
        if (b < 180) expect(t[t.length - 1]).toBe(b);
      }
    }
  });
});

describe('integerTicks', () => {
  it('gives evenly spaced integers covering the range with a 1-2-5 step', () => {
    for (const hi of [1, 3, 7, 13, 40, 99]) {
      for (const count of [2, 4, 10]) {
        const t = integerTicks(0, hi, count);
        const step = t.length > 1 ? t[1] - t[0] : 1;
        expect([1, 2, 5, 10, 20, 50]).toContain(step);
        expect(t).toEqual(multiples(0, hi, step));
      }
    }
    expect(integerTicks(0, 3, 10)).toEqual([0, 1, 2, 3]);
  });
  it('gives the single value of an empty range', () => {
    expect(integerTicks(2, 2, 5)).toEqual([2]);
  });
});

describe('niceCountDomain', () => {
  it('ends at or above the maximum, on a tick', () => {
    for (const max of [0, 1, 3, 7, 13, 19]) {
      for (const count of [3, 4, 6]) {
        const [, top] = niceCountDomain(max, count);
        expect(top).toBeGreaterThanOrEqual(Math.max(1, max));
        expect(integerTicks(0, top, count).at(-1)).toBe(top);
      }
    }
  });
});

describe('decadeTicks', () => {
  it('gives exact powers of ten, every one when they fit', () => {
    expect(decadeTicks(1e-4, 10, 10)).toEqual([0.0001, 0.001, 0.01, 0.1, 1, 10]);
  });
  it('thins to a whole step of decades on a lattice that does not move with the domain', () => {
    const t = decadeTicks(1e-18, 1, 10);
    expect(t.map((v) => Math.round(Math.log10(v)))).toEqual([-18, -16, -14, -12, -10, -8, -6, -4, -2, 0]);
    const shifted = decadeTicks(1e-17, 1e-1, 10);
    expect(shifted.map((v) => Math.round(Math.log10(v)))).toEqual([-16, -14, -12, -10, -8, -6, -4, -2]);
  });
  it('anchors the lattice at another exponent so that decade can be labelled', () => {
    const t = decadeTicks(1e-18, 1, 9, -17).map((v) => Math.round(Math.log10(v)));
    expect(t).toContain(-17);
    expect(t.every((e) => (e + 17) % 2 === 0)).toBe(true);
  });
});

describe('logTicks', () => {
  it('adds 2 and 5 multiples on a short axis', () => {
    expect(logTicks([100, 2000], 10)).toEqual([100, 200, 500, 1000, 2000]);
    expect(oneTwoFiveTicks(1e-7, 1e-5)).toEqual([1e-7, 2e-7, 5e-7, 1e-6, 2e-6, 5e-6, 1e-5]);
  });
  it('thins long axes on a fixed lattice of decades', () => {
    const t = logTicks([1e-18, 1], 10);
    expect(t.length).toBeLessThanOrEqual(10);
    expect(t.map((v) => Math.round(Math.log10(v)))).toEqual([-18, -16, -14, -12, -10, -8, -6, -4, -2, 0]);
    expect(logTicks([1e-18, 1], 9, -17).map((v) => Math.round(Math.log10(v)))).toContain(-17);
  });
});

describe('niceLogDomain', () => {
  it('widens to whole decades', () => {
    expect(niceLogDomain(3e-10, 0.5)).toEqual([1e-10, 1]);
    expect(niceLogDomain(1e-3, 1e-3)).toEqual([1e-3, 1e-3]);
  });
});

describe('niceOneTwoFiveDomain', () => {
  it('is the tightest 1-2-5 interval around the range', () => {
    const all = lattice125(-20, 20);
    for (const [lo, hi] of [
      [142.6, 1183],
      [3.3e-9, 4.1e-9],
      [1, 1000],
      [0.07, 0.3],
    ] as Array<[number, number]>) {
      const [a, b] = niceOneTwoFiveDomain(lo, hi);
      const expectA = all.filter((v) => v <= lo * (1 + 1e-12)).at(-1);
      const expectB = all.find((v) => v >= hi * (1 - 1e-12));
      expect([a, b]).toEqual([expectA, expectB]);
    }
  });
});

describe('fittedTicks', () => {
  const labelWidth = () => 20;
  it('keeps the starting count when its labels fit', () => {
    const x = (v: number) => v;
    expect(fittedTicks((c) => integerTicks(0, 400, c), x, labelWidth, 4)).toEqual(integerTicks(0, 400, 4));
  });
  it('lowers the count until labels keep the gap, down to a single label', () => {
    const squeezed = (v: number) => v / 10; // 400 units in 40 px
    const t = fittedTicks((c) => integerTicks(0, 400, c), squeezed, labelWidth, 10);
    for (let i = 1; i < t.length; i++) expect(squeezed(t[i]) - squeezed(t[i - 1]) - 20).toBeGreaterThanOrEqual(6);
    expect(t.length).toBeGreaterThanOrEqual(1);
    expect(t.length).toBeLessThan(integerTicks(0, 400, 10).length);
    expect(
      fittedTicks(
        (c) => integerTicks(0, 400, c),
        (v) => v / 100,
        labelWidth,
        10,
      ),
    ).toHaveLength(1);
  });
});
