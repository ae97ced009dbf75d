import type { AppState } from '../../shared/state/appState';
import { effectiveInputMotion } from '../../shared/state/inputMotion';
import { frameMotion } from '../../shared/linkage/frameMotion';
import { localPose, poseAsPoint } from '../../shared/linkage/localPose';
import type { FramePose } from '../../shared/linkage/FramePoseContext';
import type { PlayFrame } from '../../shared/state/playhead';
import { sameFrame, withFrame } from '../../shared/state/playhead';

/** Solves the frame on screen: the committed state with Play's frame applied, for a FramePoseProvider. */
export type FramePoser = (state: AppState, frame: PlayFrame | null, ghostShown: boolean) => FramePose;

/**
 * A FramePoser that remembers its last answer: the same state, frame (by value) and ghost give the same object, and
 * a new state keeps the last pose (and its point and rates) where the pose's own inputs did not change, as the
 * views' memos expect.
 */
export function createFramePoser(): FramePoser {
  let last: { state: AppState; frame: PlayFrame | null; ghostShown: boolean; value: FramePose } | null = null;
  return (state, frame, ghostShown) => {
    if (last && last.state === state && last.ghostShown === ghostShown && sameOrNone(last.frame, frame)) {
      return last.value;
    }
    const shown = withFrame(state, frame);
    const value = poseOf(shown, state, ghostShown, last?.value ?? null);
    last = { state, frame, ghostShown, value };
    return value;
  };
}

function sameOrNone(a: PlayFrame | null, b: PlayFrame | null): boolean {
  return a === null || b === null ? a === b : sameFrame(a, b);
}

/** The frame of `shown`, reusing the previous frame's pose, point and rates where their inputs are the same. */
function poseOf(shown: AppState, committed: AppState, ghostShown: boolean, before: FramePose | null): FramePose {
  const { linkage, branch, coupler } = shown.design;
  const { theta2Deg, omega2RadPerS, alpha2RadPerS2, direction } = shown.motion;
  const { method, tol } = shown.solver;
  const withGhost = ghostShown && shown.display.showGhost;
  const old = before?.state;
  const samePose =
    old !== undefined &&
    old.design.linkage === linkage &&
    old.design.branch === branch &&
    old.design.coupler === coupler &&
    old.motion.theta2Deg === theta2Deg &&
    before?.ghostShown === ghostShown &&
    old.display.showGhost === shown.display.showGhost;
  const local = samePose && before ? before.local : localPose(linkage, theta2Deg, branch, coupler, withGhost);
  const sameSolver = samePose && old.solver.method === method && old.solver.tol === tol;
  const marker = sameSolver && before ? before.marker : poseAsPoint(local, { method, tol });
  const sameInput =
    samePose &&
    old.motion.omega2RadPerS === omega2RadPerS &&
    old.motion.alpha2RadPerS2 === alpha2RadPerS2 &&
    old.motion.direction === direction;
  const motion =
    sameInput && before
      ? before.motion
      : frameMotion(local, effectiveInputMotion(omega2RadPerS, alpha2RadPerS2, direction));
  return { state: shown, local, marker, motion, committed, ghostShown };
}
