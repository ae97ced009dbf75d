// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { radToDeg, radToDeg360 } from '../../../solver/angles';
import type { Branch } from '../../../solver/types';
import type { SceneDesign } from '../../../shared/linkage/designOverlay';
import type { SceneVectors } from '../../../shared/linkage/motionVectors';
import type { BranchExtent, LinkageScene, ScenePose, SceneText } from '../../../shared/linkage/scene';
import type { Bounds } from '../../../shared/canvas/view';
import { sceneBounds } from '../../../shared/linkage/scene';
import type { AppState } from '../../../shared/state/appState';
import { formatDeg, formatNumber } from '../../../shared/format';
import type { Messages } from '../../../shared/i18n/messages';
import type { CycleResponse } from '../../../shared/solution';

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
