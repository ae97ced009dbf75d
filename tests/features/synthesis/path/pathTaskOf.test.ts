import { describe, expect, it } from 'vitest';
import { defaultPathBounds, pathTaskOf, samePathTask } from '../../../../src/features/synthesis/path/pathTaskOf';
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

describe('samePathTask', () => {
  const s = { ...DEFAULT_SYN_PATH, targets: square };
  it('holds for the same task, and fails after any edit of targets, timing, bounds or input (issue 34, 1)', () => {
    expect(samePathTask(pathTaskOf(s), pathTaskOf({ ...s, targets: square.map((p) => ({ ...p })) }))).toBe(true);
    // The seed and the candidate shown are not the task.
    expect(samePathTask(pathTaskOf(s), pathTaskOf({ ...s, seed: 9, chosen: 3 }))).toBe(true);
    const edits = [
      { targets: square.map((p, i) => (i === 2 ? { x: p.x + 1e-9, y: p.y } : p)) },
      { targets: square.slice(0, 3) },
      { targets: [...square, { x: 0, y: 0 }] },
      { timing: 'step' as const },
      { boundLength: 30 },
      { boundCoupler: 2 },
      { pivotBox: { min: { x: -1, y: -1 }, max: { x: 1, y: 1 } } },
      { input: 'any' as const },
    ];
    for (const e of edits)
      expect(samePathTask(pathTaskOf(s), pathTaskOf({ ...s, ...e })), JSON.stringify(e)).toBe(false);
  });
});
