import { createContext, useContext } from 'react';
import type { AppState } from '../state/appState';
import type { PointResponse } from '../solution';
import type { FrameMotion } from './frameMotion';
import type { LocalPose } from './localPose';

/** The frame on screen: the state with Play's frame applied, its pose (main thread), the plots' marker and its motion. */
export interface FramePose {
  state: AppState;
  local: LocalPose;
  marker: PointResponse;
  /** Velocities and accelerations at the pose; null where it does not assemble. */
  motion: FrameMotion | null;
  /** The committed state (the frame's fields as the app state holds them, behind Play's playhead). */
  committed: AppState;
  /** The other branch's pose is drawn (the canvas is on screen and the ghost is on). */
  ghostShown: boolean;
}

/** The frame on screen; null outside a FramePoseProvider. */
export const FramePoseContext = createContext<FramePose | null>(null);

/** The frame on screen (the views that follow every frame of Play read it). Throws outside a FramePoseProvider. */
export function useFramePose(): FramePose {
  const frame = useContext(FramePoseContext);
  if (!frame) throw new Error('useFramePose needs a FramePoseProvider above it');
  return frame;
}
