import { useMemo } from 'react';
// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { degToRad } from '../../solver/angles';
import type { Branch } from '../../solver/types';
import type { SceneDesign } from '../../shared/linkage/designOverlay';
import type { SceneVectors } from '../../shared/linkage/motionVectors';
import type { LinkageScene, ScenePose, SceneText } from '../../shared/linkage/scene';
import type { Bounds } from '../../shared/canvas/view';
import { frameOf } from '../../shared/canvas/view';
import { sceneBounds, sceneCurves, scenePose } from '../../shared/linkage/scene';
import type { AppState } from '../../shared/state/appState';
import type { Messages } from '../../shared/i18n/messages';
import type { CycleResponse } from '../../shared/solution';
import { sceneWarning } from '../../shared/linkage/frameScene';
import { assembleScene, cycleBounds, sceneDescription, sceneText } from './linkageScene';
import type { LocalPose } from '../../shared/linkage/localPose';

/** The scene to draw and its accessible description (the angles, or why it cannot assemble). */
export interface LinkageSceneView {
  scene: LinkageScene;
  description: string;
}

/** Bounds to fit: the cycle's (cycleBounds) once it has arrived, before that the pose itself. */
function useSceneBounds(
  cycle: CycleResponse | null,
  branch: Branch,
  showGhost: boolean,
  linkage: LocalPose['linkage'],
  pose: ScenePose | null,
  ghost: ScenePose | null,
): Bounds {
  const fromCycle = useMemo(() => (cycle ? cycleBounds(cycle, branch, showGhost) : null), [cycle, branch, showGhost]);
  const poseBounds = useMemo(() => sceneBounds(linkage, [], [], [pose, ghost]), [linkage, pose, ghost]);
  return fromCycle ?? poseBounds;
}

function useSceneText(t: Messages, warning: string | null, warningDetail: string | null, unit: string): SceneText {
  return useMemo(() => sceneText(t, warning, warningDetail, unit), [t, warning, warningDetail, unit]);
}

/**
 * Builds the canvas scene from this frame's pose (solved on the main thread) and the latest cycle: joints,
 * ghost, the coupler curves with the current circuit marked, bounds that stay put while the linkage moves
 * (from the cycle once it has arrived), the texts, the design overlay and the motion vectors when given.
 */
export function useLinkageScene(
  state: AppState,
  local: LocalPose,
  cycle: CycleResponse | null,
  t: Messages,
  design?: SceneDesign,
  vectors: SceneVectors | null = null,
): LinkageSceneView {
  const { linkage, coupler, theta2Rad, branch } = local;
  const pose = useMemo(() => scenePose(linkage, local.pose, coupler), [linkage, local.pose, coupler]);
  const ghost = useMemo(() => scenePose(linkage, local.ghost, coupler), [linkage, local.ghost, coupler]);
  const curves = useMemo(() => (cycle ? sceneCurves(cycle.curves, branch, theta2Rad) : []), [cycle, branch, theta2Rad]);
  const bounds = useSceneBounds(cycle, branch, state.display.showGhost, linkage, pose, ghost);

  const classification = cycle?.classification ?? null;
  const { warning, warningDetail } = sceneWarning(local.pose !== null, classification, theta2Rad, t);
  const text = useSceneText(t, warning, warningDetail, state.design.lengthUnit);
  const {
    display: { showGrid, showAngles, showGhost, showTrace },
  } = state;
  // A synthesised design sits where its task is (URL ox, oy, og), with the task's targets marked (tg).
  const { x: ox, y: oy, angleDeg: og } = state.design.placement;
  const placement = useMemo(() => frameOf(ox, oy, degToRad(og)), [ox, oy, og]);
  const markers = state.synPath.targets;
  const scene: LinkageScene = useMemo(
    () =>
      assembleScene({
        linkage,
        theta2: theta2Rad,
        pose,
        ghost,
        curves,
        display: { showGrid, showAngles, showGhost, showTrace },
        text,
        bounds,
        design,
        vectors,
        placement,
        markers,
      }),
    [
      linkage,
      theta2Rad,
      pose,
      ghost,
      curves,
      showGrid,
      showAngles,
      showGhost,
      showTrace,
      text,
      bounds,
      design,
      vectors,
      placement,
      markers,
    ],
  );
  return { scene, description: sceneDescription(theta2Rad, pose, warning) };
}
