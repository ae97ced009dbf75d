import type { ScaleContinuousNumeric } from 'd3-scale';
import { scaleLinear, scaleLog, scaleSymlog } from 'd3-scale';
import { select } from 'd3-selection';
import type { SweepMethod } from '../../solver/types';
import { CHART_COLORS } from '../../shared/theme/tokens';
import type { ChartScales, ChartSpec, ChartTexts, GSel, MarkerAt } from '../../shared/charts/chart';
import { createChart, logFloor } from '../../shared/charts/chart';
import type { Margins } from '../../shared/charts/chartFrame';
import { CHART_STYLE, LEGEND_ROW, child, legendRows, minus, prepareSvg } from '../../shared/charts/chartFrame';
import { dec, decadeTicks, integerTicks, logTicks, niceCountDomain, niceLogDomain } from '../../shared/charts/ticks';
import { theta2XAxis } from '../../shared/charts/theta2Chart';
import { METHOD_COLORS } from './workPrecisionChart';

/**
 * The lab's cycle chart: two chart-kit specs stacked in one SVG over θ2 from 0 to 360°, sharing the x axis: NR
 * iterations per point for each method (steps, linear or symlog) on top, |det J| (log y, zeros on its floor, gaps
 * where the linkage cannot assemble) below, with the unassembled stretches shaded, the input limits dashed and
 * the current θ2 as the kit's marker in both.
 */

/** NR iterations at each theta2 sample of one method. */
export interface CycleIterations {
  method: SweepMethod;
  label: string;
  iterations: Int32Array;
}

/** Data of the cycle chart; arrays are indexed like theta2Deg. */
export interface CycleChartData {
  /** Input angle samples in degrees, 0 to 360. */
  theta2Deg: Float64Array;
  /** |det J| = r3 r4 |sin mu| (length unit squared), NaN where the linkage cannot assemble. */
  detJ: Float64Array;
  iterations: CycleIterations[];
  /** Input limit angles in degrees in (-180, 180]; empty for a full-turn crank. */
  limitsDeg: number[];
}

/** Texts of the cycle chart. */
export interface CycleChartText {
  title: string;
  /** Shared x axis label, e.g. 'θ2 (°)'. */
  xLabel: string;
  /** Top panel's y label, e.g. 'iterations'. */
  iterationsLabel: string;
  /** Bottom panel's y label, e.g. '|det J| (length²)'. */
  detJLabel: string;
}

/** Options of createCycleChart, read once (texts and size change later through the handle); sizes in CSS pixels. */
export interface CycleChartOptions extends CycleChartText {
  width: number;
  height: number;
  /** Legend and line label per method; default each entry's own label. */
  methodLabels?: Partial<Record<SweepMethod, string>>;
  /** Default { top: 46 plus 16 per extra legend row, right: 14, bottom: 40, left: 58 }. */
  margins?: Partial<Margins>;
  /** Vertical gap between the two panels in pixels; default 14. */
  panelGap?: number;
}

/** A live cycle chart; every method redraws only what its change touches. */
export interface CycleChart {
  /** Replaces the study's data: curves, bands and limits are redrawn, the axes only when their domain changes. */
  update(data: CycleChartData): void;
  /** Moves the current θ2 (degrees; the orange line in both panels, hidden when not finite); nothing else is redrawn. */
  setMarker(theta2Deg: number): void;
  /** Sets the chart size in CSS pixels; a no-op when unchanged. */
  resize(width: number, height: number): void;
  /** Sets the title and axis labels; a no-op when unchanged. */
  setText(text: CycleChartText): void;
}

/** A limit or marker angle in degrees on the chart's 0..360 axis: values already in [0, 360] are kept, others wrapped (-90 -> 270). */
export function toAxisDeg(deg: number): number {
  if (deg >= 0 && deg <= 360) return deg;
  return ((deg % 360) + 360) % 360;
}

/**
 * Log-scale domain of |det J| (length unit squared): the finite positive values widened to whole decades
 * by d3's nice, at least two decades wide; zeros are drawn at the floor. Without positive values: [1e-3, 1e1].
 */
export function detJDomain(detJ: ArrayLike<number>): [number, number] {
  let lo = Infinity;
  let hi = 0;
  for (let i = 0; i < detJ.length; i++) {
    const v = detJ[i];
    if (!(v > 0) || !Number.isFinite(v)) continue;
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  if (!(hi > 0)) return [1e-3, 1e1];
  const [a, b] = niceLogDomain(lo, hi);
  let e0 = Math.round(Math.log10(a));
  let e1 = Math.round(Math.log10(b));
  if (e1 === e0) e1++;
  // A nearly constant |det J| would fill the panel with noise; show it against two decades.
  if (e1 - e0 < 2) e0 = e1 - 2;
  return [dec(1, e0), dec(1, e1)];
}

/** Largest iteration count over all methods (0 when there are none). */
export function maxIterations(iterations: readonly CycleIterations[]): number {
  let m = 0;
  for (const it of iterations) for (let i = 0; i < it.iterations.length; i++) m = Math.max(m, it.iterations[i]);
  return m;
}

/**
 * Integer tick values for an iteration axis from 0 to at least max, the last tick being the axis top:
 * d3's nice and ticks for about count ticks; for max > 20 (a symlog axis) 0 and the log ticks from 1
 * (1, 2, 5, 10, 20, 50, ... under three decades), ending at max itself.
 */
export function iterationTicks(max: number, count = 4): number[] {
  const top = Math.max(1, Math.ceil(max));
  if (top > 20) {
    const out = [0, ...logTicks([1, top], count).filter((v) => v <= top)];
    if (out[out.length - 1] !== top) out.push(top);
    return out;
  }
  const [, niceTop] = niceCountDomain(top, count);
  return integerTicks(0, niceTop, count);
}

/** Keeps the ticks (in order) whose pixel position is at least minGapPx from the last kept one, always keeping the last tick. */
export function spacedTicks(ticks: readonly number[], toPx: (v: number) => number, minGapPx: number): number[] {
  const out: number[] = [];
  for (let i = ticks.length - 1; i >= 0; i--) {
    const t = ticks[i];
    if (out.length === 0 || Math.abs(toPx(t) - toPx(out[0])) >= minGapPx) out.unshift(t);
  }
  return out;
}

/** Angle intervals (degrees, first and last sample of each run) where detJ is NaN: the linkage cannot assemble there. */
export function unassembledRuns(theta2Deg: ArrayLike<number>, detJ: ArrayLike<number>): Array<[number, number]> {
  const out: Array<[number, number]> = [];
  let start = -1;
  const n = Math.min(theta2Deg.length, detJ.length);
  for (let i = 0; i < n; i++) {
    const gap = Number.isNaN(detJ[i]);
    if (gap && start < 0) start = i;
    if ((!gap || i === n - 1) && start >= 0) {
      const end = gap ? i : i - 1;
      out.push([theta2Deg[start], theta2Deg[end]]);
      start = -1;
    }
  }
  return out;
}

/**
 * Labels for the powers of ten of one log axis, all in one style: plain numbers when every tick is
 * between 0.01 and 10000, otherwise exponent form with a typographic minus ('1e−3').
 */
export function decadeLabels(ticks: readonly number[]): string[] {
  const exps = ticks.map((v) => Math.round(Math.log10(v)));
  const plain = exps.every((e) => e >= -2 && e <= 4);
  return exps.map((e) => (plain ? (e >= 0 ? String(dec(1, e)) : `0.${'0'.repeat(-e - 1)}1`) : minus(`1e${e}`)));
}

/** The top panel's data: θ2 samples, each method's counts, the unassembled stretches and the limits (degrees). */
interface CyclePanelData {
  data: CycleChartData;
  labels: Partial<Record<SweepMethod, string>>;
}

/** Shades the stretches where the linkage cannot assemble (|det J| is NaN) over the panel's height. */
function drawBands(g: GSel, { data }: CyclePanelData, frame: ChartScales): void {
  g.selectAll<SVGRectElement, [number, number]>('rect')
    .data(unassembledRuns(data.theta2Deg, data.detJ))
    .join('rect')
    .attr('x', (r) => frame.x(r[0]))
    .attr('width', (r) => Math.max(1, frame.x(r[1]) - frame.x(r[0])))
    .attr('y', 0)
    .attr('height', frame.ih)
    .attr('fill', CHART_COLORS.unassembledBand);
}

/** The input limits as dashed grey lines down the panel. */
function drawLimits(g: GSel, { data }: CyclePanelData, frame: ChartScales): void {
  g.selectAll<SVGLineElement, number>('line.limit')
    .data(data.limitsDeg.filter(Number.isFinite).map(toAxisDeg))
    .join('line')
    .attr('class', 'limit')
    .attr('x1', (d) => frame.x(d))
    .attr('x2', (d) => frame.x(d))
    .attr('y1', 0)
    .attr('y2', frame.ih)
    .attr('stroke', CHART_STYLE.tolerance)
    .attr('stroke-width', 1.25)
    .attr('stroke-dasharray', '5 4');
}

/** The current θ2 (degrees) as the kit's marker line (no dots); hidden when not finite. */
const currentMarker = (theta2Deg: number): MarkerAt | null =>
  Number.isFinite(theta2Deg) ? { x: toAxisDeg(theta2Deg), dots: [] } : null;

/** What both panels share: bands under the grid, limits over the curves, the current θ2 as the marker. */
const panelLayers = {
  under: { className: 'bands', draw: drawBands },
  over: { className: 'limits', draw: drawLimits },
  marker: currentMarker,
};

/** The top panel: each method's iterations per point as steps (a negative count is a gap), dodged 1.5 px apart. */
export const iterationsSpec: ChartSpec<CyclePanelData, number> = {
  frame: ({ data }, plot) => {
    const itMax = maxIterations(data.iterations);
    const itAll = iterationTicks(itMax, plot.yCount);
    // Symlog when one method needs dozens of iterations somewhere: 1, 2 and 3 must stay apart from 100.
    const y: ScaleContinuousNumeric<number, number> = (itMax > 20 ? scaleSymlog() : scaleLinear())
      .domain([0, itAll[itAll.length - 1]])
      .range([plot.ih, 4]);
    return { ...theta2XAxis(plot), y, yTicks: spacedTicks(itAll, y, 13) };
  },
  curves: ({ data, labels }) => {
    const n = data.iterations.length;
    return data.iterations.map((it, k) => ({
      label: labels[it.method] ?? it.label,
      color: METHOD_COLORS[it.method] ?? CHART_STYLE.muted,
      x: data.theta2Deg,
      y: Array.from(it.iterations, (v) => (v >= 0 ? v : NaN)),
      step: true,
      strokeWidth: 1.5,
      // Overlapping counts (two methods both at 2) would hide each other: dodge each method by 1.5 px.
      dyPx: (k - (n - 1) / 2) * 1.5,
    }));
  },
  // The panels share the x axis: tick marks only here, the numbers are under the bottom panel.
  xTickFormat: () => () => '',
  ...panelLayers,
};

/** The bottom panel: |det J| on a log y, gaps where it is NaN, zeros on the floor, one style of decade labels. */
export const detJSpec: ChartSpec<CyclePanelData, number> = {
  frame: ({ data }, plot) => {
    const [d0, d1] = detJDomain(data.detJ);
    return {
      ...theta2XAxis(plot),
      y: scaleLog().domain([d0, d1]).range([plot.ih, 0]),
      yTicks: decadeTicks(d0, d1, plot.yCount),
      yFloor: logFloor(d0, [data.detJ]),
    };
  },
  curves: ({ data }) => [{ label: '|det J|', color: CHART_STYLE.residual, x: data.theta2Deg, y: data.detJ }],
  yTickFormat: (frame) => {
    const labels = decadeLabels(frame.yTicks);
    return (v) => labels[frame.yTicks.indexOf(v)] ?? '';
  },
  legend: () => [],
  ...panelLayers,
};

/** Vertical gap between the panels and the top panel's room below its plot (its tick marks), CSS pixels. */
const PANEL_FOOT = 7;

/** No study yet: what the cycle chart holds before its first update. */
const NO_CYCLE_DATA: CycleChartData = {
  theta2Deg: new Float64Array(0),
  detJ: new Float64Array(0),
  iterations: [],
  limitsDeg: [],
};

/** The heights of the two panels (CSS pixels): equal plots, the top one grown by the method legend's extra rows. */
function panelHeights(
  width: number,
  height: number,
  legend: ReturnType<typeof iterationsSpec.curves>,
  m: Margins,
  gap: number,
): [top: number, bottom: number] {
  const top = m.top + Math.max(0, legendRows(legend, width - 28) - 1) * LEGEND_ROW;
  const ihAll = Math.max(30, height - top - m.bottom);
  const hTop = Math.max(10, Math.round((ihAll - gap) * 0.5));
  const topHeight = top + hTop + PANEL_FOOT;
  return [topHeight, Math.max(0, height - topHeight)];
}

/**
 * Creates the lab's cycle chart in svg and returns its handle: the two panels (iterationsSpec over detJSpec) as
 * two kit charts in nested SVGs, equal in height, the method legend's rows pushing both down; sizes in CSS pixels
 * (0: nothing drawn until resize). A θ2 step only moves the marker; new data redraw the curves, and the axes only
 * when their domain changes.
 */
export function createCycleChart(svg: SVGSVGElement, options: CycleChartOptions): CycleChart {
  const labels = options.methodLabels ?? {};
  const m: Margins = { top: 46, right: 14, bottom: 40, left: 58, ...options.margins };
  const gap = options.panelGap ?? 14;
  const s = select(svg);
  let size = { width: Math.max(0, options.width), height: Math.max(0, options.height) };
  let panel: CyclePanelData = { data: NO_CYCLE_DATA, labels };
  let heights: [number, number] = [-1, -1];
  const panelTexts = (t: CycleChartText): [ChartTexts, ChartTexts] => [
    { title: t.title, xLabel: '', yLabel: t.iterationsLabel },
    { title: '', xLabel: t.xLabel, yLabel: t.detJLabel },
  ];
  const texts = panelTexts(options);
  const specs = [iterationsSpec, detJSpec];
  const margins = [
    { ...m, bottom: PANEL_FOOT },
    { ...m, top: gap - PANEL_FOOT },
  ];
  // The background first: prepareSvg paints it later, and a rect made after the panels would cover them.
  child(s, 'rect', 'bg');
  const els = ['panel-top', 'panel-bottom'].map((cls) => child(s, 'svg', cls).attr('x', 0));
  const panels = els.map((el, i) =>
    createChart(
      el.node() as SVGSVGElement,
      { width: 0, height: 0, margins: margins[i], xTickSpacing: 60, xMaxTicks: Infinity, yTickSpacing: i ? 18 : 24 },
      texts[i],
      specs[i],
      panel,
    ),
  );
  /** Sizes the SVG and both panels when the size or the legend's rows changed the panels' heights. */
  const layout = () => {
    if (!(size.width > 0 && size.height > 0)) return;
    const next = panelHeights(size.width, size.height, iterationsSpec.curves(panel), m, gap);
    if (next[0] === heights[0] && next[1] === heights[1]) return;
    heights = next;
    prepareSvg(svg, size.width, size.height);
    els[1].attr('y', heights[0]);
    panels.forEach((p, i) => p.resize(size.width, heights[i]));
  };
  return {
    update(data) {
      panel = { data, labels };
      panels.forEach((p) => p.update(panel));
      layout();
    },
    setMarker(theta2Deg) {
      panels.forEach((p) => p.setMarker(theta2Deg));
    },
    resize(width, height) {
      if (width === size.width && height === size.height) return;
      size = { width: Math.max(0, width), height: Math.max(0, height) };
      heights = [-1, -1];
      layout();
    },
    setText(text) {
      const next = panelTexts(text);
      panels.forEach((p, i) => p.setText(next[i]));
    },
  };
}
