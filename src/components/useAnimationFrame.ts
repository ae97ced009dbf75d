import { useEffect, useRef } from 'react';

/**
 * Runs onFrame(dtSeconds) on every animation frame while active: one requestAnimationFrame loop,
 * cancelled in the effect's cleanup. dt is the time since the previous frame in seconds, capped at
 * 0.1 s so a backgrounded tab does not jump on return.
 */
export function useAnimationFrame(active: boolean, onFrame: (dtSeconds: number) => void): void {
  const cb = useRef(onFrame);
  cb.current = onFrame;
  useEffect(() => {
    if (!active) return;
    let handle = 0;
    let last: number | null = null;
    const tick = (now: number) => {
      const dt = last === null ? 0 : Math.min(0.1, (now - last) / 1000);
      last = now;
      if (dt > 0) cb.current(dt);
      handle = requestAnimationFrame(tick);
    };
    handle = requestAnimationFrame(tick);
    return () => cancelAnimationFrame(handle);
  }, [active]);
}
