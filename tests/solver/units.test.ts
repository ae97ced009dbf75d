import { describe, expect, it } from 'vitest';
import {
  degPerSToRadPerS,
  degToRad,
  radPerSToDegPerS,
  radPerSToRpm,
  radToDeg,
  rpmToRadPerS,
  wrapDeg180,
  wrapDeg360,
} from '../../src/solver/angles';

describe('wrapDeg360', () => {
  it('keeps [0, 360) and wraps the rest', () => {
    expect(wrapDeg360(45)).toBe(45);
    expect(wrapDeg360(360)).toBe(0);
    expect(wrapDeg360(-30)).toBe(330);
    expect(wrapDeg360(725)).toBe(5);
  });
  it('never returns 360 for a tiny negative angle', () => {
    expect(wrapDeg360(-1e-17)).toBeLessThan(360);
    expect(wrapDeg360(-1e-17)).toBeGreaterThanOrEqual(0);
  });
  it('maps non-finite input to 0', () => {
    expect(wrapDeg360(Number.NaN)).toBe(0);
    expect(wrapDeg360(Infinity)).toBe(0);
  });
});

describe('wrapDeg180', () => {
  it('wraps to (-180, 180]', () => {
    expect(wrapDeg180(180)).toBe(180);
    expect(wrapDeg180(-180)).toBe(180);
    expect(wrapDeg180(190)).toBe(-170);
    expect(wrapDeg180(-190)).toBe(170);
    expect(wrapDeg180(540)).toBe(180);
    expect(wrapDeg180(12.5)).toBe(12.5);
  });
  it('leaves NaN as NaN (a gap, never a number)', () => {
    expect(wrapDeg180(Number.NaN)).toBeNaN();
  });
});

describe('wrapDeg360 and wrapDeg180 at any magnitude', () => {
  // x % 360 is exact, so the oracle is exact integer arithmetic on the double's value (BigInt).
  const exactMod360 = (x: number): number => {
    // Every double >= 2^53 is an integer; below that the test uses integers only.
    const r = Number(BigInt(x) % 360n);
    return r < 0 ? r + 360 : r;
  };
  it('reduces huge integers exactly', () => {
    for (const x of [1e15, 1e22, -1e22, 2 ** 60 + 2 ** 9, 1.7976931348623157e308, -1.7976931348623157e308]) {
      const want = exactMod360(x);
      expect(wrapDeg360(x)).toBe(want);
      expect(wrapDeg180(x)).toBe(want > 180 ? want - 360 : want);
    }
  });
  it('stays inside its documented range', () => {
    for (const x of [-1e-300, -5e-324, 359.99999999999994, -359.99999999999994, -180, 180, 540, -540]) {
      const w = wrapDeg360(x);
      expect(w >= 0 && w < 360).toBe(true);
      const v = wrapDeg180(x);
      expect(v > -180 && v <= 180).toBe(true);
    }
  });
});

describe('unit conversions', () => {
  it('converts rad/s to rpm and degrees per second and back', () => {
    expect(radPerSToRpm(2 * Math.PI)).toBeCloseTo(60, 12);
    expect(rpmToRadPerS(60)).toBeCloseTo(2 * Math.PI, 12);
    expect(radPerSToDegPerS(Math.PI)).toBeCloseTo(180, 12);
    expect(degPerSToRadPerS(180)).toBeCloseTo(Math.PI, 12);
    expect(radToDeg(degToRad(37.5))).toBeCloseTo(37.5, 12);
  });
});
