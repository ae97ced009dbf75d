import { useMemo } from 'react';
import type { InputRangeDeg } from '../state/animation';
import { isRocking, rangeToDeg } from '../state/animation';
import type { CycleResponse } from '../worker/protocol';
import type { CycleDegrees } from './chartInputs';
import { cycleDegrees } from './chartInputs';

/** What the views read off a solved cycle: the angles in degrees, the input range in degrees, whether it rocks. */
export interface CycleFacts {
  deg: CycleDegrees | null;
  rangeDeg: InputRangeDeg | null;
  /** The input cannot turn fully but can move: the animation rocks between limits. */
  rocking: boolean;
}

/** The cycle's degrees, input range and rocking flag, recomputed only when a new cycle arrives. */
export function useCycleFacts(cycle: CycleResponse | null): CycleFacts {
  const deg = useMemo(() => (cycle ? cycleDegrees(cycle) : null), [cycle]);
  const rangeDeg = useMemo(() => (cycle ? rangeToDeg(cycle.classification.inputRange) : null), [cycle]);
  const rocking = cycle ? isRocking(cycle.classification.inputRange) : false;
  return { deg, rangeDeg, rocking };
}
