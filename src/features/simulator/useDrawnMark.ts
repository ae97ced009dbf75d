import { useLayoutEffect } from 'react';
import type { Linkage } from '../../solver/types';
import { benchMark } from '../../shared/benchMarks';

/**
 * Marks `name` (with the lengths drawn) once the views show something new solved for some lengths, for the UI
 * benchmark only: 'fourbar:plot-drawn' for the plots, 'fourbar:cycle-drawn' for the worker's cycle (coupler trace,
 * cycle numbers). Called in the layout after the views, so its layout effect runs after theirs.
 */
export function useDrawnMark(name: string, drawn: { linkage: Linkage } | null): void {
  useLayoutEffect(() => {
    if (drawn) benchMark(name, { ...drawn.linkage });
  }, [name, drawn]);
}
