import { useMemo } from 'react';
import type { AppState } from '../state/appState';
import { effectiveInputMotion } from '../state/inputMotion';
import type { FrameMotion } from './frameMotion';
import { frameMotion } from './frameMotion';
import type { LocalPose } from './localPose';

/**
 * This frame's velocities and accelerations (main thread, from the frame's own pose), for the input motion
 * the state sets with ω2 signed by the animation direction; null when there is no pose.
 */
export function useFrameMotion(state: AppState, local: LocalPose): FrameMotion | null {
  const { omega2RadPerS, alpha2RadPerS2, direction } = state;
  const input = useMemo(
    () => effectiveInputMotion(omega2RadPerS, alpha2RadPerS2, direction),
    [omega2RadPerS, alpha2RadPerS2, direction],
  );
  return useMemo(() => frameMotion(local, input), [local, input]);
}
