import { useState } from 'react';
import type { SynFunctionState } from '../../../shared/state/slices/synFunctionSlice';
import { useAnimationFrame } from '../../../shared/hooks/useAnimationFrame';

/** Seconds the animation takes from x0 to x1 (then it comes back). */
const SWEEP_SECONDS = 3;

/** Whether the person asked for less motion: then the linkage waits for Play. */
const reducedMotion = () =>
  typeof window !== 'undefined' && window.matchMedia?.('(prefers-reduced-motion: reduce)').matches === true;

/** The linkage moving through its range, ping-pong, with Play/Pause and an x slider (which pauses it). */
export function useSweep(s: SynFunctionState, active: boolean) {
  const [playing, setPlaying] = useState(() => !reducedMotion());
  const [phase, setPhase] = useState(0);
  useAnimationFrame(active && playing, (dt) => setPhase((u) => (u + dt / SWEEP_SECONDS) % 2));
  const [x0, x1] = s.xRange;
  const along = phase <= 1 ? phase : 2 - phase;
  return {
    playing,
    setPlaying,
    x: x0 + (x1 - x0) * along,
    setX: (x: number) => {
      setPlaying(false);
      setPhase(Math.min(1, Math.max(0, (x - x0) / (x1 - x0))));
    },
  };
}
