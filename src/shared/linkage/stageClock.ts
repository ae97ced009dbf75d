import type { StageFrameHost } from './liveStage';

/** Longest frame step, seconds, for the page's loop (useAnimationFrame) and the workers' (stages, the 3D view): a backgrounded tab does not jump on return. */
export const MAX_DT_SECONDS = 0.1;

/**
 * The part every stage worker's loop shares (the simulator's stageLoop.ts, the Mechanisms page's mechStageLoop.ts):
 * Play's clock in the worker's animation frames, a shown frame told at the next frame, and the one 'ready'.
 */
export interface StageClock {
  /** The worker's clock as epoch ms (timeOrigin + now), the time base the page and the worker share. */
  epochNow(now?: number): number;
  /**
   * Plays from atEpochMs, the time of the page's frame it starts from: step(dt, at) runs in every animation frame
   * with the seconds since the last frame it drew (the first step from the page's frame uncapped, so the worker
   * catches up with the page's clock; later ones capped at MAX_DT_SECONDS) and returns whether it drew. A step
   * that drew nothing (no canvas yet) leaves the time where it was.
   */
  play(atEpochMs: number): void;
  /** Stops Play's frames. */
  stop(): void;
  /** Runs told at the start of the next animation frame (a shown frame is on screen then); false where there are none. */
  atNextFrame(told: () => void): boolean;
  /** Says 'ready' to the page once (whatever asks again): the stage has drawn once, unseen. */
  sayReady(): void;
  /** Whether 'ready' was said. */
  readySaid(): boolean;
}

/** A stage loop's clock on host: step(dtSeconds, atEpochMs) advances and draws one frame of Play (StageClock.play). */
export function createStageClock<R>(
  host: StageFrameHost<R | { type: 'ready' }>,
  step: (dtSeconds: number, atEpochMs: number) => boolean,
): StageClock {
  let handle = 0;
  let from: { atEpochMs: number; first: boolean } | null = null;
  let ready = false;
  const epochNow = (now = host.now()) => host.timeOrigin + now;
  const stop = () => {
    from = null;
    if (handle) host.cancelFrame(handle);
    handle = 0;
  };
  function tick(now: number) {
    handle = 0;
    const f = from;
    if (!f || !host.requestFrame) return;
    const at = epochNow(now);
    const elapsed = Math.max(0, (at - f.atEpochMs) / 1000);
    if (step(f.first ? elapsed : Math.min(MAX_DT_SECONDS, elapsed), at)) from = { atEpochMs: at, first: false };
    // A step can stop Play (the page's stop comes as a message, so not today); only a running Play asks again.
    if (from) handle = host.requestFrame(tick);
  }
  return {
    epochNow,
    play(atEpochMs) {
      from = { atEpochMs, first: true };
      if (!handle && host.requestFrame) handle = host.requestFrame(tick);
    },
    stop,
    atNextFrame(told) {
      if (!host.requestFrame) return false;
      host.requestFrame(() => told());
      return true;
    },
    sayReady() {
      if (ready) return;
      ready = true;
      host.reply({ type: 'ready' });
    },
    readySaid: () => ready,
  };
}
