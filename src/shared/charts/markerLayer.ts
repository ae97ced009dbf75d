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

/** How far a slider reaches each way (CSS pixels): far beyond any chart. */
const SLIDER_REACH = 1e5;

/** Moves an element along one axis: slide(offset) puts it offset CSS pixels from where its style places it. */
type Slide = (offset: number) => void;

/**
 * A slider: the element moved along one axis by a paused linear animation from −SLIDER_REACH to +SLIDER_REACH
 * px over 2·SLIDER_REACH ms, so that its current time in ms is the offset in px (kept to the microsecond, so
 * 0.001 px). Moving it sets a time, which goes to the compositor directly. A style transform instead makes the
 * page's thread lay out its compositor layers again (Chromium's Layerize, over the whole page) on every frame of
 * Play, and rewriting an animation's keyframes parses them each time. Measured at 6x CPU, Play with every
 * overlay (traces at load 13): the page thread's work per frame 17.7 ms with style transforms, 13.5–14.1 with
 * rewritten keyframes. Where there is no Web Animations API (jsdom), the style.
 */
function slider(el: HTMLElement, axis: 'X' | 'Y'): Slide {
  let at = Number.NaN;
  if (typeof el.animate !== 'function') {
    return (offset) => {
      if (offset !== at) el.style.transform = `translate${axis}(${(at = offset)}px)`;
    };
  }
  const animation = el.animate(
    [{ transform: `translate${axis}(${-SLIDER_REACH}px)` }, { transform: `translate${axis}(${SLIDER_REACH}px)` }],
    { duration: 2 * SLIDER_REACH, fill: 'both', easing: 'linear' },
  );
  animation.pause();
  return (offset) => {
    if (offset !== at) animation.currentTime = (at = offset) + SLIDER_REACH;
  };
}

/**
 * Places an element by a whole transform held by a paused animation (its keyframes rewritten on a change), for
 * the one marker that turns: a polar plot's radius. In jsdom, the style.
 */
function transformer(el: HTMLElement): (transform: string) => void {
  let at = '';
  let animation: Animation | null = null;
  return (transform) => {
    if (transform === at) return;
    at = transform;
    const keyframes = [{ transform }, { transform }];
    if (typeof el.animate !== 'function') el.style.transform = transform;
    else if (animation) (animation.effect as KeyframeEffect | null)?.setKeyframes(keyframes);
    else {
      animation = el.animate(keyframes, { duration: 1, fill: 'forwards' });
      animation.pause();
    }
  };
}

/** A marker element in parent: absolutely placed at its top-left, hidden at first. */
function markerElement(parent: HTMLElement, className: string): HTMLDivElement {
  const el = parent.ownerDocument.createElement('div');
  el.className = className;
  el.hidden = true;
  parent.append(el);
  return el;
}

/**
 * Hides or shows an element, writing its hidden attribute only when that changes: Play draws a marker every frame,
 * and each write of an attribute the page's styles select on ([hidden]) makes the page's thread match styles again.
 */
function hide(el: HTMLElement, hidden: boolean): void {
  if (el.hidden !== hidden) el.hidden = hidden;
}

/** A marker dot: its element (in the column) and the slider that sets its height. */
interface Dot {
  el: HTMLDivElement;
  slideY: Slide;
  color: string;
}

/**
 * Draws a chart's current-θ2 marker (a line and a dot per series) in host, a box laid over the chart's SVG at the
 * same size, as a few elements on their own compositor layers (SvgChartView.css) moved by sliders (above). Play
 * moves the marker every frame: inside the SVG each move repainted the whole chart, curves and axes included; on a
 * canvas each move cleared, drew and uploaded the canvas's pixels on the page's thread; a slider's move is
 * composited off the page's thread. Every dot is at the line's x (the marker's θ2), so the line and the dots ride
 * one column moved across; in it the line is a bar of the plot's height and each dot slides down. A segment (a
 * polar plot's radius) is a 1 px bar scaled to its length and turned to its direction instead of the column's bar.
 * A dot is a round box of radius DOT_R + DOT_RING / 2 with a DOT_RING border in the chart's background colour.
 * host carries the plot-pixel placement for tests and tools: data-x (empty when hidden), data-dots, a
 * JSON list of { cx, cy, color } (the numbers an SVG marker's circles have), and data-segment, the line's
 * { x1, y1, x2, y2 } when it is a segment (empty otherwise).
 */
export function createMarkerLayer(host: HTMLElement): MarkerLayer {
  host.setAttribute('aria-hidden', 'true');
  const column = markerElement(host, 'chart-marker-column');
  const slideX = slider(column, 'X');
  const bar = markerElement(column, 'chart-marker-bar');
  bar.style.width = `${LINE_WIDTH}px`;
  bar.style.left = `${-LINE_WIDTH / 2}px`;
  bar.style.background = CHART_STYLE.marker;
  const radius = markerElement(host, 'chart-marker-line');
  radius.style.height = `${LINE_WIDTH}px`;
  radius.style.background = CHART_STYLE.marker;
  const turnRadius = transformer(radius);
  const dots: Dot[] = [];
  const outer = DOT_R + DOT_RING / 2;
  let barBox = '';
  return {
    draw({ x, dots: placed, segment }, box) {
      host.dataset.x = x === null ? '' : String(x);
      host.dataset.dots = JSON.stringify(x === null ? [] : placed);
      host.dataset.segment = x === null || !segment ? '' : JSON.stringify(segment);
      hide(column, x === null);
      hide(bar, x === null || segment !== undefined);
      hide(radius, x === null || segment === undefined);
      const shown = x === null ? 0 : placed.length;
      for (let i = 0; i < dots.length; i++) hide(dots[i].el, i >= shown);
      if (x === null) return;
      slideX(box.left + x);
      if (segment) {
        const length = Math.hypot(segment.x2 - segment.x1, segment.y2 - segment.y1);
        const turn = Math.atan2(segment.y2 - segment.y1, segment.x2 - segment.x1);
        const y0 = box.top + segment.y1 - LINE_WIDTH / 2;
        turnRadius(`translate(${box.left + segment.x1}px, ${y0}px) rotate(${turn}rad) scaleX(${length})`);
      } else if (barBox !== `${box.top} ${box.height}`) {
        barBox = `${box.top} ${box.height}`;
        bar.style.top = `${box.top}px`;
        bar.style.height = `${box.height}px`;
      }
      placed.forEach((d, i) => {
        if (!dots[i]) {
          const el = markerElement(column, 'chart-marker-dot');
          el.style.width = el.style.height = `${2 * outer}px`;
          el.style.left = el.style.top = `${-outer}px`;
          el.style.borderWidth = `${DOT_RING}px`;
          el.style.borderColor = CHART_STYLE.background;
          el.hidden = false;
          dots[i] = { el, slideY: slider(el, 'Y'), color: '' };
        }
        const dot = dots[i];
        if (dot.color !== d.color) dot.el.style.backgroundColor = dot.color = d.color;
        dot.slideY(box.top + d.cy);
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
