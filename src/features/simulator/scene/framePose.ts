import type { AppState } from '../../../shared/state/appState';
import { effectiveInputMotion } from '../../../shared/state/inputMotion';
import type { FrameMotion } from '../../../shared/linkage/frameMotion';
import { frameMotion } from '../../../shared/linkage/frameMotion';
import type { LocalPose } from '../../../shared/linkage/localPose';
import { localPose } from '../../../shared/linkage/localPose';

/**
 * A state's pose (closed form; the ghost when it is shown and on) and its velocities and accelerations for the input
 * motion the state sets, ω2 signed by the direction; pure, in one go: the live stage's worker poses every frame with
 * it, and the page's canvas the committed state under the stage. A FramePoser (framePoser.ts) and the hooks
 * (useLinkagePose, useFrameMotion) keep the same pieces one by one.
 */
export function posedState(state: AppState, ghostShown: boolean): { local: LocalPose; motion: FrameMotion | null } {
  const { linkage, branch, coupler } = state.design;
  const { theta2Deg, omega2RadPerS, alpha2RadPerS2, direction } = state.motion;
  const local = localPose(linkage, theta2Deg, branch, coupler, ghostShown && state.display.showGhost);
  return { local, motion: frameMotion(local, effectiveInputMotion(omega2RadPerS, alpha2RadPerS2, direction)) };
}
