import { describe, expect, it } from 'vitest';
import { classify } from '../../../src/solver';
import type { Linkage } from '../../../src/solver';
import {
  advanceTheta2,
  degreesForElapsed,
  inputTurnsFully,
  isRocking,
  rangeToDeg,
  stepTheta2,
} from '../../../src/shared/state/animation';
import type { StepState } from '../../../src/shared/state/animation';
import { formatInputRange } from '../../../src/shared/state/inputRange';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import { getPreset } from '../../../src/shared/state/presets';

const FULL = { full: true, intervals: [{ lo: -180, hi: 180 }] };
/** The triple rocker 4-3-3.5-3 of the hard-case table: the input rocks within ±135.95°. */
const ROCKING = { full: false, intervals: [{ lo: -135.95, hi: 135.95 }] };

/** Angles compared on the circle, degrees. */
function gapDeg(a: number, b: number): number {
  const d = Math.abs(a - b) % 360;
  return Math.min(d, 360 - d);
}

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
    const s = advanceTheta2(135, 2, 1, 'open', ROCKING);
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

describe('full-turn cranks: change points and parallelograms', () => {
  // Change points (S + L = P + Q) whose input still turns fully, by the classification's own limit analysis:
  // the parallelogram 4-2-4-2, its ground-shortest inversion 2-4-2-4, the kite 4-2-2-4 and a crank-rocker-like 6-2-5-3.
  const FULL_TURN: ReadonlyArray<[string, Linkage]> = [
    ['parallelogram 4-2-4-2', { r1: 4, r2: 2, r3: 4, r4: 2 }],
    ['parallelogram 2-4-2-4', { r1: 2, r2: 4, r3: 2, r4: 4 }],
    ['kite 4-2-2-4', { r1: 4, r2: 2, r3: 2, r4: 4 }],
    ['change point 6-2-5-3', { r1: 6, r2: 2, r3: 5, r4: 3 }],
    ['the parallelogram preset', getPreset('parallelogram').linkage],
  ];

  it.each(FULL_TURN)('%s is a change point and a full-turn crank', (_name, l) => {
    const c = classify(l);
    expect(c.type).toBe('change-point');
    // Independent check: a crank turns fully when every input angle closes the loop, i.e. the distance
    // from A to O4 always lies within [|r3 - r4|, r3 + r4].
    for (let k = 0; k < 720; k++) {
      const t = (k / 720) * 2 * Math.PI;
      const d = Math.hypot(l.r2 * Math.cos(t) - l.r1, l.r2 * Math.sin(t));
      expect(d).toBeLessThanOrEqual(l.r3 + l.r4 + 1e-12);
      expect(d).toBeGreaterThanOrEqual(Math.abs(l.r3 - l.r4) - 1e-12);
    }
    const range = rangeToDeg(c.inputRange);
    expect(inputTurnsFully(range)).toBe(true);
    expect(isRocking(c.inputRange)).toBe(false);
    expect(formatInputRange(c.inputRange, messagesEn)).toBe(messagesEn.fullTurn);
    // Play wraps through 0° instead of reversing, and keeps the branch.
    expect(advanceTheta2(359, 2, 1, 'open', range)).toEqual({ theta2Deg: 1, direction: 1, branch: 'open' });
  });

  it('a change point whose input is not the crank rocks (4-4-2-2)', () => {
    const c = classify({ r1: 4, r2: 4, r3: 2, r4: 2 });
    expect(c.type).toBe('change-point');
    expect(isRocking(c.inputRange)).toBe(true);
  });
});

describe('stepTheta2', () => {
  const at = (theta2Deg: number, direction: 1 | -1): StepState => ({
    theta2Deg,
    samples: 360,
    direction,
    branch: 'open',
  });

  it('steps forward along Counter-clockwise and Clockwise alike', () => {
    expect(stepTheta2(at(45, 1), FULL, 1)).toEqual({ theta2Deg: 46, direction: 1, branch: 'open' });
    expect(stepTheta2(at(45, -1), FULL, 1)).toEqual({ theta2Deg: 44, direction: -1, branch: 'open' });
    expect(stepTheta2(at(45, -1), FULL, -1)).toEqual({ theta2Deg: 46, direction: -1, branch: 'open' });
    expect(stepTheta2(at(0, -1), FULL, 1).theta2Deg).toBe(359);
  });

  it('steps one sample (360 / samples degrees) before the cycle is known', () => {
    expect(stepTheta2({ ...at(10, 1), samples: 720 }, null, 1).theta2Deg).toBe(10.5);
  });

  it('lands on the step grid from an angle between two grid points, both ways', () => {
    expect(stepTheta2(at(202.98804, 1), FULL, 1).theta2Deg).toBe(203);
    expect(stepTheta2(at(202.98804, 1), FULL, -1).theta2Deg).toBe(202);
    expect(stepTheta2(at(202.98804, -1), FULL, 1).theta2Deg).toBe(202);
    expect(stepTheta2({ ...at(359.7, 1), samples: 720 }, FULL, 1).theta2Deg).toBe(0);
    // Float noise from Play or the URL counts as on the grid: a whole step, not a sliver.
    expect(stepTheta2(at(45.00000000001, 1), FULL, 1).theta2Deg).toBe(46);
  });

  it('follows a rocking input past its limit: branch and direction switch as in Play', () => {
    const s = stepTheta2(at(135.5, 1), ROCKING, 1);
    expect(s.branch).toBe('crossed');
    expect(s.direction).toBe(-1);
    // A rocking input steps whole steps (its reflections are off any grid): 0.55 past the limit, reflected.
    expect(s.theta2Deg).toBeCloseTo(135.95 - 0.55, 5);
    // The next forward step keeps going the same way along the motion, not back over the limit.
    const s2 = stepTheta2({ ...at(s.theta2Deg, s.direction), branch: s.branch }, ROCKING, 1);
    expect(s2).toMatchObject({ branch: 'crossed', direction: -1 });
    expect(s2.theta2Deg).toBeCloseTo(s.theta2Deg - 1, 9);
  });

  it('is undone by Step back (from a grid point on a full turn), across limits too', () => {
    // Every start lies inside the reachable ±135.95° (225° is −135°), some within a step of a limit.
    const starts = (range: typeof FULL) => (range.full ? [0, 45, 135, 225, 359] : [0, 45, 135.2, 135.5, 224.5, 225]);
    for (const range of [FULL, ROCKING])
      for (const direction of [1, -1] as const)
        for (const start of starts(range)) {
          const s0 = at(start, direction);
          const s1 = stepTheta2(s0, range, 1);
          const s2 = stepTheta2({ ...s0, ...s1 }, range, -1);
          // Reflections are exact up to rounding of a few additions of numbers below 360.
          expect(gapDeg(s2.theta2Deg, start), `${start} ${direction}`).toBeLessThan(1e-9);
          expect(s2.branch).toBe('open');
          expect(s2.direction).toBe(direction);
        }
  });
});
