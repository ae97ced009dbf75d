import { useCallback, useState } from 'react';
import { contentBox } from '../../shared/hooks/useElementSize';

/** The plots' width in device pixels (0 until laid out), and the callback ref to put on the plots' card. */
export interface PlotPixels {
  plotsRef: (el: HTMLElement | null) => (() => void) | undefined;
  plotPixels: number;
}

/**
 * Tracks the device-pixel width of the plots card: plot samples follow it, so only what shows is solved. The
 * callback ref measures the card as it is attached (in the commit that mounts it) and a ResizeObserver follows
 * it, so the first load renders the app once more with the width, not once for the element and again for its
 * size. Detached (the card unmounts), the width is 0.
 */
export function usePlotPixels(): PlotPixels {
  const [width, setWidth] = useState(0);
  const plotsRef = useCallback((el: HTMLElement | null) => {
    if (!el) return undefined;
    const update = (w: number) => setWidth(Math.floor(w));
    update(contentBox(el).width);
    const ro =
      typeof ResizeObserver === 'undefined'
        ? null
        : new ResizeObserver((e) => update(e[e.length - 1].contentRect.width));
    ro?.observe(el);
    return () => {
      ro?.disconnect();
      setWidth(0);
    };
  }, []);
  const dpr = typeof window !== 'undefined' ? window.devicePixelRatio || 1 : 1;
  return { plotsRef, plotPixels: width > 0 ? Math.round(width * dpr) : 0 };
}
