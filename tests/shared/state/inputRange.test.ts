import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { classify } from '../../../src/solver';
import { formatInputRange, sliderIntervals } from '../../../src/shared/state/inputRange';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import { messagesZhTw } from '../../../src/shared/i18n/messagesZhTw';
import { referenceLimits } from '../../oracle/reference';

/** Whether a slider interval holds an angle already in [0, 360). */
function holds(iv: { loDeg: number; hiDeg: number; wraps: boolean }, x: number, eps: number): boolean {
  return iv.wraps ? x >= iv.loDeg - eps || x <= iv.hiDeg + eps : x >= iv.loDeg - eps && x <= iv.hiDeg + eps;
}

/** An independent [0, 360) wrap for the oracle side. */
function to360(x: number): number {
  return ((x % 360) + 360) % 360;
}

describe('sliderIntervals', () => {
  it('holds exactly the angles of the interval, in the slider convention (seeded property)', () => {
    const interval = fc
      .tuple(fc.double({ min: -180, max: 180, noNaN: true }), fc.double({ min: 0, max: 359, noNaN: true }))
      .map(([lo, width]) => ({ lo, hi: lo + width }));
    fc.assert(
      fc.property(interval, fc.double({ min: 0, max: 1, noNaN: true }), (iv, f) => {
        const [s] = sliderIntervals([iv]);
        expect(s.loDeg).toBeGreaterThanOrEqual(0);
        expect(s.loDeg).toBeLessThan(360);
        expect(s.hiDeg).toBeLessThanOrEqual(360);
        // A point inside maps inside; a point in the gap (outside the interval on the circle) maps outside.
        const width = iv.hi - iv.lo;
        const inside = to360(iv.lo + f * width);
        expect(holds(s, inside, 1e-9)).toBe(true);
        const gap = 360 - width;
        if (gap > 1e-6) {
          const outside = to360(iv.hi + gap * Math.min(0.999, Math.max(0.001, f)));
          expect(holds(s, outside, -1e-9)).toBe(false);
        }
      }),
      { seed: 20251222, numRuns: 500 },
    );
  });

  it('sorts intervals by their start on the slider', () => {
    const s = sliderIntervals([
      { lo: 38.6, hi: 78.6 },
      { lo: -78.6, hi: -38.6 },
    ]);
    expect(s.map((x) => x.loDeg)).toEqual([38.6, 360 - 78.6]);
  });
});

describe('formatInputRange', () => {
  it('says the triple rocker 4-3-3.5-3 reaches 224.05° through 0° to 135.95°, not −135.95°…135.95°', () => {
    const l = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
    const c = classify(l);
    // The oracle's upper limit, independent of the classification.
    const upperDeg = (referenceLimits(l).upperAbs * 180) / Math.PI;
    const shown = `${(360 - upperDeg).toFixed(2)}° through 0° to ${upperDeg.toFixed(2)}°`;
    expect(formatInputRange(c.inputRange, messagesEn)).toBe(shown);
    expect(shown).toBe('224.05° through 0° to 135.95°');
    expect(formatInputRange(c.inputRange, messagesZhTw)).toBe('224.05° 經 0° 至 135.95°');
  });

  it('keeps an interval that does not pass 0° as one plain range', () => {
    const l = { r1: 4, r2: 3, r3: 1, r4: 3.5 };
    const c = classify(l);
    const lim = referenceLimits(l);
    const lo = (lim.lowerAbs * 180) / Math.PI;
    const hi = (lim.upperAbs * 180) / Math.PI;
    expect(formatInputRange(c.inputRange, messagesEn)).toBe(
      `${lo.toFixed(2)}° to ${hi.toFixed(2)}°; ${(360 - hi).toFixed(2)}° to ${(360 - lo).toFixed(2)}°`,
    );
  });

  it('says full turn for a crank and none when the linkage cannot assemble', () => {
    expect(formatInputRange(classify({ r1: 6, r2: 2, r3: 5, r4: 5 }).inputRange, messagesEn)).toBe('full turn');
    expect(formatInputRange(classify({ r1: 10, r2: 1, r3: 2, r4: 3 }).inputRange, messagesEn)).toBe(messagesEn.noRange);
  });
});
