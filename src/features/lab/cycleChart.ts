import type { ScaleContinuousNumeric } from 'd3-scale';
import { scaleLinear, scaleLog, scaleSymlog } from 'd3-scale';
import type { SweepMethod } from '../../solver/types';
import { CHART_COLORS } from '../../shared/theme/tokens';
import type { ChartScales, ChartSpec, ChartTexts, GSel, MarkerAt } from '../../shared/charts/chart';
import { chartSize, createChart, logFloor } from '../../shared/charts/chart';
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
  /** Current theta2 in degrees, drawn as an orange line; none when omitted or not finite. */
  currentDeg?: number;
}

/** Options of drawCycleChart; sizes in CSS pixels. */
export interface CycleChartOptions {
  width: number;
  height: number;
  title: string;
  /** Shared x axis label, e.g. 'θ2 (°)'. */
  xLabel: string;
  /** Top panel's y label, e.g. 'iterations'. */
  iterationsLabel: string;
  /** Bottom panel's y label, e.g. '|det J| (length²)'. */
  detJLabel: string;
  /** Legend and line label per method; default each entry's own label. */
  methodLabels?: Partial<Record<SweepMethod, string>>;
  /** Default { top: 46 plus 16 per extra legend row, right: 14, bottom: 40, left: 58 }. */
  margins?: Partial<Margins>;
  /** Vertical gap between the two panels in pixels; default 14. */
  panelGap?: number;
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

/** The current θ2 as the kit's marker line (no dots); hidden when not finite. */
const currentMarker = (_m: true, { data }: CyclePanelData): MarkerAt | null =>
  data.currentDeg !== undefined && Number.isFinite(data.currentDeg)
    ? { x: toAxisDeg(data.currentDeg), dots: [] }
    : null;

/** What both panels share: bands under the grid, limits over the curves, the current θ2 as the marker. */
const panelLayers = {
  under: { className: 'bands', draw: drawBands },
  over: { className: 'limits', draw: drawLimits },
  marker: currentMarker,
};

/** The top panel: each method's iterations per point as steps (a negative count is a gap), dodged 1.5 px apart. */
export const iterationsSpec: ChartSpec<CyclePanelData, true> = {
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
export const detJSpec: ChartSpec<CyclePanelData, true> = {
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

/**
 * Draws (or redraws in place) the lab's cycle chart: the two panels (iterationsSpec over detJSpec) as two kit charts
 * in nested SVGs, equal in height, the method legend's rows pushing both down; sizes in CSS pixels.
 */
export function drawCycleChart(svg: SVGSVGElement, data: CycleChartData, options: CycleChartOptions): void {
  const { width, height } = options;
  const s = prepareSvg(svg, width, height);
  const labels = options.methodLabels ?? {};
  const panel: CyclePanelData = { data, labels };
  const legend = iterationsSpec.curves(panel);
  const m = { top: 46, right: 14, bottom: 40, left: 58, ...options.margins };
  const gap = options.panelGap ?? 14;
  const top = m.top + Math.max(0, legendRows(legend, width - 28) - 1) * LEGEND_ROW;
  const ihAll = Math.max(30, height - top - m.bottom);
  const hTop = Math.max(10, Math.round((ihAll - gap) * 0.5));
  const topHeight = top + hTop + PANEL_FOOT;
  const panels = [
    { cls: 'panel-top', spec: iterationsSpec, y: 0, h: topHeight, margins: { ...m, bottom: PANEL_FOOT } },
    {
      cls: 'panel-bottom',
      spec: detJSpec,
      y: topHeight,
      h: Math.max(0, height - topHeight),
      margins: { ...m, top: gap - PANEL_FOOT },
    },
  ];
  const texts: ChartTexts[] = [
    { title: options.title, xLabel: '', yLabel: options.iterationsLabel },
    { title: '', xLabel: options.xLabel, yLabel: options.detJLabel },
  ];
  panels.forEach((p, i) => {
    const el = child(s, 'svg', p.cls).attr('x', 0).attr('y', p.y).node() as SVGSVGElement;
    const size = chartSize({
      width,
      height: p.h,
      margins: p.margins,
      xTickSpacing: 60,
      xMaxTicks: Infinity,
      yTickSpacing: i ? 18 : 24,
    });
    createChart(el, size, texts[i], p.spec, panel).setMarker(true);
  });
}
