import { useMemo } from 'react';
import type { SceneDesign } from '../../shared/linkage/designOverlay';
import type { AppState } from '../../shared/state/appState';
import type { Messages } from '../../shared/i18n/messages';
import type { LocalPose } from '../../shared/linkage/localPose';
import type { DesignInfo } from './useDesignMetrics';
import { designScene } from './designScene';

/** designScene for the frame on screen, rebuilt only when what it shows changes (the pose only with the centres). */
export function useDesignScene(state: AppState, local: LocalPose, design: DesignInfo | null, t: Messages): SceneDesign {
  const {
    display: { showDeadCentres, showInstantCentres, muBandLoDeg, muBandHiDeg },
    design: { lengthUnit },
  } = state;
  const centres = showInstantCentres ? local : null;
  return useMemo(
    () => designScene({ showDeadCentres, muBandLoDeg, muBandHiDeg }, lengthUnit, centres, design, t),
    [showDeadCentres, muBandLoDeg, muBandHiDeg, lengthUnit, centres, design, t],
  );
}
