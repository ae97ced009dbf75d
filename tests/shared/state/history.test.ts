import { describe, expect, it } from 'vitest';
import type { History, HistoryAction, HistoryPolicy } from '../../../src/shared/state/history';
import {
  BURST_MS,
  HISTORY_CAP,
  canRedo,
  canUndo,
  historyReducer,
  initHistory,
} from '../../../src/shared/state/history';

/** A toy state: two numbers that are undone, and a view that is not. */
interface Toy {
  a: number;
  b: number;
  view: number;
}
type ToyAction = { type: 'setA'; value: number } | { type: 'setB'; value: number } | { type: 'pan'; value: number };

function toyReducer(s: Toy, action: ToyAction): Toy {
  if (action.type === 'setA') return s.a === action.value ? s : { ...s, a: action.value };
  if (action.type === 'setB') return s.b === action.value ? s : { ...s, b: action.value };
  return s.view === action.value ? s : { ...s, view: action.value };
}

const policy: HistoryPolicy<Toy, ToyAction> = {
  stepKey: (a) => (a.type === 'pan' ? null : a.type),
  carry: (restored, present) => ({ ...restored, view: present.view }),
};
const reduce = historyReducer(toyReducer, policy);
const START: Toy = { a: 0, b: 0, view: 0 };

/** Applies actions at the given times (ms), outside any gesture unless one is given. */
function run(h: History<Toy>, steps: readonly (readonly [ToyAction, number, (number | null)?])[]): History<Toy> {
  return steps.reduce((acc, [action, at, gesture = null]) => reduce(acc, { type: 'apply', action, at, gesture }), h);
}

const undo: HistoryAction<ToyAction> = { type: 'undo' };
const redo: HistoryAction<ToyAction> = { type: 'redo' };

describe('historyReducer', () => {
  it('records a change as a step and undoes and redoes it', () => {
    const h = run(initHistory(START), [[{ type: 'setA', value: 1 }, 0]]);
    expect(h.present.a).toBe(1);
    expect(canUndo(h)).toBe(true);
    const u = reduce(h, undo);
    expect(u.present).toEqual(START);
    expect(canUndo(u)).toBe(false);
    expect(canRedo(u)).toBe(true);
    expect(reduce(u, redo).present.a).toBe(1);
  });

  it('returns the same history for an action that changes nothing, and for undo or redo with nothing to do', () => {
    const h = initHistory(START);
    expect(run(h, [[{ type: 'setA', value: 0 }, 0]])).toBe(h);
    expect(reduce(h, undo)).toBe(h);
    expect(reduce(h, redo)).toBe(h);
  });

  it('makes one step of every change in one gesture, however long it lasts', () => {
    // A slow drag: 300 moves over 7.5 minutes, each 1.5 s after the last (each pause longer than a burst).
    const moves = Array.from({ length: 300 }, (_, i) => [{ type: 'setA', value: i + 1 }, i * 1500, 7] as const);
    const h = run(initHistory(START), moves);
    expect(h.past).toHaveLength(1);
    expect(h.present.a).toBe(300);
    expect(reduce(h, undo).present.a).toBe(0);
  });

  it('joins changes of one gesture even across keys and pauses (a pinch, a drag that moves two things)', () => {
    const h = run(initHistory(START), [
      [{ type: 'setA', value: 1 }, 0, 3],
      [{ type: 'setB', value: 1 }, 5000, 3],
    ]);
    expect(h.past).toHaveLength(1);
  });

  it('starts a new step with a new gesture', () => {
    const h = run(initHistory(START), [
      [{ type: 'setA', value: 1 }, 0, 1],
      [{ type: 'setA', value: 2 }, 10, 2],
    ]);
    expect(h.past).toHaveLength(2);
    expect(reduce(h, undo).present.a).toBe(1);
  });

  it("joins a drag's release value (same key, no gesture, within BURST_MS) to the drag, not another key's", () => {
    const h = run(initHistory(START), [
      [{ type: 'setA', value: 1 }, 0, 4],
      [{ type: 'setA', value: 2 }, 100, 4],
      // Committed on the release, after the pointer's gesture ended.
      [{ type: 'setA', value: 3 }, 150],
    ]);
    expect(h.past.map((s) => s.a)).toEqual([0]);
    expect(reduce(h, undo).present.a).toBe(0);
    const other = run(initHistory(START), [
      [{ type: 'setA', value: 1 }, 0, 4],
      [{ type: 'setB', value: 1 }, 50],
      [{ type: 'setA', value: 2 }, 60 + BURST_MS + 1],
    ]);
    expect(other.past.map((s) => [s.a, s.b])).toEqual([
      [0, 0],
      [1, 0],
      [1, 1],
    ]);
  });

  it('joins a burst of the same key with pauses up to BURST_MS, and splits at a longer pause', () => {
    const h = run(initHistory(START), [
      [{ type: 'setA', value: 1 }, 0],
      [{ type: 'setA', value: 2 }, BURST_MS],
      [{ type: 'setA', value: 3 }, 2 * BURST_MS],
      [{ type: 'setA', value: 4 }, 3 * BURST_MS + 1],
    ]);
    expect(h.past.map((s) => s.a)).toEqual([0, 3]);
  });

  it('does not join a burst of another key', () => {
    const h = run(initHistory(START), [
      [{ type: 'setA', value: 1 }, 0],
      [{ type: 'setB', value: 1 }, 1],
      [{ type: 'setA', value: 2 }, 2],
    ]);
    expect(h.past).toHaveLength(3);
  });

  it('keeps a change that is not a step in the present, without a step and without dropping the future', () => {
    const h = reduce(run(initHistory(START), [[{ type: 'setA', value: 1 }, 0]]), undo);
    const panned = run(h, [[{ type: 'pan', value: 5 }, 10]]);
    expect(panned.present.view).toBe(5);
    expect(panned.past).toHaveLength(0);
    expect(panned.future).toHaveLength(1);
    // Redo carries the view from the present: the pan is not undone by it.
    expect(reduce(panned, redo).present).toEqual({ a: 1, b: 0, view: 5 });
  });

  it('carries what is not undone from the present on undo', () => {
    const h = run(initHistory(START), [
      [{ type: 'setA', value: 1 }, 0],
      [{ type: 'pan', value: 9 }, 10],
    ]);
    expect(reduce(h, undo).present).toEqual({ a: 0, b: 0, view: 9 });
  });

  it('drops the future on a new step', () => {
    const h = reduce(
      run(initHistory(START), [
        [{ type: 'setA', value: 1 }, 0],
        [{ type: 'setB', value: 1 }, 1],
      ]),
      undo,
    );
    expect(canRedo(h)).toBe(true);
    const next = run(h, [[{ type: 'setA', value: 5 }, 2]]);
    expect(canRedo(next)).toBe(false);
  });

  it('never joins a change to a step that was undone or redone (undo seals the newest step)', () => {
    const h = run(initHistory(START), [
      [{ type: 'setA', value: 1 }, 0],
      [{ type: 'setA', value: 2 }, 2000],
    ]);
    const u = reduce(h, undo);
    const again = run(u, [[{ type: 'setA', value: 7 }, 2001]]);
    expect(again.past.map((s) => s.a)).toEqual([0, 1]);
    const r = run(reduce(u, redo), [[{ type: 'setA', value: 8 }, 2002]]);
    expect(r.past.map((s) => s.a)).toEqual([0, 1, 2]);
  });

  it('never joins a change of the same gesture to the step before an undo', () => {
    const h = run(initHistory(START), [
      [{ type: 'setA', value: 1 }, 0],
      [{ type: 'setA', value: 2 }, 5000, 9],
    ]);
    const again = run(reduce(h, undo), [[{ type: 'setA', value: 7 }, 5001, 9]]);
    expect(again.past.map((s) => s.a)).toEqual([0, 1]);
    expect(reduce(again, undo).present.a).toBe(1);
  });

  it(`keeps at most HISTORY_CAP (${HISTORY_CAP}) steps, dropping the oldest`, () => {
    const steps = Array.from(
      { length: HISTORY_CAP + 20 },
      (_, i) => [{ type: 'setA', value: i + 1 }, i * 5000] as const,
    );
    let h = run(initHistory(START), steps);
    expect(h.past).toHaveLength(HISTORY_CAP);
    for (let i = 0; i < HISTORY_CAP; i++) h = reduce(h, undo);
    expect(h.present.a).toBe(20);
    expect(canUndo(h)).toBe(false);
  });

  it('honours a policy cap and burst', () => {
    const small = historyReducer(toyReducer, { ...policy, cap: 2, burstMs: 10 });
    let h = initHistory(START);
    for (const [value, at] of [
      [1, 0],
      [2, 5],
      [3, 100],
      [4, 200],
    ])
      h = small(h, { type: 'apply', action: { type: 'setA', value }, at, gesture: null });
    expect(h.past.map((s) => s.a)).toEqual([2, 3]);
  });
});
