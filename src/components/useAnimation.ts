import type { Dispatch } from 'react';
import { flushSync } from 'react-dom';
import { advanceTheta2, degreesForElapsed, stepTheta2 } from '../state/animation';
import type { InputRangeDeg } from '../state/animation';
import type { Action, AppState } from '../state/appState';
import { useAnimationFrame } from './useAnimationFrame';
import { useStableCallback } from './useStableCallback';

/**
 * Plays the input while state.playing (time based: speed in degrees per nominal 60 FPS frame, rocking
 * between limits when the input cannot turn fully) and returns the step handler: +1 one cycle sample
 * forward in the play direction (so clockwise when Clockwise is chosen), -1 one back. Play waits for the
 * first cycle's input range. Each frame's state is committed inside its animation frame (flushSync), so
 * the canvas draws that frame's pose before the browser paints, and the next frame starts from it.
 */
export function useAnimation(
  state: AppState,
  dispatch: Dispatch<Action>,
  rangeDeg: InputRangeDeg | null,
): (sign: 1 | -1) => void {
  useAnimationFrame(state.playing, (dt) => {
    if (!rangeDeg) return;
    const next = advanceTheta2(
      state.theta2Deg,
      degreesForElapsed(state.speedDegPerFrame, dt),
      state.direction,
      state.branch,
      rangeDeg,
    );
    flushSync(() => dispatch({ type: 'animate', ...next }));
  });
  return useStableCallback((sign: 1 | -1) => dispatch({ type: 'animate', ...stepTheta2(state, rangeDeg, sign) }));
}
