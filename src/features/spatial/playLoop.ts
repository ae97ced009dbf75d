import { MAX_DT_SECONDS } from '../../shared/linkage/stageClock';

/** The animation-frame calls a loop runs on (a window's, or a dedicated worker's with an OffscreenCanvas). */
export interface AnimationFrames {
  request(callback: (nowMs: number) => void): number;
  cancel(handle: number): void;
}

/** Longest step passed on, seconds: a throttled or hidden worker does not jump on return (the stages' cap). */
export const MAX_PLAY_DT_S = MAX_DT_SECONDS;

/**
 * Runs onFrame(dtS, nowMs) on every animation frame from the second on (dt since the previous frame in seconds, capped
 * at MAX_PLAY_DT_S; frames with dt 0 skipped) until the returned stop is called. The next frame is asked for after
 * onFrame, so a frame onFrame asks for (the 3D view's render after a new pose) runs first in the next animation frame,
 * before the next onFrame: the view draws on every animation frame. Asked for first, the next onFrame would run before
 * that render and a pose set there would find a render pending, so the view drew every other frame (30 frames/s at most
 * at 60 Hz: issue 32's Play, session 28).
 */
export function startPlayLoop(frames: AnimationFrames, onFrame: (dtS: number, nowMs: number) => void): () => void {
  let handle = 0;
  let last: number | null = null;
  let stopped = false;
  const tick = (now: number) => {
    const dt = last === null ? 0 : Math.min(MAX_PLAY_DT_S, (now - last) / 1000);
    last = now;
    try {
      if (dt > 0) onFrame(dt, now);
    } finally {
      if (!stopped) handle = frames.request(tick);
    }
  };
  handle = frames.request(tick);
  return () => {
    stopped = true;
    frames.cancel(handle);
  };
}
