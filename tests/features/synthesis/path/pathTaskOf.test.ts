import { describe, expect, it } from 'vitest';
import { defaultPathBounds, pathTaskOf } from '../../../../src/features/synthesis/path/pathTaskOf';
import { DEFAULT_SYN_PATH } from '../../../../src/shared/state/slices/synthesisSlice';
import { normaliseTask } from '../../../../src/synthesis/pathTask';

const square = [
  { x: 10, y: 10 },
  { x: 12, y: 10 },
  { x: 12, y: 12 },
  { x: 10, y: 12 },
];

describe('defaultPathBounds', () => {
  it('scales with the targets’ size and holds the targets’ centroid in the pivot box', () => {
    const b = defaultPathBounds(square);
    const size = Math.SQRT2;
    expect(b.length).toBeGreaterThanOrEqual(5 * size);
    expect(b.length).toBeLessThan(5.5 * size);
    expect(b.coupler).toBeGreaterThanOrEqual(3 * size);
    expect(b.pivot.min.x).toBeLessThanOrEqual(11 - 4 * size);
    expect(b.pivot.max.y).toBeGreaterThanOrEqual(11 + 4 * size);
    const twice = defaultPathBounds(square.map((p) => ({ x: 2 * p.x, y: 2 * p.y })));
    // Both are rounded up to two significant digits (7.1 and 15): within 10 % of twice.
    expect(twice.length / b.length).toBeGreaterThan(1.9);
    expect(twice.length / b.length).toBeLessThan(2.2);
  });
});

describe('pathTaskOf', () => {
  it('turns the page’s degrees into radians and its bounds into a task the synthesis accepts', () => {
    const s = { ...DEFAULT_SYN_PATH, targets: square, timing: 'given' as const, givenTheta2Deg: [0, 90] };
    const task = pathTaskOf(s);
    expect(task.timing).toEqual({ kind: 'given', theta2: [0, Math.PI / 2, 0, 0] });
    expect(() => normaliseTask(task)).not.toThrow();
    const step = pathTaskOf({ ...s, timing: 'step', timingStepDeg: -30 });
    expect(step.timing).toEqual({ kind: 'step', step: -Math.PI / 6 });
    const set = pathTaskOf({ ...s, boundLength: 3, boundCoupler: 1 });
    expect(set.bounds).toMatchObject({ length: [0, 3], coupler: 1 });
  });
});
