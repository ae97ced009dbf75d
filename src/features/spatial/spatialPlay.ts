import { normalizeTheta2Deg } from '../../shared/state/appState';
import type { SpatialBranchName } from '../../shared/state/slices/spatialSlice';
import type { SpatialModel, SpatialPose } from '../../spatial';
import type { SpatialInput } from './useSpatialAnalysis';
import { poseAt } from './useSpatialAnalysis';

/** Play's speed, degrees of θ2 per second. */
export const PLAY_DEG_PER_S = 90;

/** Where Play is: θ2 (degrees), the branch, and the way θ2 runs (+1 up, −1 down). */
export interface PlayState {
  theta2Deg: number;
  branch: SpatialBranchName;
  direction: 1 | -1;
}

/** Play one step on: the next state, its pose (null only where neither branch closes), and whether it turned. */
export interface PlayStep extends PlayState {
  pose: SpatialPose | null;
  /** True at the input's limit: θ2 kept, the branch and the direction swapped (the app state takes the new branch). */
  turned: boolean;
}

/**
 * Play's step over dtS seconds (PLAY_DEG_PER_S): θ2 moves on in its direction; where the loop cannot close there (an
 * input's limit) a real linkage goes back on the other branch, the two meeting there, so θ2 stays and the branch and
 * direction swap. One function for the page's Play and the 3D view worker's, so both move alike. Throws on a dtS that is
 * not a finite number ≥ 0.
 */
export function playStep(model: SpatialModel, input: SpatialInput, from: PlayState, dtS: number): PlayStep {
  if (!(Number.isFinite(dtS) && dtS >= 0)) throw new Error(`dtS must be a finite number >= 0, got ${dtS}`);
  const theta2Deg = normalizeTheta2Deg(from.theta2Deg + from.direction * PLAY_DEG_PER_S * dtS);
  const pose = poseAt(model, theta2Deg, from.branch, input);
  if (pose !== null) return { theta2Deg, branch: from.branch, direction: from.direction, pose, turned: false };
  const branch: SpatialBranchName = from.branch === 'open' ? 'crossed' : 'open';
  const direction = from.direction === 1 ? -1 : 1;
  return {
    theta2Deg: from.theta2Deg,
    branch,
    direction,
    pose: poseAt(model, from.theta2Deg, branch, input),
    turned: true,
  };
}
