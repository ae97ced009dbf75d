import { useMemo } from 'react';
import type { AppState } from '../../shared/state/appState';
import { effectiveInputMotion } from '../../shared/state/inputMotion';
import type { FrameMotion } from '../../shared/linkage/frameMotion';
import { frameMotion } from '../../shared/linkage/frameMotion';
import type { LocalPose } from '../../shared/linkage/localPose';

/**
 * This frame's velocities and accelerations (main thread, from the frame's own pose), for the input motion
 * the state sets with ω2 signed by the animation direction; null when there is no pose.
 */
export function useFrameMotion(state: AppState, local: LocalPose): FrameMotion | null {
  const {
    motion: { omega2RadPerS, alpha2RadPerS2, direction },
  } = state;
  const input = useMemo(
    () => effectiveInputMotion(omega2RadPerS, alpha2RadPerS2, direction),
    [omega2RadPerS, alpha2RadPerS2, direction],
  );
  return useMemo(() => frameMotion(local, input), [local, input]);
}
