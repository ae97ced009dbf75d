import { describe, expect, it } from 'vitest';
import { MAX_PLAY_DT_S, startPlayLoop } from '../../../src/features/spatial/playLoop';
import type { AnimationFrames } from '../../../src/features/spatial/playLoop';

/**
 * Animation frames as the HTML spec runs them: each frame runs, in the order they were asked for, the callbacks asked
 * for before it began; a callback asked for during a frame waits for the next one.
 */
function fakeFrames(): AnimationFrames & { run(nowMs: number): void; waiting(): number } {
  let next = 1;
  let queue = new Map<number, (nowMs: number) => void>();
  return {
    request(callback) {
      queue.set(next, callback);
      return next++;
    },
    cancel(handle) {
      queue.delete(handle);
    },
    run(nowMs) {
      const due = queue;
      queue = new Map();
      for (const callback of due.values()) callback(nowMs);
    },
    waiting: () => queue.size,
  };
}

/** A view as spatialScene.ts schedules it: a change asks for one render on the next frame, unless one is pending. */
function fakeView(frames: AnimationFrames) {
  let pending = 0;
  let drawn = 0;
  let shown = -1;
  let posed = -1;
  return {
    setPose(pose: number) {
      posed = pose;
      if (pending) return;
      pending = frames.request(() => {
        pending = 0;
        drawn++;
        shown = posed;
      });
    },
    drawn: () => drawn,
    shown: () => shown,
  };
}

describe('startPlayLoop', () => {
  it('lets the view draw on every animation frame (a render asked for in a tick runs before the next tick)', () => {
    const frames = fakeFrames();
    const view = fakeView(frames);
    let ticks = 0;
    startPlayLoop(frames, () => view.setPose(++ticks));
    const periodMs = 1000 / 60;
    for (let i = 0; i < 3; i++) frames.run(i * periodMs);
    const before = view.drawn();
    for (let i = 3; i < 63; i++) frames.run(i * periodMs);
    // 60 animation frames, 60 drawn (30 when the loop asked for its next frame before the tick: issue 32's Play).
    expect(view.drawn() - before).toBe(60);
    // Each drawn frame shows the pose of the tick one animation frame before it.
    expect(view.shown()).toBe(ticks - 1);
  });

  it('passes the time since the last frame in seconds, capped at MAX_PLAY_DT_S, and skips the first frame', () => {
    const frames = fakeFrames();
    const dts: number[] = [];
    const nows: number[] = [];
    startPlayLoop(frames, (dt, now) => {
      dts.push(dt);
      nows.push(now);
    });
    frames.run(1000);
    frames.run(1016);
    frames.run(1016);
    frames.run(3016);
    expect(nows).toEqual([1016, 3016]);
    expect(dts[0]).toBeCloseTo(0.016, 15);
    expect(dts[1]).toBe(MAX_PLAY_DT_S);
  });

  it('stops: no frame asked for after stop, also when stopped from inside a tick', () => {
    const frames = fakeFrames();
    let ticks = 0;
    const stop = startPlayLoop(frames, () => ticks++);
    frames.run(0);
    frames.run(10);
    stop();
    expect(frames.waiting()).toBe(0);
    frames.run(20);
    expect(ticks).toBe(1);
    const frames2 = fakeFrames();
    let stop2 = () => {};
    stop2 = startPlayLoop(frames2, () => stop2());
    frames2.run(0);
    frames2.run(10);
    expect(frames2.waiting()).toBe(0);
  });

  it('keeps running after a tick throws (the error still reaches the caller)', () => {
    const frames = fakeFrames();
    let ticks = 0;
    startPlayLoop(frames, () => {
      ticks++;
      if (ticks === 1) throw new Error('boom');
    });
    frames.run(0);
    expect(() => frames.run(10)).toThrow('boom');
    frames.run(20);
    expect(ticks).toBe(2);
  });
});
