import { useMemo } from 'react';
// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { degToRad, radToDeg, radToDeg360 } from '../../solver/angles';
import type { Branch } from '../../solver/types';
import type { SceneDesign } from '../../shared/linkage/designOverlay';
import type { SceneVectors } from '../../shared/linkage/motionVectors';
import type { BranchExtent, LinkageScene, ScenePose, SceneText } from '../../shared/linkage/scene';
import type { Bounds } from '../../shared/canvas/view';
import { frameOf } from '../../shared/canvas/view';
import { sceneBounds, sceneCurves, scenePose } from '../../shared/linkage/scene';
import type { AppState } from '../../shared/state/appState';
import { formatDeg, formatNumber } from '../../shared/format';
import type { Messages } from '../../shared/i18n/messages';
import type { CycleResponse } from '../../shared/solution';
import { sceneWarning } from '../../shared/linkage/frameScene';
import type { LocalPose } from '../../shared/linkage/localPose';

/** The scene to draw and its accessible description (the angles, or why it cannot assemble). */
export interface LinkageSceneView {
  scene: LinkageScene;
  description: string;
}

/**
 * The cycle's bounds to fit, which stay put while the linkage moves: both branches when the ghost shows or the input
 * rocks (which switches branch), else the branch's own.
 */
export function cycleBounds(cycle: CycleResponse, branch: Branch, showGhost: boolean): Bounds {
  const range = cycle.classification.inputRange;
  const rocking = !range.full && range.intervals.length > 0;
  const other: Branch = branch === 'open' ? 'crossed' : 'open';
  const ext = (b: Branch): BranchExtent => ({ theta4: cycle[b].theta4, px: cycle[b].px, py: cycle[b].py });
  return sceneBounds(cycle.linkage, showGhost || rocking ? [ext(branch), ext(other)] : [ext(branch)], [], []);
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

/**
 * The scene's texts in the page's language: joint names, the warning, the grid's spacing and number formats (a
 * length with the app's length unit: "grid 2 mm").
 */
export function sceneText(t: Messages, warning: string | null, warningDetail: string | null, unit: string): SceneText {
  return {
    ...t.jointLabels,
    warning,
    warningDetail,
    gridSpacing: t.gridSpacing,
    formatAngle: (d: number) => `${formatDeg(d, 1)}°`,
    formatLength: (x: number) => `${formatNumber(x, 4)} ${unit}`,
  };
}

/** What a scene is made of (assembleScene): the pose's parts, the display toggles and the overlays. */
export interface SceneParts {
  linkage: LinkageScene['linkage'];
  theta2: number;
  pose: ScenePose | null;
  ghost: ScenePose | null;
  curves: LinkageScene['curves'];
  display: Pick<AppState['display'], 'showGrid' | 'showAngles' | 'showGhost' | 'showTrace'>;
  text: SceneText;
  bounds: Bounds;
  design?: SceneDesign;
  vectors: SceneVectors | null;
  placement: LinkageScene['placement'] | null;
  markers: NonNullable<LinkageScene['markers']>;
}

/** The canvas scene from its parts (placement and markers only when there are some). */
export function assembleScene(p: SceneParts): LinkageScene {
  const { showGrid, showAngles, showGhost, showTrace } = p.display;
  return {
    linkage: p.linkage,
    theta2: p.theta2,
    pose: p.pose,
    ghost: p.ghost,
    curves: p.curves,
    showGrid,
    showAngles,
    showGhost,
    showTrace,
    text: p.text,
    bounds: p.bounds,
    ...(p.design ? { design: p.design } : {}),
    vectors: p.vectors,
    ...(p.placement ? { placement: p.placement } : {}),
    ...(p.markers.length > 0 ? { markers: p.markers } : {}),
  };
}

/** The scene's accessible description: the angles, or why it cannot assemble. */
export function sceneDescription(theta2Rad: number, pose: ScenePose | null, warning: string | null): string {
  if (!pose) return warning ?? '';
  const theta2Text = formatDeg(radToDeg360(theta2Rad), 2);
  return `θ2 ${theta2Text}°, θ3 ${formatDeg(radToDeg(pose.theta3), 2)}°, θ4 ${formatDeg(radToDeg(pose.theta4), 2)}°, μ ${formatDeg(radToDeg(pose.mu), 2)}°`;
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
  const text = useSceneText(t, warning, warningDetail, state.forces.lengthUnit);
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
