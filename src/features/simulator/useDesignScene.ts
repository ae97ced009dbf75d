import { useMemo } from 'react';
import { degToRad, radToDeg } from '../../solver/angles';
// The module itself, not the solver's barrel (which would pull the sweep and NR into the main bundle).
import { instantCenters } from '../../solver/instantCenters';
import type { SceneDesign } from '../../shared/linkage/designOverlay';
import type { AppState } from '../../shared/state/appState';
import { formatDeg, formatNumber } from '../../shared/format';
import type { Messages } from '../../shared/i18n/messages';
import type { LocalPose } from '../../shared/linkage/localPose';
import type { DesignInfo } from './useDesignMetrics';

/**
 * The canvas's design overlay for this frame: the mu band (always, for the mu label's colour), the dead
 * centres and swing when that toggle is on and the input is a crank driving a rocker, and this pose's
 * instant centres when that toggle is on (an off-screen one labelled with its coordinates in the length unit).
 */
export function useDesignScene(state: AppState, local: LocalPose, design: DesignInfo | null, t: Messages): SceneDesign {
  const {
    display: { showDeadCentres, showInstantCentres, muBandLoDeg, muBandHiDeg },
  } = state;
  const output = design?.metrics.output ?? null;
  const dead = useMemo(
    () => (showDeadCentres && output ? [output.extended, output.folded] : null),
    [showDeadCentres, output],
  );
  const { linkage, theta2Rad, pose } = local;
  const centres = useMemo(() => {
    if (!showInstantCentres || !pose) return null;
    try {
      return instantCenters(linkage, theta2Rad, pose);
    } catch {
      return null;
    }
  }, [showInstantCentres, linkage, theta2Rad, pose]);
  const swingText = output ? t.swingLabel(`${formatDeg(radToDeg(output.swing), 2)}°`) : '';
  const unit = state.forces.lengthUnit;
  return useMemo(
    () => ({
      muBandRad: { lo: degToRad(muBandLoDeg), hi: degToRad(muBandHiDeg) },
      deadCentres: dead,
      swingText,
      instantCentres: centres,
      offscreenText: (name, at) =>
        at ? t.offscreenCentre(name, formatNumber(at.x, 3), formatNumber(at.y, 3), unit) : t.centreAtInfinity(name),
    }),
    [muBandLoDeg, muBandHiDeg, dead, swingText, centres, t, unit],
  );
}
