import { useMemo, useState } from 'react';
import { useElementSize } from '../../shared/hooks/useElementSize';

/** The plots' width in device pixels (0 until laid out), and the callback ref to put on the plots' card. */
export interface PlotPixels {
  plotsRef: (el: HTMLElement | null) => void;
  plotPixels: number;
}

/**
 * Tracks the device-pixel width of the plots card: plot samples follow it, so only what shows is solved.
 * The element is kept in state (a callback ref), so the size follows the card when it mounts again.
 */
export function usePlotPixels(): PlotPixels {
  const [el, setEl] = useState<HTMLElement | null>(null);
  const { width } = useElementSize(useMemo(() => ({ current: el }), [el]));
  const dpr = typeof window !== 'undefined' ? window.devicePixelRatio || 1 : 1;
  return { plotsRef: setEl, plotPixels: width > 0 ? Math.round(width * dpr) : 0 };
}
