import { describe, expect, it } from 'vitest';
import { MAX_DT_SECONDS, createStageClock } from '../../../src/shared/linkage/stageClock';
import { handRunFrames } from './handRunFrames';

const ORIGIN_MS = 2_000;

/** A worker's clock and animation frames run by hand; step draws when told to and notes each (dt, at) it got. */
function harness(withFrames = true) {
  const frames = handRunFrames<unknown>(ORIGIN_MS, withFrames);
  const steps: { dt: number; at: number }[] = [];
  let draws = true;
  const clock = createStageClock(frames.host, (dt, at) => {
    steps.push({ dt, at });
    return draws;
  });
  return { ...frames, clock, steps, setDraws: (d: boolean) => (draws = d) };
}

describe('createStageClock', () => {
  it("steps from the page's frame uncapped first, then by the frames' intervals capped at MAX_DT_SECONDS", () => {
    const h = harness();
    h.clock.play(ORIGIN_MS + 100);
    h.frameAt(400); // 0.3 s after the page's frame: the worker catches up at once
    h.frameAt(416);
    h.frameAt(916); // a frame 0.5 s late (a backgrounded tab) is capped
    expect(h.steps.map((s) => s.dt)).toEqual([0.3, 0.016, MAX_DT_SECONDS]);
    expect(h.steps.map((s) => s.at)).toEqual([ORIGIN_MS + 400, ORIGIN_MS + 416, ORIGIN_MS + 916]);
  });

  it('keeps the time of the last frame drawn: frames drawn late catch up on the time that passed', () => {
    const h = harness();
    h.clock.play(ORIGIN_MS);
    h.setDraws(false); // no canvas yet
    h.frameAt(50);
    h.frameAt(90);
    h.setDraws(true);
    h.frameAt(120);
    h.frameAt(136);
    // Nothing drawn before 120 ms: the first drawn step still counts from the page's frame, uncapped.
    expect(h.steps.map((s) => s.dt)).toEqual([0.05, 0.09, 0.12, 0.016]);
  });

  it('stops asking for frames at stop, and a new play starts from its own frame', () => {
    const h = harness();
    h.clock.play(ORIGIN_MS);
    h.frameAt(16);
    h.clock.stop();
    expect(h.pending.size).toBe(0);
    h.frameAt(32);
    h.clock.play(ORIGIN_MS + 1_000);
    h.frameAt(1_250);
    expect(h.steps.map((s) => s.dt)).toEqual([0.016, 0.25]);
  });

  it('tells a shown frame at the next frame, says ready once, and has no frames where workers have none', () => {
    const h = harness();
    const told: number[] = [];
    expect(h.clock.atNextFrame(() => told.push(h.clock.epochNow()))).toBe(true);
    expect(told).toEqual([]);
    h.frameAt(20);
    expect(told).toEqual([ORIGIN_MS + 20]);
    h.clock.sayReady();
    h.clock.sayReady();
    expect(h.replies).toEqual([{ type: 'ready' }]);
    expect(h.clock.readySaid()).toBe(true);
    const none = harness(false);
    none.clock.play(ORIGIN_MS);
    expect(none.pending.size).toBe(0);
    expect(none.clock.atNextFrame(() => undefined)).toBe(false);
  });
});
