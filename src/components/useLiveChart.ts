import { useCallback, useLayoutEffect, useRef, useState } from 'react';
import type { RefCallback, RefObject } from 'react';
import { useElementSize } from './useElementSize';

/** What every chart handle (angle, rate, transmission) offers the views: new data, a new marker, a new size. */
export interface LiveChart<D, M> {
  update(data: D): void;
  setMarker(marker: M): void;
  resize(width: number, height: number): void;
}

/** The chart handle of a view, the refs to attach (the box it sizes to, its SVG), and nothing else. */
export interface LiveChartRefs<C> {
  chart: C | null;
  boxRef: RefObject<HTMLDivElement | null>;
  svgRef: RefCallback<SVGSVGElement>;
}

/**
 * Creates a chart once per SVG element (create gets it at size 0: nothing drawn until sized) and keeps its
 * data, marker and size in step with the props, each through its own update so a new marker only moves
 * the marker. create must be stable (a module-level function). Texts and chart-specific options stay with
 * the view.
 */
export function useLiveChart<D, M, C extends LiveChart<D, M>>(
  create: (svg: SVGSVGElement) => C,
  data: D,
  marker: M,
): LiveChartRefs<C> {
  const boxRef = useRef<HTMLDivElement>(null);
  const [chart, setChart] = useState<C | null>(null);
  const svgRef = useCallback((svg: SVGSVGElement | null) => setChart(svg ? create(svg) : null), [create]);
  const { width, height } = useElementSize(boxRef);
  useLayoutEffect(() => {
    chart?.update(data);
  }, [chart, data]);
  useLayoutEffect(() => {
    chart?.setMarker(marker);
  }, [chart, marker]);
  useLayoutEffect(() => {
    if (width > 0 && height > 0) chart?.resize(width, height);
  }, [chart, width, height]);
  return { chart, boxRef, svgRef };
}
