import { axisBottom, axisLeft } from 'd3-axis';
import { select } from 'd3-selection';
import type { Selection } from 'd3-selection';
import type { ScaleContinuousNumeric } from 'd3-scale';
import { curveStep } from 'd3-shape';
import type { LegendItem, Margins } from './chartFrame';
import {
  CHART_STYLE,
  LEGEND_ROW,
  child,
  drawChartText,
  drawGridX,
  drawGridY,
  drawHLines,
  drawLegend,
  legendBoxes,
  legendRows,
  minus,
  prepareSvg,
  sameChartTexts,
  styleAxis,
} from './chartFrame';
import type { MarkerDotPx, MarkerPlacement } from './markerLayer';
import { chartMarker } from './markerLayer';
import type { XMark } from './xMarks';
import { drawXMarks } from './xMarks';
import { linePath } from './line';

/**
 * The chart kit's one skeleton: frame, axes (linear or log, a log y with a floor), grid, x rules, curves with
 * gaps, point marks, a legend that wraps, texts, an empty state, marker, resize and axis caching. A spec says what
 * differs (scales, curves, layers, marker); the θ2 charts (angle, rate, transmission), the x–y chart, the NR
 * convergence chart and the lab's work-precision and cycle charts are specs of it.
 */

/** A d3 group selection, as the layers draw into. */
export type GSel = Selection<SVGGElement, unknown, null, undefined>;

/** The SVG's defs as a d3 selection (clip paths go here). */
export type DefsSel = Selection<SVGDefsElement, unknown, null, undefined>;

/** One curve: y against x (same length; a NaN in either is a gap, never drawn as a zero). */
export interface Curve {
  label: string;
  color: string;
  x: ArrayLike<number>;
  y: ArrayLike<number>;
  /** Drawn thin and dashed: the other branch, for reference; default false. */
  faint?: boolean;
  /** Wrapped angle in degrees: at a jump over 180 the line runs to the +-180 edge and breaks; default false. */
  wrapped?: boolean;
  /** Draw the line; default true (false for point marks alone). */
  line?: boolean;
  /** A dot at every finite point (precision points, say); default false. */
  dots?: boolean;
  /** Class of its path (e2e and CSS read it); default none. */
  className?: string;
  /** Stroke width, CSS pixels; default 1.75 (1 when faint). */
  strokeWidth?: number;
  /** Id of a clipPath the line is drawn through; default none. */
  clipId?: string;
  /** Steps: each value holds until the next sample (d3's curveStep, a count per sample); default false. */
  step?: boolean;
  /** Shifts the curve down this many pixels, so equal values of two curves stay apart (a dodge); default 0. */
  dyPx?: number;
}

/** The title and axis labels every chart has. */
export interface ChartTexts {
  title: string;
  xLabel: string;
  yLabel: string;
}

/** Size options of a chart; CSS pixels. */
export interface ChartSizeOptions {
  /** Chart width; 0 (not laid out yet) draws nothing until resize. */
  width: number;
  /** Chart height; 0 (not laid out yet) draws nothing until resize. */
  height: number;
  /** Default { top: 46, right: 14, bottom: 40, left: 50 }. */
  margins?: Margins;
  /** Pixels of plot width per x tick, at most xMaxTicks; default 40 (60 degree steps on θ2 from 160 px of plot up). */
  xTickSpacing?: number;
  /** Most x ticks asked of d3, so a wide chart keeps 60 degree steps on θ2; default 8. */
  xMaxTicks?: number;
  /** Pixels of plot height per y tick; default 34. */
  yTickSpacing?: number;
}

/** Options every chart reads once at creation: its size, x rules and where the marker goes. */
export interface ChartOptions extends ChartSizeOptions {
  /** Faint vertical rules on the x axis (dead centres); default none. */
  xMarks?: readonly XMark[];
  /** A box laid over the SVG to draw the marker in (on screen: moving it repaints nothing); default inside the SVG. */
  markerHost?: HTMLElement;
}

/** Size options with every default filled in (CSS pixels). */
export type ChartSize = Required<ChartSizeOptions>;

/** The plot area of a chart (pixels inside the margins) and the tick counts its size asks for. */
export interface PlotArea {
  iw: number;
  ih: number;
  /** About this many x ticks fit (tickCount of iw, at most xMaxTicks). */
  xCount: number;
  /** About this many y ticks fit. */
  yCount: number;
}

/** A scale from data to plot pixels: d3's linear, log or symlog. */
export type ChartScale = ScaleContinuousNumeric<number, number>;

/** The plot area, the scales (data to plot pixels) and the ticks of a chart. */
export interface ChartScales {
  iw: number;
  ih: number;
  /** Data to plot pixels; a value the scale cannot place (0 on a log scale) is a gap. */
  x: ChartScale;
  y: ChartScale;
  xTicks: number[];
  yTicks: number[];
  /**
   * The floor of a log y: finite values below it (zeros and negatives included) are drawn on it, their dots hollow,
   * with a dashed line along it and its tick labelled ≤; default none (logFloor sets it when some value is below).
   */
  yFloor?: number;
}

/** The marker in data units: a vertical line at x and a dot at each y on it (NaN or outside the plot: no dot). */
export interface MarkerAt {
  x: number;
  dots: readonly { y: number; color: string }[];
  /**
   * When given, the line runs from this point (data units) to (x, the first dot's y) instead of the full height at x:
   * a polar plot's radius from its centre.
   */
  from?: { x: number; y: number };
}

/** A group of the plot the spec draws itself: under the grid (a band) or over the curves (clip marks). */
export interface ChartLayer<D> {
  /** Class of the layer's group. */
  className: string;
  /** Draws the layer for these data in plot pixels; defs is the SVG's defs (for clip paths). */
  draw(g: GSel, data: D, frame: ChartScales, defs: DefsSel): void;
}

/** What makes a chart an angle, rate, transmission or x–y chart; the skeleton does the rest. */
export interface ChartSpec<D, M, T extends ChartTexts = ChartTexts> {
  /** The scales and ticks for these data on this plot area (x, y and their ticks). */
  frame(data: D, plot: PlotArea): Omit<ChartScales, 'iw' | 'ih'>;
  /** The curves of these data. */
  curves(data: D): Curve[];
  /** x tick labels; default the number as d3 writes it, typographic minus. */
  xTickFormat?: (frame: ChartScales) => (value: number) => string;
  /** y tick labels; default the number as d3 writes it, typographic minus (the floor's tick gets ≤ before it). */
  yTickFormat?: (frame: ChartScales) => (value: number) => string;
  /** The legend (it wraps into rows, which push the plot down); default one entry per curve. */
  legend?: (curves: readonly Curve[], text: T, data: D) => LegendItem[];
  /** A text shown in the middle instead of the plot and axis labels (nothing to plot), or null; default null. */
  empty?: (data: D, text: T) => string | null;
  /** Where the marker goes, in data units (null hides it); default no marker. */
  marker?: (marker: M, data: D) => MarkerAt | null;
  /** Clip the curves' group to the plot (curves that run off a clipped y domain); default false. */
  clipToPlot?: boolean;
  /** Drawn under the grid. */
  under?: ChartLayer<D>;
  /** Drawn over the curves. */
  over?: ChartLayer<D>;
}

/** A live chart; every method redraws only what its change touches. */
export interface Chart<D, M, T extends ChartTexts = ChartTexts> {
  /** Replaces the data; the axes are redrawn only when their domain, ticks or size change. */
  update(data: D): void;
  /** Moves the marker (null hides it); nothing else is redrawn. */
  setMarker(marker: M | null): void;
  /** Sets the chart size in CSS pixels; a no-op when unchanged. */
  resize(width: number, height: number): void;
  /** Sets the title, axis labels and legend texts; a no-op when unchanged. */
  setText(text: T): void;
  /** Replaces the faint x rules (dead centres); nothing else is redrawn. */
  setXMarks(marks: readonly XMark[]): void;
  /** Redraws what depends on the spec's own settings (the transmission band): layers, curves and marker. */
  refresh(): void;
  /** A copy of the x or the y scale (data to plot pixels). */
  scale(name: 'x' | 'y'): ChartScale;
}

const DEFAULT_MARGINS: Margins = { top: 46, right: 14, bottom: 40, left: 50 };
/** Dot radius of point marks, CSS pixels. */
const DOT_R = 3;

/** Fills in the documented defaults of the size options (negative sizes become 0). */
export function chartSize(options: ChartSizeOptions): ChartSize {
  return {
    width: Math.max(0, options.width),
    height: Math.max(0, options.height),
    margins: options.margins ?? DEFAULT_MARGINS,
    xTickSpacing: options.xTickSpacing ?? 40,
    xMaxTicks: options.xMaxTicks ?? 8,
    yTickSpacing: options.yTickSpacing ?? 34,
  };
}

/** The plot area of a chart of this size: at least 10 px each way, and the tick counts that fit it. */
export function plotArea(size: ChartSize): PlotArea {
  const m = size.margins;
  const iw = Math.max(10, size.width - m.left - m.right);
  const ih = Math.max(10, size.height - m.top - m.bottom);
  const xCount = Math.min(size.xMaxTicks, Math.max(2, Math.floor(iw / size.xTickSpacing)));
  return { iw, ih, xCount, yCount: Math.max(2, Math.floor(ih / size.yTickSpacing)) };
}

/** The frame of a spec's data at a size: the plot area with the spec's scales and ticks. */
export function chartFrame<D>(spec: Pick<ChartSpec<D, unknown>, 'frame'>, data: D, size: ChartSize): ChartScales {
  const area = plotArea(size);
  return { ...spec.frame(data, area), iw: area.iw, ih: area.ih };
}

/**
 * Indices to plot when a curve has more samples than the chart has pixels: every k-th sample for at
 * most maxPoints, plus the first and last sample of every defined run (so gaps start and end where
 * they really do) and both samples around every jump over 180 (so a wrap's edge crossing is placed exactly).
 */
export function plotIndices(y: ArrayLike<number>, maxPoints: number): number[] {
  const n = y.length;
  const out: number[] = [];
  if (n <= maxPoints) {
    for (let i = 0; i < n; i++) out.push(i);
    return out;
  }
  const stride = Math.ceil(n / Math.max(2, maxPoints));
  for (let i = 0; i < n; i++) {
    const v = y[i];
    const fin = Number.isFinite(v);
    const prevFin = i > 0 && Number.isFinite(y[i - 1]);
    const nextFin = i < n - 1 && Number.isFinite(y[i + 1]);
    const edge = fin && (!prevFin || !nextFin);
    const wrap = fin && ((prevFin && Math.abs(v - y[i - 1]) > 180) || (nextFin && Math.abs(y[i + 1] - v) > 180));
    if (i % stride === 0 || i === n - 1 || edge || wrap || (!fin && prevFin)) out.push(i);
  }
  return out;
}

/**
 * Points of a wrapped angle curve ready for d3's line with defined(): NaN samples become gaps, and where
 * the angle wraps between two samples (a jump of more than 180 degrees) the curve runs to the +-180 edge,
 * breaks and continues from the opposite edge, so no vertical stroke crosses the plot.
 */
export function wrappedSegments(x: ArrayLike<number>, yDeg: ArrayLike<number>): [number, number][] {
  const out: [number, number][] = [];
  const n = Math.min(x.length, yDeg.length);
  for (let i = 0; i < n; i++) {
    const y = yDeg[i];
    if (i > 0) {
      const y0 = yDeg[i - 1];
      if (Number.isFinite(y0) && Number.isFinite(y) && Math.abs(y - y0) > 180) {
        const up = y < y0; // e.g. 179 -> -179: the unwrapped angle goes up through 180
        const yUnwrapped = up ? y + 360 : y - 360;
        const edge = up ? 180 : -180;
        const f = (edge - y0) / (yUnwrapped - y0);
        const xe = x[i - 1] + f * (x[i] - x[i - 1]);
        out.push([xe, edge], [xe, Number.NaN], [xe, -edge]);
      }
    }
    out.push([x[i], Number.isFinite(y) ? y : Number.NaN]);
  }
  return out;
}

/** y as drawn on a y axis with this floor: a finite value below the floor sits on it; NaN stays NaN (a gap). */
export function onFloor(y: number, floor: number | undefined): number {
  return floor !== undefined && y < floor ? floor : y;
}

/**
 * The floor of a log axis for these values: floor when a finite value is below it (a zero, say), else undefined
 * (nothing to floor, so no floor line and no ≤ is drawn).
 */
export function logFloor(floor: number, values: Iterable<ArrayLike<number>>): number | undefined {
  for (const v of values) for (let i = 0; i < v.length; i++) if (v[i] < floor) return floor;
  return undefined;
}

/**
 * SVG path data of a curve in plot pixels: gaps where x or y is NaN or off its scale (0 on a log axis), values below
 * the y floor on it, breaks at wraps, steps when asked, at most two samples per pixel.
 */
export function curvePath(
  curve: Pick<Curve, 'x' | 'y' | 'wrapped' | 'step' | 'dyPx'>,
  frame: Pick<ChartScales, 'x' | 'y' | 'iw' | 'yFloor'>,
): string {
  // At most two samples per horizontal pixel: n = 3600 on a 300 px chart would only cost time.
  const idx = plotIndices(curve.y, Math.max(64, Math.round(2 * frame.iw)));
  const xs = idx.map((i) => curve.x[i]);
  const ys = idx.map((i) => curve.y[i]);
  const pts: [number, number][] = curve.wrapped ? wrappedSegments(xs, ys) : xs.map((x, i) => [x, ys[i]]);
  const dy = curve.dyPx ?? 0;
  const px = pts.map(([x, y]): [number, number] => [frame.x(x), frame.y(onFloor(y, frame.yFloor)) + dy]);
  // Hundredths of a pixel: finer digits only lengthen the path text the browser parses on every redraw.
  return linePath(
    px,
    (d) => d[0],
    (d) => d[1],
    (d) => Number.isFinite(d[0]) && Number.isFinite(d[1]),
    2,
    curve.step ? curveStep : undefined,
  );
}

/**
 * Where the marker goes in plot pixels: its line at x clamped to the x domain, a dot for each finite y in the y
 * domain; with at.from, the line is the segment from that point to the first dot (hidden when either is not finite).
 */
export function markerPlacement(at: MarkerAt | null, frame: Pick<ChartScales, 'x' | 'y'>): MarkerPlacement {
  if (!at || !Number.isFinite(at.x)) return { x: null, dots: [] };
  const [x0, x1] = frame.x.domain();
  const cx = frame.x(Math.min(Math.max(x0, x1), Math.max(Math.min(x0, x1), at.x)));
  const [y0, y1] = frame.y.domain();
  const dots: MarkerDotPx[] = at.dots
    .filter((d) => Number.isFinite(d.y) && d.y >= Math.min(y0, y1) && d.y <= Math.max(y0, y1))
    .map((d) => ({ cx, cy: frame.y(d.y), color: d.color }));
  const end = at.dots[0];
  if (!at.from) return { x: cx, dots };
  // A radius needs both ends; without its far end (an undetermined pose) the marker hides rather than mislead.
  if (!end || !Number.isFinite(end.y) || !Number.isFinite(at.from.x) || !Number.isFinite(at.from.y)) {
    return { x: null, dots: [] };
  }
  const segment = { x1: frame.x(at.from.x), y1: frame.y(at.from.y), x2: frame.x(at.x), y2: frame.y(end.y) };
  return { x: cx, dots, segment };
}

/** Plain number labels with a typographic minus. */
const plainFormat = () => (d: number) => minus(`${d}`);

/** Which optional parts a chart has: a clip of its curves to the plot, a layer under the grid, one over the curves. */
interface PartsPlan {
  clipToPlot?: boolean;
  under?: { className: string };
  over?: { className: string };
}

/** The parts of a chart's SVG, each created once in drawing order (background, defs, plot and its groups). */
function chartParts(svg: SVGSVGElement, spec: PartsPlan, clipId: string) {
  const s = select(svg);
  child(s, 'rect', 'bg'); // first child, so the background stays under the plot
  const defs = child(s, 'defs', 'defs');
  const clipRect = spec.clipToPlot
    ? child(child(defs, 'clipPath', 'clip').attr('id', clipId), 'rect', 'clip-rect')
    : null;
  const plot = child(s, 'g', 'plot');
  const under = spec.under ? child(plot, 'g', spec.under.className) : null;
  const gridX = child(plot, 'g', 'grid-x');
  const gridY = child(plot, 'g', 'grid-y');
  const ax = child(plot, 'g', 'axis-x');
  const ay = child(plot, 'g', 'axis-y');
  const marksG = child(plot, 'g', 'x-marks');
  const lines = child(plot, 'g', 'lines');
  if (spec.clipToPlot) lines.attr('clip-path', `url(#${clipId})`);
  const dots = child(plot, 'g', 'dots');
  const over = spec.over ? child(plot, 'g', spec.over.className) : null;
  return { s, defs, clipRect, plot, under, gridX, gridY, ax, ay, marksG, lines, dots, over };
}

/** The groups of a chart's SVG. */
type ChartParts = ReturnType<typeof chartParts>;

/** One point mark in plot pixels: hollow when it sits on the floor (the value is below it), smaller on a faint curve. */
interface DotPx {
  cx: number;
  cy: number;
  color: string;
  r: number;
  hollow: boolean;
}

/** The point marks of the curves with dots, in plot pixels: one per point both scales can place. */
export function curveDots(curves: readonly Curve[], frame: Pick<ChartScales, 'x' | 'y' | 'yFloor'>): DotPx[] {
  const out: DotPx[] = [];
  for (const c of curves) {
    if (!c.dots) continue;
    const n = Math.min(c.x.length, c.y.length);
    for (let i = 0; i < n; i++) {
      const y = c.y[i];
      const cx = frame.x(c.x[i]);
      const cy = frame.y(onFloor(y, frame.yFloor)) + (c.dyPx ?? 0);
      if (!Number.isFinite(cx) || !Number.isFinite(cy)) continue;
      out.push({ cx, cy, color: c.color, r: c.faint ? DOT_R - 1 : DOT_R, hollow: onFloor(y, frame.yFloor) !== y });
    }
  }
  return out;
}

/** Draws the lines (one path per curve with a line) and the point marks (one circle per finite point). */
function drawCurves(parts: ChartParts, curves: readonly Curve[], frame: ChartScales): void {
  parts.lines
    .selectAll<SVGPathElement, Curve>('path')
    .data(curves.filter((c) => c.line !== false))
    .join('path')
    .attr('class', (d) => d.className ?? null)
    .attr('fill', 'none')
    .attr('stroke', (d) => d.color)
    .attr('stroke-width', (d) => d.strokeWidth ?? (d.faint ? 1 : 1.75))
    .attr('stroke-dasharray', (d) => (d.faint ? '4 3' : null))
    .attr('stroke-opacity', (d) => (d.faint ? 0.55 : 1))
    .attr('stroke-linejoin', 'round')
    .attr('clip-path', (d) => (d.clipId ? `url(#${d.clipId})` : null))
    .attr('d', (d) => curvePath(d, frame));
  parts.dots
    .selectAll<SVGCircleElement, DotPx>('circle')
    .data(curveDots(curves, frame))
    .join('circle')
    .attr('class', 'dot')
    .attr('cx', (d) => d.cx)
    .attr('cy', (d) => d.cy)
    .attr('r', (d) => d.r)
    .attr('fill', (d) => (d.hollow ? CHART_STYLE.background : d.color))
    .attr('stroke', (d) => (d.hollow ? d.color : CHART_STYLE.background))
    .attr('stroke-width', (d) => (d.hollow ? 1.25 : 1));
}

/** Draws the x axis (these tick labels, in tick order) and its grid. */
function drawXAxis(parts: ChartParts, frame: ChartScales, labels: readonly string[]): void {
  const { ih, x, xTicks } = frame;
  drawGridX(parts.gridX, ih, xTicks, x);
  parts.ax.attr('transform', `translate(0,${ih})`).call(
    axisBottom(x)
      .tickValues(xTicks)
      .tickFormat((_d, i) => labels[i])
      .tickSizeOuter(0),
  );
  styleAxis(parts.ax);
}

/** Draws the y axis (these tick labels, in tick order), its grid and the dashed line of its floor. */
function drawYAxis(parts: ChartParts, frame: ChartScales, labels: readonly string[]): void {
  const { iw, y, yTicks, yFloor } = frame;
  drawGridY(parts.gridY, iw, yTicks, y);
  drawHLines(parts.gridY, 'floor', yFloor === undefined ? [] : [yFloor], iw, y, CHART_STYLE.tolerance, '3 3');
  parts.ay.call(
    axisLeft(y)
      .tickValues(yTicks)
      .tickFormat((_d, i) => labels[i])
      .tickSizeOuter(0),
  );
  styleAxis(parts.ay);
}

/** The y tick labels: the spec's format, ≤ before the floor's (everything below it is drawn there). */
function yTickLabels(format: (v: number) => string, frame: ChartScales): string[] {
  return frame.yTicks.map((t) => (t === frame.yFloor ? `≤${format(t)}` : format(t)));
}

/** What a live chart draws from: its size, texts, data and their curves, marker, x rules and scales. */
interface ChartState<D, M, T extends ChartTexts> {
  /** The size asked for. */
  size: ChartSize;
  /** The size laid out: the top margin grown by a row per extra legend row. */
  layout: ChartSize;
  text: T;
  data: D;
  curves: readonly Curve[];
  marker: M | null;
  xMarks: readonly XMark[];
  frame: ChartScales;
  /** What the axes, legend, x rules and empty text were last drawn for: each is redrawn only when its key changes. */
  keys: { x: string; y: string; legend: string; marks: string; empty: string | null };
}

/** The spec's empty text for the state's data and texts (null: there is a plot to show). */
function emptyText<D, M, T extends ChartTexts>(spec: ChartSpec<D, M, T>, st: ChartState<D, M, T>): string | null {
  return spec.empty ? spec.empty(st.data, st.text) : null;
}

/** Draws the title, the x label and the y label centred on the plot, or the spec's empty text instead of the plot. */
function drawTexts<D, M, T extends ChartTexts>(parts: ChartParts, spec: ChartSpec<D, M, T>, st: ChartState<D, M, T>) {
  const { text, frame, layout: size } = st;
  const m = size.margins;
  const centerY = m.top + frame.ih / 2;
  const empty = emptyText(spec, st);
  st.keys.empty = empty;
  drawChartText(
    parts.s,
    { title: text.title, xLabel: text.xLabel, yLabels: [{ text: text.yLabel, centerY }] },
    m.left,
    frame.iw,
    size.width,
    size.height,
    spec.empty ? { plot: parts.plot, text: empty, centerY } : undefined,
  );
}

/** Draws the x and y axes (and the clip to the plot), each only when its size, domain or ticks changed. */
function drawAxes<D, M, T extends ChartTexts>(parts: ChartParts, spec: ChartSpec<D, M, T>, st: ChartState<D, M, T>) {
  const { frame, keys } = st;
  const { iw, ih, x, y, xTicks, yTicks } = frame;
  parts.clipRect?.attr('x', 0).attr('y', 0).attr('width', iw).attr('height', ih);
  const xLabels = xTicks.map((spec.xTickFormat ?? plainFormat)(frame));
  const xKey = `${iw} ${ih} ${x.domain().join(',')} ${xTicks.join(',')} ${xLabels.join(',')}`;
  if (xKey !== keys.x) drawXAxis(parts, frame, xLabels);
  const yLabels = yTickLabels((spec.yTickFormat ?? plainFormat)(frame), frame);
  // Keyed by what is drawn (the ticks' pixel rows, their labels, the floor's row), not by the domain: a log domain
  // recomputed a rounding apart from the last one moves nothing on screen and must not rewrite the axis.
  const yRow = (v: number) => y(v).toFixed(3);
  const yFloorRow = frame.yFloor === undefined ? '' : yRow(frame.yFloor);
  const yKey = `${iw} ${ih} ${yTicks.map(yRow).join(',')} ${yLabels.join(',')} ${yFloorRow}`;
  if (yKey !== keys.y) drawYAxis(parts, frame, yLabels);
  Object.assign(keys, { x: xKey, y: yKey });
}

/** Draws the data: the layer under the grid, the curves, the layer over them. */
function drawData<D, M, T extends ChartTexts>(parts: ChartParts, spec: ChartSpec<D, M, T>, st: ChartState<D, M, T>) {
  if (parts.under) spec.under?.draw(parts.under, st.data, st.frame, parts.defs);
  drawCurves(parts, st.curves, st.frame);
  if (parts.over) spec.over?.draw(parts.over, st.data, st.frame, parts.defs);
}

/** Where the legend starts in the SVG (CSS pixels): its first line sample's left end and the row's middle. */
const LEGEND_AT = { x: 14, y: 33 } as const;

/** The legend's entries: the spec's items, or one per curve. */
function legendItems<D, M, T extends ChartTexts>(
  spec: ChartSpec<D, M, T>,
  st: Pick<ChartState<D, M, T>, 'curves' | 'text' | 'data'>,
): readonly LegendItem[] {
  return spec.legend ? spec.legend(st.curves, st.text, st.data) : st.curves;
}

/** The legend's widest row, CSS pixels: the chart's width less its left inset on both sides. */
const legendWidth = (size: ChartSize) => size.width - 2 * LEGEND_AT.x;

/** The size laid out for a legend of these entries: the top margin grown by LEGEND_ROW per row after the first. */
export function legendLayoutSize(size: ChartSize, items: readonly LegendItem[]): ChartSize {
  const extra = Math.max(0, legendRows(items, legendWidth(size)) - 1);
  return extra ? { ...size, margins: { ...size.margins, top: size.margins.top + extra * LEGEND_ROW } } : size;
}

/**
 * Draws the legend when its labels, colours or faintness changed, then the x rules when the x axis, the legend
 * or the rules changed: their labels keep clear of the legend (xMarkBaselines).
 */
function drawLegendIfChanged<D, M, T extends ChartTexts>(
  parts: ChartParts,
  spec: ChartSpec<D, M, T>,
  st: ChartState<D, M, T>,
) {
  const items = legendItems(spec, st);
  const key = items.map((d) => `${d.label}|${d.color}|${d.faint === true}`).join('\n');
  if (key !== st.keys.legend) drawLegend(parts.s, items, LEGEND_AT.x, LEGEND_AT.y, legendWidth(st.size));
  st.keys.legend = key;
  const marksKey = `${st.keys.x}\n${key}\n${st.xMarks.map((m) => `${m.xDeg}|${m.label}`).join('\n')}`;
  if (marksKey === st.keys.marks) return;
  st.keys.marks = marksKey;
  const { left, top } = st.layout.margins;
  const avoid = legendBoxes(items, LEGEND_AT.x, LEGEND_AT.y, legendWidth(st.size)).map((b) => ({
    x0: b.x0 - left,
    y0: b.y0 - top,
    x1: b.x1 - left,
    y1: b.y1 - top,
  }));
  drawXMarks(parts.marksG, st.xMarks, st.frame.x, st.frame.ih, avoid);
}

let clipCounter = 0;

/**
 * Creates a chart in svg as the spec says (axes, grid, legend, x rules, curves, layers and a marker) and
 * returns its handle; the scales live in the handle (scale()). Options are read once here; resize and
 * setText change size and texts later. Draws nothing while width or height is 0.
 */
export function createChart<D, M, T extends ChartTexts>(
  svg: SVGSVGElement,
  options: ChartOptions,
  initialText: T,
  spec: ChartSpec<D, M, T>,
  empty: D,
): Chart<D, M, T> {
  const size = chartSize(options);
  const text = { ...initialText };
  const curves = spec.curves(empty);
  const layout = legendLayoutSize(size, legendItems(spec, { curves, text, data: empty }));
  const st: ChartState<D, M, T> = {
    size,
    layout,
    text,
    data: empty,
    curves,
    marker: null,
    xMarks: options.xMarks ?? [],
    frame: chartFrame(spec, empty, layout),
    keys: { x: '', y: '', legend: '', marks: '', empty: null },
  };
  const laidOut = () => st.size.width > 0 && st.size.height > 0;
  // The id e2e reads on the rate chart's clipped lines.
  const parts = chartParts(svg, spec, `theta2-clip-${++clipCounter}`);
  const mark = chartMarker(parts.plot.node() as SVGGElement, options.markerHost);

  /** Lays the chart out again for its legend and data; true when the plot moved (a legend row came or went). */
  const relayout = () => {
    const top = st.layout.margins.top;
    st.layout = legendLayoutSize(st.size, legendItems(spec, st));
    st.frame = chartFrame(spec, st.data, st.layout);
    return st.layout.margins.top !== top;
  };
  const drawMarker = () => {
    const at = st.marker === null || !spec.marker ? null : spec.marker(st.marker, st.data);
    const { left, top } = st.layout.margins;
    mark.draw(markerPlacement(at, st.frame), { left, top, height: st.frame.ih }, st.size.width, st.size.height);
  };
  const drawAll = () => {
    if (!laidOut()) return;
    prepareSvg(svg, st.size.width, st.size.height);
    parts.plot.attr('transform', `translate(${st.layout.margins.left},${st.layout.margins.top})`);
    drawAxes(parts, spec, st);
    drawData(parts, spec, st);
    drawTexts(parts, spec, st);
    drawLegendIfChanged(parts, spec, st);
    drawMarker();
  };

  drawAll();
  return {
    update(next) {
      Object.assign(st, { data: next, curves: spec.curves(next) });
      const moved = relayout();
      if (!laidOut()) return;
      if (moved) return drawAll();
      drawAxes(parts, spec, st);
      drawData(parts, spec, st);
      if (emptyText(spec, st) !== st.keys.empty) drawTexts(parts, spec, st);
      drawLegendIfChanged(parts, spec, st);
      drawMarker();
    },
    setMarker(next) {
      st.marker = next;
      if (laidOut()) drawMarker();
    },
    resize(width, height) {
      if (width === st.size.width && height === st.size.height) return;
      st.size = chartSize({ ...st.size, width, height });
      relayout();
      drawAll();
    },
    setText(next) {
      if (sameChartTexts(next, st.text)) return;
      st.text = { ...next };
      const moved = relayout();
      if (!laidOut()) return;
      if (moved) return drawAll();
      drawTexts(parts, spec, st);
      drawLegendIfChanged(parts, spec, st);
    },
    setXMarks(next) {
      st.xMarks = next;
      if (laidOut()) drawLegendIfChanged(parts, spec, st);
    },
    refresh() {
      if (!laidOut()) return;
      drawData(parts, spec, st);
      drawMarker();
    },
    scale(name) {
      return (name === 'x' ? st.frame.x : st.frame.y).copy();
    },
  };
}
