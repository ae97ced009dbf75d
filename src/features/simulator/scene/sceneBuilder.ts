// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { degToRad } from '../../../solver/angles';
import type { Branch } from '../../../solver/types';
import type { Bounds } from '../../../shared/canvas/view';
import { placementTransform } from '../../../shared/canvas/view';
import type { Messages } from '../../../shared/i18n/messages';
import type { ForceLayer } from '../../../shared/linkage/forceVectors';
import type { FrameMotion } from '../../../shared/linkage/frameMotion';
import { sceneWarning } from '../../../shared/linkage/frameScene';
import type { LocalPose } from '../../../shared/linkage/localPose';
import type { LinkageScene } from '../../../shared/linkage/scene';
import { sceneBounds, sceneCurves, scenePose } from '../../../shared/linkage/scene';
import { memoLast } from '../../../shared/memoLast';
import type { CycleResponse } from '../../../shared/solution';
import type { AppState } from '../../../shared/state/appState';
import type { DesignInfo } from './designScene';
import { designScene } from './designScene';
import { assembleScene, cycleBounds, sceneDescription, sceneText } from './linkageScene';
import { sceneVectors, vectorScales, vectorText } from './sceneVectors';

/** What a frame's scene is built from: the frame's state and pose, the latest cycle, the design facts, the texts. */
export interface SceneInputs {
  /** The state of the frame drawn (its θ2, branch and direction). */
  state: AppState;
  /** The frame's pose (closed form) and its velocities and accelerations (null where it cannot assemble). */
  local: LocalPose;
  motion: FrameMotion | null;
  cycle: CycleResponse | null;
  design: DesignInfo | null;
  t: Messages;
  /** Pin forces to draw for the frame (the app feeds the forces feature's layer); default none. */
  forceLayer?: ForceLayer | null;
}

/** The scene to draw and its accessible description (the angles, or why it cannot assemble). */
export interface BuiltScene {
  scene: LinkageScene;
  description: string;
}

/** A scene builder: inputs to the scene, each part rebuilt only when what it reads changes. */
export type SceneBuilder = (inputs: SceneInputs) => BuiltScene;

/**
 * The one scene pipeline of the simulator's canvas, used by the page (LinkageStage) and the live stage's worker
 * (createStageScene): the pose and ghost, the coupler curves with the current circuit marked, bounds that stay put
 * while the linkage moves (the cycle's, kept per branch: a rocking input switches branch; before the cycle, the
 * pose's), the texts, the design overlay, the motion vectors and the pin forces. Each part is memoized on what it
 * reads (memoLast), so an unchanged part is the same object from frame to frame and the background bitmap holds
 * (sameBackground compares by identity). Pure: no React, no DOM.
 */
export function createSceneBuilder(): SceneBuilder {
  const pose = memoLast(scenePose);
  const ghost = memoLast(scenePose);
  const curves = memoLast((cycle: CycleResponse | null, branch: Branch, theta2Rad: number) =>
    cycle ? sceneCurves(cycle.curves, branch, theta2Rad) : [],
  );
  const boundsByBranch = memoLast(
    (_cycle: CycleResponse | null, _showGhost: boolean): Partial<Record<Branch, Bounds>> => ({}),
  );
  const poseBounds = memoLast((l: LocalPose['linkage'], p: LinkageScene['pose'], g: LinkageScene['ghost']) =>
    sceneBounds(l, [], [], [p, g]),
  );
  const text = memoLast(sceneText);
  const placement = memoLast((x: number, y: number, angleDeg: number) => placementTransform(x, y, degToRad(angleDeg)));
  const design = memoLast(
    (
      showDeadCentres: boolean,
      muBandLoDeg: number,
      muBandHiDeg: number,
      unit: AppState['design']['lengthUnit'],
      centres: LocalPose | null,
      info: DesignInfo | null,
      t: Messages,
    ) => designScene({ showDeadCentres, muBandLoDeg, muBandHiDeg }, unit, centres, info, t),
  );
  const scales = memoLast(vectorScales);
  const arrowText = memoLast(vectorText);
  const vectors = memoLast(
    (
      showVelocity: boolean,
      showAcceleration: boolean,
      s: ReturnType<typeof vectorScales>,
      motion: FrameMotion | null,
      vt: ReturnType<typeof vectorText>,
    ) => sceneVectors({ showVelocity, showAcceleration }, s, motion, vt),
  );
  const kinematic = memoLast(
    (
      linkage: LinkageScene['linkage'],
      theta2: number,
      p: LinkageScene['pose'],
      g: LinkageScene['ghost'],
      c: LinkageScene['curves'],
      showGrid: boolean,
      showAngles: boolean,
      showGhost: boolean,
      showTrace: boolean,
      tx: LinkageScene['text'],
      bounds: Bounds,
      d: ReturnType<typeof designScene>,
      v: ReturnType<typeof sceneVectors>,
      at: LinkageScene['placement'],
      markers: NonNullable<LinkageScene['markers']>,
    ) =>
      assembleScene({
        linkage,
        theta2,
        pose: p,
        ghost: g,
        curves: c,
        display: { showGrid, showAngles, showGhost, showTrace },
        text: tx,
        bounds,
        design: d,
        vectors: v,
        placement: at,
        markers,
      }),
  );
  const forces = memoLast(
    (layer: ForceLayer | null, state: AppState, local: LocalPose) => layer?.(state, local) ?? null,
  );
  const withForces = memoLast((scene: LinkageScene, f: ReturnType<ForceLayer>) =>
    f ? { ...scene, forces: f } : scene,
  );

  return ({ state, local, motion, cycle, design: info, t, forceLayer = null }) => {
    const { linkage, coupler, theta2Rad, branch } = local;
    const { display } = state;
    const unit = state.design.lengthUnit;
    const p = pose(linkage, local.pose, coupler);
    const g = ghost(linkage, local.ghost, coupler);
    const kept = cycle ? boundsByBranch(cycle, display.showGhost) : null;
    const bounds =
      cycle && kept ? (kept[branch] ??= cycleBounds(cycle, branch, display.showGhost)) : poseBounds(linkage, p, g);
    const { warning, warningDetail } = sceneWarning(local.pose !== null, cycle?.classification ?? null, theta2Rad, t);
    // A synthesised design sits where its task is (URL ox, oy, og), with the task's targets marked (tg).
    const { x, y, angleDeg } = state.design.placement;
    const { omega2RadPerS: w, alpha2RadPerS2: a } = state.motion;
    const scene = kinematic(
      linkage,
      theta2Rad,
      p,
      g,
      curves(cycle, branch, theta2Rad),
      display.showGrid,
      display.showAngles,
      display.showGhost,
      display.showTrace,
      text(t, warning, warningDetail, unit),
      bounds,
      design(
        display.showDeadCentres,
        display.muBandLoDeg,
        display.muBandHiDeg,
        unit,
        display.showInstantCentres ? local : null,
        info,
        t,
      ),
      vectors(
        display.showVelocity,
        display.showAcceleration,
        scales(state.design.linkage.r2, w, a),
        motion,
        arrowText(t, unit),
      ),
      placement(x, y, angleDeg),
      state.synPath.targets,
    );
    return {
      scene: withForces(scene, forces(forceLayer, state, local)),
      description: sceneDescription(theta2Rad, p, warning),
    };
  };
}
