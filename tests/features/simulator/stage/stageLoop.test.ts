import { describe, expect, it } from 'vitest';
import type { StagePainter } from '../../../../src/features/simulator/stage/stageLoop';
import { MAX_DT_SECONDS, createStageLoop } from '../../../../src/features/simulator/stage/stageLoop';
import type { StageReply, StageRequest } from '../../../../src/features/simulator/stage/stageProtocol';
import { DEFAULT_STATE } from '../../../../src/shared/state/appState';
import type { PlayFrame } from '../../../../src/shared/state/playhead';
import { handRunFrames } from '../../../shared/linkage/handRunFrames';

/** The nominal frame rate a speed in degrees per frame refers to (60 frames a second). */
const FPS = 60;
const ORIGIN_MS = 5_000;

/** A worker's clock and animation frames run by hand, and a painter that notes what it drew. */
function harness(withFrames = true, prepare: StagePainter['prepare'] = () => Promise.resolve()) {
  const { host, replies, pending, frameAt } = handRunFrames<StageReply>(ORIGIN_MS, withFrames);
  const drawn: PlayFrame[] = [];
  const painter: StagePainter = {
    setCanvas: () => {},
    setSize: () => {},
    prepare,
    draw: (frame) => {
      drawn.push(frame);
      return 1;
    },
  };
  const send = createStageLoop(host, painter);
  return { send, frameAt, replies, drawn, pending };
}

const state: StageRequest = { type: 'state', state: DEFAULT_STATE, ghostShown: true };
const start = (theta2Deg: number, atMs: number, speedDegPerFrame = 1): StageRequest => ({
  type: 'play',
  id: 7,
  frame: { theta2Deg, direction: 1, branch: 'open' },
  atEpochMs: ORIGIN_MS + atMs,
  speedDegPerFrame,
  range: { full: true, intervals: [] },
});

describe('createStageLoop', () => {
  it('tells the page the frame it drew in each animation frame of Play, so Pause keeps the frame on screen', () => {
    const h = harness();
    h.send(state);
    h.send(start(10, 0));
    // Frame times (ms): the first step catches up with the page's clock uncapped; a long gap is capped.
    const times = [16, 33, 50, 400, 417];
    let expected = 10;
    let previous = 0;
    times.forEach((t, k) => {
      h.frameAt(t);
      const dt = k === 0 ? (t - previous) / 1000 : Math.min(MAX_DT_SECONDS, (t - previous) / 1000);
      expected = (expected + FPS * dt) % 360;
      previous = t;
      const reply = h.replies[k];
      if (reply?.type !== 'drawn') throw new Error(`no frame told at ${t} ms`);
      // The frame told is the one drawn in this animation frame, not the one before it.
      expect(reply.frame).toEqual(h.drawn[k]);
      expect(reply.frame.theta2Deg).toBeCloseTo(expected, 9);
      expect(reply.atEpochMs).toBe(ORIGIN_MS + t);
      expect(reply.id).toBe(7);
    });
    // Pause: the last frame told is the last drawn, and nothing moves on.
    h.send({ type: 'stop' });
    h.frameAt(500);
    expect(h.replies).toHaveLength(times.length);
    expect(h.drawn).toHaveLength(times.length);
    expect(h.replies.at(-1)).toMatchObject({ frame: h.drawn.at(-1) });
    expect(h.pending.size).toBe(0);
  });

  it('restarts from the frame and time the page gives, dropping its own', () => {
    const h = harness();
    h.send(state);
    h.send(start(10, 0));
    h.frameAt(16);
    h.send(start(200, 20, 2));
    h.frameAt(30);
    const last = h.replies.at(-1);
    if (last?.type !== 'drawn') throw new Error('no frame told');
    expect(last.frame.theta2Deg).toBeCloseTo(200 + 2 * FPS * 0.01, 9);
    expect(last.frame).toEqual(h.drawn.at(-1));
  });

  it('draws a dragged frame (show) at once, stops Play, and tells it in the next animation frame', () => {
    const h = harness();
    h.send(state);
    h.send(start(10, 0));
    h.frameAt(16);
    const dragged: PlayFrame = { theta2Deg: 123.45, direction: -1, branch: 'crossed' };
    h.send({ type: 'show', id: 9, frame: dragged });
    expect(h.drawn.at(-1)).toEqual(dragged);
    expect(h.replies).toHaveLength(1);
    h.frameAt(40);
    expect(h.replies).toHaveLength(2);
    expect(h.replies[1]).toMatchObject({ type: 'drawn', id: 9, frame: dragged, shownEpochMs: ORIGIN_MS + 40 });
    h.frameAt(60);
    // Play stopped: nothing more is drawn or told.
    expect(h.drawn).toHaveLength(2);
    expect(h.replies).toHaveLength(2);
  });

  it('draws nothing before the state arrives, and says so where workers have no animation frames', () => {
    const h = harness();
    h.send(start(10, 0));
    h.frameAt(16);
    expect(h.drawn).toEqual([]);
    expect(h.replies).toEqual([]);
    const none = harness(false);
    none.send({ type: 'canvas', canvas: {} as OffscreenCanvas });
    expect(none.replies).toEqual([{ type: 'unsupported' }]);
  });

  it("says 'ready' once, after the canvas and the state's language, having drawn the state's pose once", async () => {
    let loaded = () => {};
    const language = new Promise<void>((resolve) => (loaded = resolve));
    const h = harness(true, () => language);
    h.send({ type: 'canvas', canvas: {} as OffscreenCanvas });
    h.send({
      type: 'state',
      state: { ...DEFAULT_STATE, shell: { ...DEFAULT_STATE.shell, locale: 'zh-TW' } },
      ghostShown: true,
    });
    await Promise.resolve();
    // The language is still loading: not ready, nothing drawn.
    expect(h.replies).toEqual([]);
    expect(h.drawn).toEqual([]);
    loaded();
    await language;
    await Promise.resolve();
    expect(h.replies).toEqual([{ type: 'ready' }]);
    expect(h.drawn).toEqual([
      {
        theta2Deg: DEFAULT_STATE.motion.theta2Deg,
        direction: DEFAULT_STATE.motion.direction,
        branch: DEFAULT_STATE.design.branch,
      },
    ]);
    // A later state or canvas does not say it again.
    h.send(state);
    h.send({ type: 'canvas', canvas: {} as OffscreenCanvas });
    await Promise.resolve();
    await Promise.resolve();
    expect(h.replies).toEqual([{ type: 'ready' }]);
  });

  it('is not ready without a canvas, and a state that comes first waits for the canvas', async () => {
    const h = harness();
    h.send(state);
    await Promise.resolve();
    await Promise.resolve();
    expect(h.replies).toEqual([]);
    h.send({ type: 'canvas', canvas: {} as OffscreenCanvas });
    expect(h.replies).toEqual([{ type: 'ready' }]);
    const none = harness(false);
    none.send(state);
    none.send({ type: 'canvas', canvas: {} as OffscreenCanvas });
    await Promise.resolve();
    await Promise.resolve();
    expect(none.replies).toEqual([{ type: 'unsupported' }]);
  });
});
