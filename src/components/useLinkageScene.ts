import { useMemo } from 'react';
// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { degToRad, radToDeg, radToDeg360 } from '../solver/angles';
import type { Branch } from '../solver/types';
import type { BranchExtent, LinkageScene, SceneText } from '../render/scene';
import { sceneBounds, sceneCurves, scenePose } from '../render/scene';
import type { AppState } from '../state/appState';
import { formatDeg, formatIntervalsDeg, formatNumber } from '../state/format';
import type { Messages } from '../state/messages';
import type { CycleResponse, PointResponse } from '../worker/protocol';

/** The scene to draw and its accessible description (the angles, or why it cannot assemble). */
export interface LinkageSceneView {
  scene: LinkageScene;
  description: string;
}

/**
 * Builds the canvas scene from the state, the pose answer and the cycle: joints, ghost, the coupler curves
 * with the current circuit marked, bounds that stay put while the linkage moves, and the texts.
 */
export function useLinkageScene(
  state: AppState,
  point: PointResponse | null,
  cycle: CycleResponse | null,
  t: Messages,
): LinkageSceneView {
  // The scene is built from the point answer's own lengths, so a pose is never drawn with other lengths.
  const sceneLinkage = point ? point.linkage : state.linkage;
  const sceneCoupler = useMemo(
    () => (point ? point.coupler : { distance: state.coupler.distance, angleRad: degToRad(state.coupler.angleDeg) }),
    [point, state.coupler.distance, state.coupler.angleDeg],
  );
  const pose = useMemo(
    () => scenePose(sceneLinkage, point?.pose ?? null, sceneCoupler),
    [sceneLinkage, point, sceneCoupler],
  );
  const ghost = useMemo(
    () => scenePose(sceneLinkage, point?.ghost ?? null, sceneCoupler),
    [sceneLinkage, point, sceneCoupler],
  );
  const theta2Rad = point ? point.theta2Rad : degToRad(state.theta2Deg);
  const drawBranch: Branch = point ? point.branch : state.branch;
  const range = cycle?.classification.inputRange;
  const rocking = range ? !range.full && range.intervals.length > 0 : false;
  const curves = useMemo(
    () => (cycle ? sceneCurves(cycle.curves, drawBranch, theta2Rad) : []),
    [cycle, drawBranch, theta2Rad],
  );
  const cycleBounds = useMemo(() => {
    if (!cycle) return null;
    const other: Branch = drawBranch === 'open' ? 'crossed' : 'open';
    const ext = (b: Branch): BranchExtent => ({ theta4: cycle[b].theta4, px: cycle[b].px, py: cycle[b].py });
    const both = state.showGhost || rocking;
    return sceneBounds(cycle.linkage, both ? [ext(drawBranch), ext(other)] : [ext(drawBranch)], [], []);
  }, [cycle, drawBranch, state.showGhost, rocking]);
  // Before the first cycle arrives, fit the pose itself.
  const poseBounds = useMemo(() => sceneBounds(sceneLinkage, [], [], [pose, ghost]), [sceneLinkage, pose, ghost]);
  const bounds = cycleBounds ?? poseBounds;

  const classification = cycle?.classification ?? null;
  const theta2Text = formatDeg(radToDeg360(theta2Rad), 2);
  const warning =
    point && !point.pose
      ? classification?.type === 'cannot-assemble'
        ? t.cannotAssembleAny
        : t.cannotAssembleAt(theta2Text)
      : null;
  const warningDetail =
    warning &&
    classification &&
    classification.type !== 'cannot-assemble' &&
    classification.inputRange.intervals.length > 0
      ? t.reachableHint(formatIntervalsDeg(classification.inputRange.intervals, t.rangeInterval))
      : null;
  const text: SceneText = useMemo(
    () => ({
      ...t.jointLabels,
      warning,
      warningDetail,
      gridSpacing: t.gridSpacing,
      formatAngle: (d: number) => `${formatDeg(d, 1)}°`,
      formatLength: (x: number) => formatNumber(x, 4),
    }),
    [t, warning, warningDetail],
  );
  const { showGrid, showAngles, showGhost, showTrace } = state;
  const scene: LinkageScene = useMemo(
    () => ({
      linkage: sceneLinkage,
      theta2: theta2Rad,
      pose,
      ghost,
      curves,
      showGrid,
      showAngles,
      showGhost,
      showTrace,
      text,
      bounds,
    }),
    [sceneLinkage, theta2Rad, pose, ghost, curves, showGrid, showAngles, showGhost, showTrace, text, bounds],
  );
  const description = pose
    ? `θ2 ${theta2Text}°, θ3 ${formatDeg(radToDeg(pose.theta3), 2)}°, θ4 ${formatDeg(radToDeg(pose.theta4), 2)}°, μ ${formatDeg(radToDeg(pose.mu), 2)}°`
    : (warning ?? '');
  return { scene, description };
}
