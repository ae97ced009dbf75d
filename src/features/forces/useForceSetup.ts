import { useMemo } from 'react';
import type { ForceInputs, ForceSetup } from './forceModel';
import { forceSetup } from './forceModel';

/**
 * The state's forces setup in SI (forceSetup), remade only when the lengths, their unit, the coupler point, the forces or the
 * input motion change: not with each frame of Play, whose state carries a new design object (the branch it is on).
 */
export function useForceSetup(state: ForceInputs): ForceSetup {
  const { forces } = state;
  const { linkage, coupler, lengthUnit } = state.design;
  const { omega2RadPerS, alpha2RadPerS2, direction } = state.motion;
  return useMemo(
    () =>
      forceSetup({
        design: { linkage, coupler, lengthUnit },
        forces,
        motion: { omega2RadPerS, alpha2RadPerS2, direction },
      }),
    [linkage, coupler, lengthUnit, forces, omega2RadPerS, alpha2RadPerS2, direction],
  );
}
