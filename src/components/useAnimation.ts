import type { Dispatch } from 'react';
import { flushSync } from 'react-dom';
import { advanceTheta2, degreesForElapsed } from '../state/animation';
import type { InputRangeDeg } from '../state/animation';
import type { Action, AppState, Direction } from '../state/appState';
import { useAnimationFrame } from './useAnimationFrame';
import { useStableCallback } from './useStableCallback';

/** A full turn: the range used for a step before the first cycle says otherwise. */
const FULL_TURN: InputRangeDeg = { full: true, intervals: [] };

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
  // TODO(integrator): use stepTheta2 from src/state/animation.ts once it lands; this is sign * direction inline.
  return useStableCallback((sign: 1 | -1) => {
    const moving = (sign * state.direction) as Direction;
    const next = advanceTheta2(state.theta2Deg, 360 / state.samples, moving, state.branch, rangeDeg ?? FULL_TURN);
    // A step that reflects at a limit turns the play direction too, as Play would.
    const direction = (sign * next.direction) as Direction;
    dispatch({ type: 'animate', theta2Deg: next.theta2Deg, branch: next.branch, direction });
  });
}
