import { degToRad } from '../solver/angles';
import type { Branch } from '../solver/types';
import type { Bounds } from '../shared/canvas/view';
import { frameOf } from '../shared/canvas/view';
import type { Messages } from '../shared/i18n/messages';
import { sceneWarning } from '../shared/linkage/frameScene';
import type { LinkageScene } from '../shared/linkage/scene';
import { sceneBounds, sceneCurves, scenePose } from '../shared/linkage/scene';
import type { AppState } from '../shared/state/appState';
import type { PlayFrame } from '../shared/state/playhead';
import { withFrame } from '../shared/state/playhead';
import type { CycleResponse } from '../shared/solution';
import { createForceLayer } from '../features/forces/forceLayer';
import type { DesignInfo } from '../features/simulator/designScene';
import { designInfo, designScene } from '../features/simulator/designScene';
import { posedState } from '../features/simulator/framePose';
import { assembleScene, cycleBounds, sceneText } from '../features/simulator/linkageScene';
import { sceneVectors, vectorScales, vectorText } from '../features/simulator/sceneVectors';

/** What the live stage draws from besides the frame: the committed state, the latest cycle, whether the ghost shows. */
export interface StageInputs {
  state: AppState;
  cycle: CycleResponse | null;
  ghostShown: boolean;
}

/** What stays put from frame to frame for the same inputs and language. */
interface Prepared {
  inputs: StageInputs;
  t: Messages;
  design: DesignInfo | null;
  placement: ReturnType<typeof frameOf>;
  vectorText: ReturnType<typeof vectorText>;
  scales: ReturnType<typeof vectorScales>;
  /** The cycle's bounds per branch (a rocking input switches branch; its bounds hold both). */
  bounds: Partial<Record<Branch, Bounds>>;
}

function prepare(inputs: StageInputs, t: Messages): Prepared {
  const { state } = inputs;
  const { x, y, angleDeg } = state.design.placement;
  const { omega2RadPerS: w, alpha2RadPerS2: a } = state.motion;
  return {
    inputs,
    t,
    design: designInfo(state.design.linkage, state.design.branch),
    placement: frameOf(x, y, degToRad(angleDeg)),
    vectorText: vectorText(t, state.design.lengthUnit),
    scales: vectorScales(state.design.linkage.r2, w, a),
    bounds: {},
  };
}

/**
 * The scene builder of the live stage's worker: for inputs, a frame of Play and the page's messages, the scene the
 * page's canvas would draw for that frame (LinkageStage: the pose, ghost, coupler curves, design overlay, motion
 * vectors and pin forces), from the same pure functions its hooks memoize. What does not change from frame to frame
 * (the design metrics, the placement, the arrows' scales and texts, the cycle's bounds, the forces' setup) is kept
 * while the inputs are the same object, so the background bitmap holds (sameBackground compares by identity).
 */
export function createStageScene(): (inputs: StageInputs, frame: PlayFrame, t: Messages) => LinkageScene {
  const forceLayer = createForceLayer();
  let kept: Prepared | null = null;
  return (inputs, frame, t) => {
    if (!kept || kept.inputs !== inputs || kept.t !== t) kept = prepare(inputs, t);
    const p = kept;
    const { cycle, ghostShown } = inputs;
    const state = withFrame(inputs.state, frame);
    const { linkage, branch } = state.design;
    const { display } = state;
    const { local, motion } = posedState(state, ghostShown);
    const pose = scenePose(linkage, local.pose, local.coupler);
    const ghost = scenePose(linkage, local.ghost, local.coupler);
    let bounds = cycle ? p.bounds[branch] : undefined;
    if (cycle && !bounds) bounds = p.bounds[branch] = cycleBounds(cycle, branch, display.showGhost);
    const { warning, warningDetail } = sceneWarning(
      local.pose !== null,
      cycle?.classification ?? null,
      local.theta2Rad,
      t,
    );
    const scene = assembleScene({
      linkage,
      theta2: local.theta2Rad,
      pose,
      ghost,
      curves: cycle ? sceneCurves(cycle.curves, branch, local.theta2Rad) : [],
      display,
      text: sceneText(t, warning, warningDetail, state.design.lengthUnit),
      bounds: bounds ?? sceneBounds(linkage, [], [], [pose, ghost]),
      design: designScene(display, state.design.lengthUnit, display.showInstantCentres ? local : null, p.design, t),
      vectors: sceneVectors(display, p.scales, motion, p.vectorText),
      placement: p.placement,
      markers: state.synPath.targets,
    });
    const forces = forceLayer(state, local);
    return forces ? { ...scene, forces } : scene;
  };
}
