import { radToDeg, radToDeg360 } from '../../solver/angles';
import type { Branch } from '../../solver/types';
import type { LinkageScene } from './scene';
import { sceneCurves, scenePose } from './scene';
import type { CouplerPoint } from '../state/appState';
import { formatDeg } from '../format';
import { formatInputRange } from '../state/inputRange';
import type { Messages } from '../i18n/messages';
import type { Classification } from '../../solver/types';
import type { CouplerCurve } from '../solution';
import { localPose } from './localPose';

/** The canvas's message when the linkage cannot be drawn assembled, and a hint where it can be; both null when assembled. */
export interface SceneWarning {
  warning: string | null;
  warningDetail: string | null;
}

/**
 * What the canvas says about a pose: nothing when it assembled (hasPose), else that it cannot assemble at all
 * or not at theta2Rad, with the reachable input range as a hint when there is one.
 */
export function sceneWarning(
  hasPose: boolean,
  classification: Classification | null,
  theta2Rad: number,
  t: Messages,
): SceneWarning {
  if (hasPose) return { warning: null, warningDetail: null };
  const warning =
    classification?.type === 'cannot-assemble'
      ? t.cannotAssembleAny
      : t.cannotAssembleAt(formatDeg(radToDeg360(theta2Rad), 2));
  const warningDetail =
    classification && classification.type !== 'cannot-assemble' && classification.inputRange.intervals.length > 0
      ? t.reachableHint(formatInputRange(classification.inputRange, t))
      : null;
  return { warning, warningDetail };
}

/** What sceneAtFrame needs besides the frame: the scene on screen, the coupler point, the cycle's curves and strings. */
export interface FrameSceneSource {
  /** The scene on screen: its toggles, texts and (stable) bounds are kept. */
  base: LinkageScene;
  coupler: CouplerPoint;
  curves: readonly CouplerCurve[];
  classification: Classification | null;
  t: Messages;
}

/**
 * The scene the canvas would draw with the input at theta2Rad on branch (radians): the closed-form pose, the
 * ghost when it is shown, the circuit marked current and the warning, with the base scene's toggles, texts
 * and bounds, so every frame of an exported animation is the screen's picture at that angle.
 */
export function sceneAtFrame(src: FrameSceneSource, theta2Rad: number, branch: Branch): LinkageScene {
  const { base } = src;
  const local = localPose(base.linkage, radToDeg(theta2Rad), branch, src.coupler, base.showGhost);
  const pose = scenePose(base.linkage, local.pose, local.coupler);
  const ghost = scenePose(base.linkage, local.ghost, local.coupler);
  const w = sceneWarning(local.pose !== null, src.classification, theta2Rad, src.t);
  return {
    ...base,
    theta2: theta2Rad,
    pose,
    ghost,
    curves: sceneCurves(src.curves, branch, theta2Rad),
    text: { ...base.text, ...w },
  };
}
