import type { Messages } from '../../../shared/i18n/messages';
import type { ForceLayer } from '../../../shared/linkage/forceVectors';
import type { LinkageScene } from '../../../shared/linkage/scene';
import { memoLast } from '../../../shared/memoLast';
import type { CycleResponse } from '../../../shared/solution';
import type { AppState } from '../../../shared/state/appState';
import type { PlayFrame } from '../../../shared/state/playhead';
import { withFrame } from '../../../shared/state/playhead';
import { designInfo } from './designScene';
import { posedState } from './framePose';
import { createSceneBuilder } from './sceneBuilder';

/** What the live stage draws from besides the frame: the committed state, the latest cycle, whether the ghost shows. */
export interface StageInputs {
  state: AppState;
  cycle: CycleResponse | null;
  ghostShown: boolean;
}

/**
 * The live stage's scene for a frame of Play: the committed state moved to the frame, posed (posedState), through the
 * page's own scene builder (createSceneBuilder), with the design facts of the committed state and the pin forces of
 * forceLayer (the worker entry passes the forces feature's). What does not change from frame to frame is kept, so
 * the background bitmap holds.
 */
export function createStageScene(
  forceLayer: ForceLayer | null = null,
): (inputs: StageInputs, frame: PlayFrame, t: Messages) => LinkageScene {
  const build = createSceneBuilder();
  const design = memoLast(designInfo);
  return (inputs, frame, t) => {
    const { cycle, ghostShown } = inputs;
    const state = withFrame(inputs.state, frame);
    const { local, motion } = posedState(state, ghostShown);
    const info = design(inputs.state.design.linkage, inputs.state.design.branch);
    return build({ state, local, motion, cycle, design: info, t, forceLayer }).scene;
  };
}
