import type { Dispatch } from 'react';
import { advanceTheta2, degreesForElapsed } from '../state/animation';
import type { InputRangeDeg } from '../state/animation';
import type { Action, AppState } from '../state/appState';
import { useAnimationFrame } from './useAnimationFrame';
import { useStableCallback } from './useStableCallback';

/** A full turn: the range used for a step before the first cycle says otherwise. */
const FULL_TURN: InputRangeDeg = { full: true, intervals: [] };

/**
 * Plays the input while state.playing (time based: speed in degrees per nominal 60 FPS frame, rocking
 * between limits when the input cannot turn fully) and returns the step handler (+1 forward, -1 back,
 * one cycle sample per step). Waits for the first cycle's input range before it moves.
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
    dispatch({ type: 'animate', ...next });
  });
  return useStableCallback((sign: 1 | -1) => {
    const next = advanceTheta2(state.theta2Deg, 360 / state.samples, sign, state.branch, rangeDeg ?? FULL_TURN);
    dispatch({ type: 'animate', theta2Deg: next.theta2Deg, branch: next.branch, direction: state.direction });
  });
}
