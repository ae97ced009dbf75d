import { describe, expect, it } from 'vitest';
import { createPageDraws, dragViaStage } from '../../../../src/features/simulator/stage/pageDraws';
import { createStageInputs } from '../../../../src/features/simulator/stage/stageInputs';
import { createStageRun } from '../../../../src/features/simulator/stage/stageRun';
import { DEFAULT_STATE } from '../../../../src/shared/state/appState';
import type { PlayFrame } from '../../../../src/shared/state/playhead';

const frame = (theta2Deg: number): PlayFrame => ({ theta2Deg, direction: 1, branch: 'open' }) as PlayFrame;

describe('createPageDraws', () => {
  it('is not judged before six draws, however slow they are (the first carry one-time costs)', () => {
    const d = createPageDraws();
    for (const ms of [100, 50, 30, 20, 20]) d.note(ms);
    expect([d.judged(), d.slow()]).toEqual([false, false]);
    d.note(20);
    expect([d.judged(), d.slow()]).toEqual([true, true]);
  });

  it('decides by the lower median of the latest five draws (4, 4, 5, 9, 50: median 5 is slow)', () => {
    const d = createPageDraws();
    // The first (200) is no longer kept at the sixth.
    for (const ms of [200, 50, 4, 9, 5, 4]) d.note(ms);
    expect(d.slow()).toBe(true);
  });

  it('forgets draws older than the latest five and passes over bad times', () => {
    const d = createPageDraws();
    for (const ms of [9, 9, 1, 1, 1, 1]) d.note(ms);
    // Kept: 9, 1, 1, 1, 1 (median 1); NaN, -1 and Infinity are not kept.
    d.note(Number.NaN);
    d.note(-1);
    d.note(Infinity);
    expect(d.slow()).toBe(false);
    d.note(9);
    d.note(9);
    // Kept: 1, 1, 1, 9, 9 → 1, quick; one more 9 keeps 1, 1, 9, 9, 9 → 9, slow.
    expect(d.slow()).toBe(false);
    d.note(9);
    expect(d.slow()).toBe(true);
  });

  it('stays slow once slow: a window of lucky quick draws (CPU throttle) does not hand drags back to the page', () => {
    const d = createPageDraws();
    // The first frame and its idle redraws at 6x (measured: 192, 53, 28, 23, 20, 17 ms), then a drag's draws over the
    // cached background, some of which CDP's throttle lets through at full speed.
    for (const ms of [192, 53, 28, 23, 20, 17]) d.note(ms);
    expect(d.slow()).toBe(true);
    for (const ms of [1.5, 3.3, 1.6, 2.2, 1.4, 1.7]) d.note(ms);
    expect(d.slow()).toBe(true);
  });

  it('is quick for a quick page through its first draws and a drag (1x: 27, 7.2, 9.3, 1.3, 1.8, 1.3, then 1 to 6 ms)', () => {
    const d = createPageDraws();
    for (const ms of [26.9, 7.2, 9.3, 1.3, 1.8, 1.3, 1.7, 2.3, 1.6, 6.0, 2.0, 1.9]) d.note(ms);
    expect(d.slow()).toBe(false);
  });
});

describe('dragViaStage', () => {
  it("decides a drag's route at its first move from the page's speed", () => {
    expect(dragViaStage(true, false, true)).toBe(true);
    expect(dragViaStage(true, false, false)).toBe(false);
    // A new drag does not inherit the last one's route.
    expect(dragViaStage(true, true, false)).toBe(false);
  });

  it('moves a drag the page draws to the stage once the page is found slow, and never back within the drag', () => {
    expect(dragViaStage(false, false, false)).toBe(false);
    expect(dragViaStage(false, false, true)).toBe(true);
    expect(dragViaStage(false, true, false)).toBe(true);
  });
});

describe('createStageInputs', () => {
  it('sends a size once per change and replays the latest', () => {
    const inputs = createStageInputs();
    expect(inputs.size(300, 200, 2)).toEqual({ type: 'size', width: 300, height: 200, dpr: 2 });
    expect(inputs.size(300, 200, 2)).toBeNull();
    expect(inputs.size(300, 200, 1)).toEqual({ type: 'size', width: 300, height: 200, dpr: 1 });
    expect(inputs.replay()).toEqual([{ type: 'size', width: 300, height: 200, dpr: 1 }]);
  });

  it('sends the state and the cycle only when each changes, a null cycle included', () => {
    const inputs = createStageInputs();
    expect(inputs.scene(DEFAULT_STATE, null, false)).toEqual([
      { type: 'state', state: DEFAULT_STATE, ghostShown: false },
      { type: 'cycle', cycle: null },
    ]);
    expect(inputs.scene(DEFAULT_STATE, null, false)).toEqual([]);
    expect(inputs.scene(DEFAULT_STATE, null, true)).toEqual([
      { type: 'state', state: DEFAULT_STATE, ghostShown: true },
    ]);
    const next = { ...DEFAULT_STATE };
    expect(inputs.scene(next, null, true)).toEqual([{ type: 'state', state: next, ghostShown: true }]);
  });

  it('replays size, state and cycle in that order for a worker that starts late', () => {
    const inputs = createStageInputs();
    expect(inputs.replay()).toEqual([]);
    inputs.scene(DEFAULT_STATE, null, false);
    inputs.size(10, 20, 1);
    expect(inputs.replay().map((m) => m.type)).toEqual(['size', 'state', 'cycle']);
  });
});

describe('createStageRun', () => {
  it('drops a reply of an earlier run', () => {
    const run = createStageRun();
    const first = run.begin('play');
    const second = run.begin('play');
    expect(second).not.toBe(first);
    expect(run.receive(first, frame(10))).toBe(false);
    expect(run.newest()).toBeNull();
    expect(run.receive(second, frame(20))).toBe(true);
    expect(run.newest()).toEqual(frame(20));
  });

  it("shows play from its third frame and a drag's shows from its first", () => {
    const run = createStageRun();
    const id = run.begin('play');
    run.receive(id, frame(1));
    run.receive(id, frame(2));
    expect(run.ready()).toBe(false);
    run.receive(id, frame(3));
    expect(run.ready()).toBe(true);
    const drag = run.begin('show');
    expect(run.ready()).toBe(false);
    run.receive(drag, frame(4));
    expect(run.ready()).toBe(true);
  });

  it('end() makes the run stale and forgets its frames; abandon() keeps the newest', () => {
    const run = createStageRun();
    const id = run.begin('play');
    run.receive(id, frame(5));
    run.abandon();
    expect(run.mode()).toBeNull();
    expect(run.newest()).toEqual(frame(5));
    run.end();
    expect(run.newest()).toBeNull();
    expect(run.receive(id, frame(6))).toBe(false);
  });
});
