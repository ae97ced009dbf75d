import { useMemo } from 'react';
// The solver's modules themselves, not its barrel: the barrel would pull the sweep and NR into the main bundle.
import { inputRange } from '../../solver/classify';
import type { DesignMetrics } from '../../solver/metrics';
import { designMetrics } from '../../solver/metrics';
import type { Branch, InputRange, Linkage } from '../../solver/types';

/** The design metrics of the linkage on its branch and the input's reachable range (radians). */
export interface DesignInfo {
  metrics: DesignMetrics;
  range: InputRange;
}

/**
 * designMetrics and inputRange on the main thread (closed form, microseconds), recomputed only when the
 * linkage or the branch changes; null for a linkage the solver refuses (the panel then shows dashes).
 */
export function useDesignMetrics(linkage: Linkage, branch: Branch): DesignInfo | null {
  return useMemo(() => {
    try {
      return { metrics: designMetrics(linkage, branch), range: inputRange(linkage) };
    } catch {
      return null;
    }
  }, [linkage, branch]);
}
