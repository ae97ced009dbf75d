import { useMemo } from 'react';
import type { Branch, Linkage } from '../../solver/types';
import type { DesignInfo } from './scene/designScene';
import { designInfo } from './scene/designScene';

export type { DesignInfo } from './scene/designScene';

/**
 * designMetrics and inputRange on the main thread (closed form, microseconds), recomputed only when the
 * linkage or the branch changes; null for a linkage the solver refuses (the panel then shows dashes).
 */
export function useDesignMetrics(linkage: Linkage, branch: Branch): DesignInfo | null {
  return useMemo(() => designInfo(linkage, branch), [linkage, branch]);
}
