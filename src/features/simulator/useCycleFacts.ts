import { useMemo } from 'react';
import type { InputRangeDeg } from '../../shared/state/animation';
import type { Direction } from '../../shared/state/appState';
import { isRocking, rangeToDeg } from '../../shared/state/animation';
import type { CycleResponse } from '../../shared/solution';
import type { CycleDegrees } from '../../shared/charts/chartInputs';
import { cycleDegrees, plotDegrees } from '../../shared/charts/chartInputs';
import type { CycleRates } from '../../shared/charts/rateInputs';
import { plotRates } from '../../shared/charts/rateInputs';
import type { SolvedPlot } from './usePlotSeries';

/** What the views read off a solved cycle: the angles in degrees, the input range in degrees, whether it rocks. */
export interface CycleFacts {
  deg: CycleDegrees | null;
  /** The plotted rates for the direction the input turns; null when no rate plot is solved. */
  rates: CycleRates | null;
  rangeDeg: InputRangeDeg | null;
  /** The input cannot turn fully but can move: the animation rocks between limits. */
  rocking: boolean;
}

/**
 * The plotted angles in degrees (from the main thread's plot when plots show, else from the worker's cycle), its
 * rates for the input's direction, the input range in degrees and the rocking flag (from the cycle's
 * classification), each recomputed only when its source changes.
 */
export function useCycleFacts(cycle: CycleResponse | null, plot: SolvedPlot | null, direction: Direction): CycleFacts {
  const deg = useMemo(() => (plot ? plotDegrees(plot.plot) : cycle ? cycleDegrees(cycle) : null), [cycle, plot]);
  const rates = useMemo(() => plotRates(plot?.plot ?? null, direction), [plot, direction]);
  const rangeDeg = useMemo(() => (cycle ? rangeToDeg(cycle.classification.inputRange) : null), [cycle]);
  const rocking = cycle ? isRocking(cycle.classification.inputRange) : false;
  return { deg, rates, rangeDeg, rocking };
}
