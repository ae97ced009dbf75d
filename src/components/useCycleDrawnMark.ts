import { useLayoutEffect } from 'react';
import type { CycleResponse } from '../worker/protocol';
import { benchMark } from '../worker/benchMarks';

/**
 * Marks 'fourbar:cycle-drawn' (with the cycle's lengths) once the plots and canvas show a new cycle, for
 * the UI benchmark only. Called in the layout after the views, so its layout effect runs after theirs.
 */
export function useCycleDrawnMark(cycle: CycleResponse | null): void {
  useLayoutEffect(() => {
    if (cycle) benchMark('fourbar:cycle-drawn', { ...cycle.linkage });
  }, [cycle]);
}
