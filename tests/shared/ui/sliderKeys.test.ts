import { describe, expect, it } from 'vitest';
import { turnKeyValue } from '../../../src/shared/ui/sliderKeys';

const DEG = { step: 1 };
const key = (k: string, v: number) => turnKeyValue(k, v, 0, 360, DEG);

describe('turnKeyValue', () => {
  it('moves an arrow press one degree, to the next whole degree from between two', () => {
    expect(key('ArrowRight', 45)).toBe(46);
    expect(key('ArrowUp', 45)).toBe(46);
    expect(key('ArrowLeft', 45)).toBe(44);
    expect(key('ArrowRight', 202.98804)).toBe(203);
    expect(key('ArrowLeft', 202.98804)).toBe(202);
    // Float noise counts as on the grid: a whole step, not a sliver.
    expect(key('ArrowRight', 45.00000000001)).toBe(46);
  });

  it('goes ten degrees with Page Up and Page Down', () => {
    expect(key('PageUp', 45)).toBe(55);
    expect(key('PageDown', 45)).toBe(35);
  });

  it('turns a full circle in 360 presses and wraps at both ends', () => {
    let v = 0;
    for (let i = 0; i < 360; i++) v = key('ArrowRight', v) ?? Number.NaN;
    expect(v).toBe(0);
    expect(key('ArrowRight', 359)).toBe(0);
    expect(key('ArrowLeft', 0)).toBe(359);
    expect(key('PageDown', 5)).toBe(355);
  });

  it('sends End to the last step below the full turn, never to 360 (which is 0 again)', () => {
    expect(key('End', 45)).toBe(359);
    expect(key('Home', 45)).toBe(0);
  });

  it('works on a range that does not start at 0 (the coupler angle, -180 to 180)', () => {
    expect(turnKeyValue('ArrowRight', 179, -180, 180, DEG)).toBe(-180);
    expect(turnKeyValue('ArrowLeft', -180, -180, 180, DEG)).toBe(179);
    expect(turnKeyValue('ArrowRight', -20.5, -180, 180, DEG)).toBe(-20);
  });

  it('leaves every other key to the browser', () => {
    expect(key('Tab', 45)).toBeNull();
    expect(key('a', 45)).toBeNull();
  });
});
