import { describe, expect, it } from 'vitest';
import { advanceTheta2, degreesForElapsed, rangeToDeg } from '../../src/state/animation';

const FULL = { full: true, intervals: [{ lo: -180, hi: 180 }] };

describe('degreesForElapsed', () => {
  it('is time based: the same degrees per second at any frame rate', () => {
    const at60 = 60 * degreesForElapsed(2, 1 / 60);
    const at144 = 144 * degreesForElapsed(2, 1 / 144);
    expect(at60).toBeCloseTo(120, 10);
    expect(at144).toBeCloseTo(120, 10);
  });
});

describe('advanceTheta2', () => {
  it('wraps a full-turn input in either direction', () => {
    expect(advanceTheta2(359, 2, 1, 'open', FULL)).toEqual({ theta2Deg: 1, direction: 1, branch: 'open' });
    expect(advanceTheta2(1, 2, -1, 'open', FULL)).toEqual({ theta2Deg: 359, direction: -1, branch: 'open' });
  });

  it('rocks a limited input: reverses at the limit and switches branch', () => {
    const range = { full: false, intervals: [{ lo: -135.95, hi: 135.95 }] };
    const s = advanceTheta2(135, 2, 1, 'open', range);
    expect(s.direction).toBe(-1);
    expect(s.branch).toBe('crossed');
    expect(s.theta2Deg).toBeCloseTo(135.95 - 1.05, 4);
  });

  it('rocks across 0 degrees inside an interval given in (-180, 180]', () => {
    const range = { full: false, intervals: [{ lo: -40, hi: 40 }] };
    expect(advanceTheta2(359, 2, 1, 'open', range).theta2Deg).toBeCloseTo(1, 10);
    expect(advanceTheta2(330, 2, 1, 'open', range).theta2Deg).toBeCloseTo(332, 10);
  });

  it('handles an interval that runs past 180 degrees', () => {
    const range = { full: false, intervals: [{ lo: 57.95, hi: 302.05 }] };
    expect(advanceTheta2(179, 2, 1, 'open', range)).toMatchObject({ theta2Deg: 181, branch: 'open' });
    expect(advanceTheta2(302, 1, 1, 'open', range)).toMatchObject({ direction: -1, branch: 'crossed' });
  });

  it('jumps to the nearest limit from an unreachable angle', () => {
    const range = {
      full: false,
      intervals: [
        { lo: 38.6, hi: 78.6 },
        { lo: -78.6, hi: -38.6 },
      ],
    };
    const s = advanceTheta2(100, 0, 1, 'open', range);
    expect(s.theta2Deg).toBeCloseTo(78.6, 4);
    const t = advanceTheta2(300, 0, 1, 'open', range);
    expect(t.theta2Deg).toBeCloseTo(360 - 60, 0);
  });

  it('stays put when the linkage cannot assemble anywhere', () => {
    expect(advanceTheta2(45, 5, 1, 'open', { full: false, intervals: [] })).toEqual({
      theta2Deg: 45,
      direction: 1,
      branch: 'open',
    });
  });

  it('converts the solver range from radians', () => {
    expect(rangeToDeg({ full: false, intervals: [{ lo: -Math.PI / 2, hi: Math.PI / 2 }] }).intervals[0]).toEqual({
      lo: -90,
      hi: 90,
    });
  });
});
