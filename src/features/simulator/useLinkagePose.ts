import { useMemo } from 'react';
import type { AppState } from '../../shared/state/appState';
import type { PointResponse } from '../../shared/solution';
import type { LocalPose } from '../../shared/linkage/localPose';
import { localPose, poseAsPoint } from '../../shared/linkage/localPose';

/** This render's pose, and the same pose as a point answer for the plots' marker. */
export interface LinkagePose {
  local: LocalPose;
  marker: PointResponse;
}

/**
 * The pose to draw for this render, solved on the main thread from the state (closed form, the worker's
 * formulas): the canvas and the plot markers never wait for a worker round trip. The ghost (the other
 * branch) is solved only when it is drawn.
 */
export function useLinkagePose(state: AppState, ghostShown: boolean): LinkagePose {
  const {
    design: { linkage, branch, coupler },
    motion: { theta2Deg },
    solver: { method, tol },
  } = state;
  const withGhost = ghostShown && state.display.showGhost;
  const local = useMemo(
    () => localPose(linkage, theta2Deg, branch, coupler, withGhost),
    [linkage, theta2Deg, branch, coupler, withGhost],
  );
  const marker = useMemo(() => poseAsPoint(local, { method, tol }), [local, method, tol]);
  return { local, marker };
}
