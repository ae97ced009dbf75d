import { TWO_PI } from '../../solver/angles';
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

/**
 * Draws a chart's current-θ2 marker (a line and a dot per series) on a canvas in host, a box laid over the
 * chart's SVG at the same size. Play moves the marker every frame: inside the SVG each move repainted the
 * whole chart, curves and axes included, and re-layered the page; a canvas only redraws its own pixels.
 * host carries the plot-pixel placement for tests and tools: data-x (empty when hidden), data-dots, a
 * JSON list of { cx, cy, color } (the numbers an SVG marker's circles have), and data-segment, the line's
 * { x1, y1, x2, y2 } when it is a segment (empty otherwise).
 */
export function createMarkerLayer(host: HTMLElement): MarkerLayer {
  host.setAttribute('aria-hidden', 'true');
  const canvas = host.ownerDocument.createElement('canvas');
  canvas.style.position = 'absolute';
  canvas.style.inset = '0';
  canvas.style.width = '100%';
  canvas.style.height = '100%';
  host.append(canvas);
  let drawn = false;
  return {
    draw({ x, dots, segment }, box, width, height) {
      const view = host.ownerDocument.defaultView;
      const dpr = Math.max(1, Math.min(4, view?.devicePixelRatio ?? 1));
      const pw = Math.round(width * dpr);
      const ph = Math.round(height * dpr);
      if (canvas.width !== pw || canvas.height !== ph) {
        canvas.width = pw;
        canvas.height = ph;
        drawn = false;
      }
      const ctx = canvas.getContext('2d');
      host.dataset.x = x === null ? '' : String(x);
      host.dataset.dots = JSON.stringify(x === null ? [] : dots);
      host.dataset.segment = x === null || !segment ? '' : JSON.stringify(segment);
      if (!ctx) return;
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      if (drawn) ctx.clearRect(0, 0, pw, ph);
      drawn = x !== null;
      if (x === null) return;
      ctx.setTransform(dpr, 0, 0, dpr, dpr * box.left, dpr * box.top);
      ctx.strokeStyle = CHART_STYLE.marker;
      ctx.lineWidth = LINE_WIDTH;
      const l = lineOf(x, segment, box.height);
      ctx.beginPath();
      ctx.moveTo(l.x1, l.y1);
      ctx.lineTo(l.x2, l.y2);
      ctx.stroke();
      ctx.lineWidth = DOT_RING;
      ctx.strokeStyle = CHART_STYLE.background;
      for (const d of dots) {
        ctx.fillStyle = d.color;
        ctx.beginPath();
        ctx.arc(d.cx, d.cy, DOT_R, 0, TWO_PI);
        ctx.fill();
        ctx.stroke();
      }
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
