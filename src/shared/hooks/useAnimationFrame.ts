import { useEffect, useEffectEvent } from 'react';
import { MAX_DT_SECONDS } from '../linkage/stageClock';

/**
 * Runs onFrame(dtSeconds, nowMs) on every animation frame while active: one requestAnimationFrame loop, cancelled
 * in the effect's cleanup. dt is the time since the previous frame in seconds, capped at 0.1 s, now the frame's timestamp (ms); onFrame is
 * an effect event, so it always sees the latest render's values without restarting the loop.
 */
export function useAnimationFrame(active: boolean, onFrame: (dtSeconds: number, nowMs: number) => void): void {
  const frame = useEffectEvent(onFrame);
  useEffect(() => {
    if (!active) return;
    let handle = 0;
    let last: number | null = null;
    const tick = (now: number) => {
      const dt = last === null ? 0 : Math.min(MAX_DT_SECONDS, (now - last) / 1000);
      last = now;
      if (dt > 0) frame(dt, now);
      handle = requestAnimationFrame(tick);
    };
    handle = requestAnimationFrame(tick);
    return () => cancelAnimationFrame(handle);
  }, [active]);
}
