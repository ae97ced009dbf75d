import { useLayoutEffect, useRef, useState } from 'react';
import type { RefObject } from 'react';
import { useElementSize } from '../hooks/useElementSize';
import { watchOnScreen } from '../hooks/useOnScreen';
import type { ValueSource } from '../state/externalValue';

/** What every chart handle (angle, rate, transmission) offers the views: new data, a new marker, a new size. */
export interface LiveChart<D, M> {
  update(data: D): void;
  setMarker(marker: M): void;
  resize(width: number, height: number): void;
}

/**
 * A chart's marker: a value, or a source the chart follows by itself (Play's frame moves the marker with no render
 * of the view that gave it).
 */
export type LiveMarker<M> = M | ValueSource<M>;

/** Whether a marker is a source to follow (markers themselves are plain data, never with a subscribe function). */
function isMarkerSource<M>(marker: LiveMarker<M>): marker is ValueSource<M> {
  return typeof (marker as Partial<ValueSource<M>> | null)?.subscribe === 'function';
}

/** The chart handle of a view, the refs to attach (the box it sizes to, its SVG, the marker box over it), and nothing else. */
export interface LiveChartRefs<C> {
  chart: C | null;
  boxRef: RefObject<HTMLDivElement | null>;
  svgRef: RefObject<SVGSVGElement | null>;
  /** A box over the SVG (className "chart-marker") the marker is drawn in: Play moves it without repainting the chart. */
  markerRef: RefObject<HTMLDivElement | null>;
}

/**
 * Creates a chart once, on mount (create gets the SVG and the marker box at size 0: nothing drawn until
 * sized), and keeps its data, marker (or the marker's source) and size in step with the props, each through its own update so a
 * new marker only moves the marker. create must be stable (a module-level function). Texts and
 * chart-specific options stay with the view. While `held`, no chart is made (the view's box keeps its place): a chart
 * below the fold can wait for the first screen.
 */
export function useLiveChart<D, M, C extends LiveChart<D, M>>(
  create: (svg: SVGSVGElement, markerHost: HTMLDivElement | undefined) => C,
  data: D,
  marker: LiveMarker<M>,
  held = false,
): LiveChartRefs<C> {
  const boxRef = useRef<HTMLDivElement>(null);
  const svgRef = useRef<SVGSVGElement>(null);
  const markerRef = useRef<HTMLDivElement>(null);
  const [chart, setChart] = useState<C | null>(null);
  useLayoutEffect(() => {
    const svg = svgRef.current;
    const host = markerRef.current ?? undefined;
    if (!svg || held) return;
    // Once per mount: the element refs are read after commit, never during render.
    setChart(create(svg, host));
    return () => {
      setChart(null);
      host?.replaceChildren();
    };
  }, [create, held]);
  const { width, height } = useElementSize(boxRef);
  useLayoutEffect(() => {
    chart?.update(data);
  }, [chart, data]);
  useLayoutEffect(() => {
    if (!chart) return;
    if (!isMarkerSource(marker)) {
      chart.setMarker(marker);
      return;
    }
    return followOnScreen(boxRef.current, () => chart.setMarker(marker.get()), marker.subscribe);
  }, [chart, marker]);
  useLayoutEffect(() => {
    if (width > 0 && height > 0) chart?.resize(width, height);
  }, [chart, width, height]);
  return { chart, boxRef, svgRef, markerRef };
}

/**
 * Draws a marker from its source now and at each change the source tells of (subscribe), but only while box is on
 * screen (watchOnScreen, with no margin: a marker's move costs the page's thread about as much as the rest of its
 * frame): a chart below the fold does not move its marker through Play; it is drawn as soon as a check finds it in
 * view (a scroll, a resize, a render of a watched section). Returns the stop.
 */
function followOnScreen(
  box: Element | null,
  draw: () => void,
  subscribe: (listener: () => void) => () => void,
): () => void {
  let onScreen = true;
  let stale = false;
  const follow = () => {
    stale = !onScreen;
    if (onScreen) draw();
  };
  follow();
  const unsubscribe = subscribe(follow);
  if (!box || typeof window === 'undefined') return unsubscribe;
  const unwatch = watchOnScreen(
    box,
    (now) => {
      onScreen = now;
      if (onScreen && stale) follow();
    },
    0,
  );
  return () => {
    unwatch();
    unsubscribe();
  };
}
