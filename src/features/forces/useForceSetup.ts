import { useMemo } from 'react';
import type { ForceInputs, ForceSetup } from './forceModel';
import { forceSetup } from './forceModel';

/** The state's forces setup in SI (forceSetup), remade only when the design, the forces or the input motion change. */
export function useForceSetup(state: ForceInputs): ForceSetup {
  const { design, forces } = state;
  const { omega2RadPerS, alpha2RadPerS2, direction } = state.motion;
  return useMemo(
    () => forceSetup({ design, forces, motion: { omega2RadPerS, alpha2RadPerS2, direction } }),
    [design, forces, omega2RadPerS, alpha2RadPerS2, direction],
  );
}
