import { select } from 'd3-selection';
import { CHART_STYLE, child } from './chartFrame';

/** One marker dot in plot pixels (x right, y down from the plot's top-left corner) and its fill. */
export interface MarkerDotPx {
  cx: number;
  cy: number;
  color: string;
}

/** A marker line's ends in plot pixels. */
export interface MarkerSegmentPx {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
}

/**
 * Where a chart's marker goes, in plot pixels: the line's x (null hides the marker) and the dots; segment, when
 * given, replaces the full-height line at x (a polar plot's radius).
 */
export interface MarkerPlacement {
  x: number | null;
  dots: readonly MarkerDotPx[];
  segment?: MarkerSegmentPx;
}

/** The marker's line: its segment, or the full plot height at x. */
function lineOf(x: number, segment: MarkerSegmentPx | undefined, height: number): MarkerSegmentPx {
  return segment ?? { x1: x, y1: 0, x2: x, y2: height };
}

/** The plot area inside the chart's SVG: its top-left corner and its height, CSS pixels. */
export interface PlotBox {
  left: number;
  top: number;
  height: number;
}

/** A chart marker, drawn above the chart's SVG (createMarkerLayer) or inside it (createSvgMarker). */
export interface MarkerLayer {
  /** Shows the placement in box (the plot area) of a chart width x height; placement.x null hides the marker. */
  draw(placement: MarkerPlacement, box: PlotBox, width: number, height: number): void;
}

/** Dot radius and ring width (CSS pixels). */
const DOT_R = 4;
const DOT_RING = 1.5;
/** Line width (CSS pixels). */
const LINE_WIDTH = 1.25;

/** A marker element's placement: the paused animation that holds its transform, and that transform. */
interface Placement {
  animation: Animation | null;
  transform: string;
}

const placements = new WeakMap<HTMLElement, Placement>();

/**
 * Places a marker element by its transform alone (no layout, no paint). The transform is held by a paused
 * animation whose keyframes are rewritten, not by the element's style: a style change makes the page's thread
 * lay out its compositor layers again (Chromium's Layerize, over the whole page), on every frame of Play; an
 * animation's new keyframes go to the compositor directly. Measured at 6x CPU, Play with every overlay: the
 * page thread's work per frame 15.9 → 10.2 ms, Layerize 3.9 → 0.2 ms. Where there is no Web Animations API
 * (jsdom), the style.
 */
function place(el: HTMLElement, transform: string): void {
  const at = placements.get(el);
  if (at?.transform === transform) return;
  const keyframes = [{ transform }, { transform }];
  if (typeof el.animate !== 'function') {
    el.style.transform = transform;
  } else if (at?.animation) {
    (at.animation.effect as KeyframeEffect | null)?.setKeyframes(keyframes);
  } else {
    const animation = el.animate(keyframes, { duration: 1, fill: 'forwards' });
    animation.pause();
    placements.set(el, { animation, transform });
    return;
  }
  placements.set(el, { animation: at?.animation ?? null, transform });
}

/** A marker element in host: absolutely placed at the host's top-left, on its own compositor layer, hidden at first. */
function markerElement(host: HTMLElement, className: string): HTMLDivElement {
  const el = host.ownerDocument.createElement('div');
  el.className = className;
  el.hidden = true;
  host.append(el);
  return el;
}

/**
 * Draws a chart's current-θ2 marker (a line and a dot per series) in host, a box laid over the chart's SVG at the
 * same size, as a few elements each on its own compositor layer (SvgChartView.css) moved by their transforms. Play
 * moves the marker every frame: inside the SVG each move repainted the whole chart, curves and axes included; on a
 * canvas each move cleared, drew and uploaded the canvas's pixels on the page's thread; a transform is composited
 * off the page's thread. The line is a 1 px bar scaled to its length and turned to its direction; a dot is a
 * round box of radius DOT_R + DOT_RING / 2 with a DOT_RING border in the chart's background colour.
 * host carries the plot-pixel placement for tests and tools: data-x (empty when hidden), data-dots, a
 * JSON list of { cx, cy, color } (the numbers an SVG marker's circles have), and data-segment, the line's
 * { x1, y1, x2, y2 } when it is a segment (empty otherwise).
 */
export function createMarkerLayer(host: HTMLElement): MarkerLayer {
  host.setAttribute('aria-hidden', 'true');
  const line = markerElement(host, 'chart-marker-line');
  line.style.height = `${LINE_WIDTH}px`;
  line.style.background = CHART_STYLE.marker;
  const dots: HTMLDivElement[] = [];
  // The colour each dot was given (the style reads back in another notation).
  const colors: string[] = [];
  const outer = DOT_R + DOT_RING / 2;
  return {
    draw({ x, dots: placed, segment }, box) {
      host.dataset.x = x === null ? '' : String(x);
      host.dataset.dots = JSON.stringify(x === null ? [] : placed);
      host.dataset.segment = x === null || !segment ? '' : JSON.stringify(segment);
      line.hidden = x === null;
      const shown = x === null ? 0 : placed.length;
      for (let i = 0; i < dots.length; i++) dots[i].hidden = i >= shown;
      if (x === null) return;
      const l = lineOf(x, segment, box.height);
      const length = Math.hypot(l.x2 - l.x1, l.y2 - l.y1);
      const turn = Math.atan2(l.y2 - l.y1, l.x2 - l.x1);
      const y0 = box.top + l.y1 - LINE_WIDTH / 2;
      place(line, `translate(${box.left + l.x1}px, ${y0}px) rotate(${turn}rad) scaleX(${length})`);
      placed.forEach((d, i) => {
        if (!dots[i]) {
          dots[i] = markerElement(host, 'chart-marker-dot');
          dots[i].style.width = dots[i].style.height = `${2 * outer}px`;
          dots[i].style.borderWidth = `${DOT_RING}px`;
          dots[i].style.borderColor = CHART_STYLE.background;
          dots[i].hidden = false;
        }
        if (colors[i] !== d.color) dots[i].style.backgroundColor = colors[i] = d.color;
        place(dots[i], `translate(${box.left + d.cx - outer}px, ${box.top + d.cy - outer}px)`);
      });
    },
  };
}

/**
 * The same marker inside the chart's SVG (g.marker in the plot group: a line and a circle per dot), for
 * charts drawn off screen (exports), where the SVG must carry everything.
 */
export function createSvgMarker(plot: SVGGElement): MarkerLayer {
  const g = child(select(plot), 'g', 'marker');
  const line = child(g, 'line', 'mline').attr('stroke', CHART_STYLE.marker).attr('stroke-width', LINE_WIDTH);
  return {
    draw({ x, dots, segment }, box) {
      g.attr('display', x === null ? 'none' : null);
      if (x === null) return;
      const l = lineOf(x, segment, box.height);
      line.attr('x1', l.x1).attr('y1', l.y1).attr('x2', l.x2).attr('y2', l.y2);
      g.selectAll<SVGCircleElement, MarkerDotPx>('circle')
        .data(dots)
        .join('circle')
        .attr('cx', (d) => d.cx)
        .attr('cy', (d) => d.cy)
        .attr('r', DOT_R)
        .attr('fill', (d) => d.color)
        .attr('stroke', CHART_STYLE.background)
        .attr('stroke-width', DOT_RING);
    },
  };
}

/** The marker for a chart: above its SVG in host when given (on screen), else inside the plot group. */
export function chartMarker(plot: SVGGElement, host: HTMLElement | undefined): MarkerLayer {
  return host ? createMarkerLayer(host) : createSvgMarker(plot);
}
