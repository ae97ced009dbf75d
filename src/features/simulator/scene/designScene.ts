import { degToRad, radToDeg } from '../../../solver/angles';
// The module itself, not the solver's barrel (which would pull the sweep and NR into the main bundle).
import { instantCenters } from '../../../solver/instantCenters';
import type { SceneDesign } from '../../../shared/linkage/designOverlay';
import type { AppState } from '../../../shared/state/appState';
import type { LengthUnit } from '../../../shared/state/slices/designSlice';
import { formatDeg, formatNumber } from '../../../shared/format';
import type { Messages } from '../../../shared/i18n/messages';
import type { LocalPose } from '../../../shared/linkage/localPose';
// The solver's modules themselves, not its barrel: the barrel would pull the sweep and NR into the main bundle.
import { inputRange } from '../../../solver/classify';
import type { DesignMetrics } from '../../../solver/metrics';
import { designMetrics } from '../../../solver/metrics';
import type { Branch, InputRange, Linkage } from '../../../solver/types';

/** The design metrics of the linkage on its branch and the input's reachable range (radians). */
export interface DesignInfo {
  metrics: DesignMetrics;
  range: InputRange;
}

/** designMetrics and inputRange (closed form, microseconds); null for a linkage the solver refuses. */
export function designInfo(linkage: Linkage, branch: Branch): DesignInfo | null {
  try {
    return { metrics: designMetrics(linkage, branch), range: inputRange(linkage) };
  } catch {
    return null;
  }
}

/** The display choices the design overlay reads. */
export type DesignSceneDisplay = Pick<AppState['display'], 'showDeadCentres' | 'muBandLoDeg' | 'muBandHiDeg'>;

/** The instant centres of a pose (null without a pose, or where the solver refuses them). */
function centresOf(local: LocalPose | null) {
  if (!local?.pose) return null;
  try {
    return instantCenters(local.linkage, local.theta2Rad, local.pose);
  } catch {
    return null;
  }
}

/**
 * The canvas's design overlay: the mu band (always, for the mu label's colour), the dead centres and swing when that
 * toggle is on and the input is a crank driving a rocker, and the instant centres of `centres` (the frame's pose
 * while that toggle is on, else null; an off-screen one is labelled with its coordinates in the length unit). Pure:
 * the scene builder (sceneBuilder.ts) memoizes it for the page's canvas and the live stage's worker.
 */
export function designScene(
  display: DesignSceneDisplay,
  unit: LengthUnit,
  centres: LocalPose | null,
  design: DesignInfo | null,
  t: Messages,
): SceneDesign {
  const output = design?.metrics.output ?? null;
  return {
    muBandRad: { lo: degToRad(display.muBandLoDeg), hi: degToRad(display.muBandHiDeg) },
    deadCentres: display.showDeadCentres && output ? [output.extended, output.folded] : null,
    swingText: output ? t.swingLabel(`${formatDeg(radToDeg(output.swing), 2)}°`) : '',
    instantCentres: centresOf(centres),
    offscreenText: (name, at) =>
      at ? t.offscreenCentre(name, formatNumber(at.x, 3), formatNumber(at.y, 3), unit) : t.centreAtInfinity(name),
  };
}
