import { axisBottom, axisLeft } from 'd3-axis';
import type { ScaleContinuousNumeric, ScaleLinear, ScaleLogarithmic } from 'd3-scale';
import type { Selection } from 'd3-selection';
import { scaleLinear, scaleLog, scaleSymlog } from 'd3-scale';
import { curveStep, line } from 'd3-shape';
import type { SweepMethod } from '../../solver/types';
import { CHART_COLORS } from '../../shared/theme/tokens';
import type { Margins, SvgSel } from '../../shared/charts/chartFrame';
import {
  CHART_STYLE,
  child,
  estimateTextWidth,
  minus,
  prepareSvg,
  styleAxis,
  drawGridX,
  drawGridY,
  drawChartText,
} from '../../shared/charts/chartFrame';
import {
  angleTicks,
  fittedTicks,
  dec,
  decadeTicks,
  integerTicks,
  logTicks,
  niceCountDomain,
  niceLogDomain,
  tickCount,
} from '../../shared/charts/ticks';
import { LEGEND_ROW, METHOD_COLORS, drawMethodLegend } from './workPrecisionChart';

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
  /** Default { top: 46 plus 16 per extra legend row, right: 14, bottom: 40, left: 58 }; top given here wins. */
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

type G = Selection<SVGGElement, unknown, null, undefined>;

/** Where the cycle chart's parts go (CSS pixels): margins, the plot's width, the two panels' heights and the gap. */
interface CycleLayout {
  m: Margins;
  iw: number;
  hTop: number;
  hBot: number;
  /** Top of the bottom panel, from the plot's top. */
  yBot0: number;
}

/** Draws the method legend (its rows push the plot down) and splits the rest into the two panels. */
function layoutCycleChart(s: SvgSel, data: CycleChartData, options: CycleChartOptions): CycleLayout {
  const { width, height } = options;
  const legendRows = drawMethodLegend(
    s,
    data.iterations.map((it) => ({
      label: options.methodLabels?.[it.method] ?? it.label,
      color: METHOD_COLORS[it.method] ?? CHART_STYLE.muted,
      kind: 'line',
    })),
    14,
    33,
    width - 28,
  );
  const m: Margins = {
    top: options.margins?.top ?? 46 + Math.max(0, legendRows - 1) * LEGEND_ROW,
    right: options.margins?.right ?? 14,
    bottom: options.margins?.bottom ?? 40,
    left: options.margins?.left ?? 58,
  };
  const gapPx = options.panelGap ?? 14;
  const iw = Math.max(10, width - m.left - m.right);
  const ihAll = Math.max(30, height - m.top - m.bottom);
  const hTop = Math.max(10, Math.round((ihAll - gapPx) * 0.5));
  const hBot = Math.max(10, ihAll - gapPx - hTop);
  return { m, iw, hTop, hBot, yBot0: hTop + gapPx };
}

/** The cycle chart's scales and ticks: θ2 across, iterations up the top panel, |det J| (log) up the bottom one. */
interface CycleScales {
  x: ScaleLinear<number, number>;
  xTicks: number[];
  yIt: ScaleContinuousNumeric<number, number>;
  itTicks: number[];
  yDet: ScaleLogarithmic<number, number>;
  detTicks: number[];
  /** |det J| floor: zeros are drawn on it. */
  d0: number;
}

function cycleScales(data: CycleChartData, { iw, hTop, hBot }: CycleLayout): CycleScales {
  const x = scaleLinear().domain([0, 360]).range([0, iw]);
  const xTicks = fittedTicks(
    (c) => angleTicks(0, 360, c),
    x,
    (t) => estimateTextWidth(`${t}`),
    tickCount(iw, 60),
  );
  const itMax = maxIterations(data.iterations);
  const itAll = iterationTicks(itMax, tickCount(hTop, 24));
  const itTop = itAll[itAll.length - 1];
  // Symlog when one method needs dozens of iterations somewhere: 1, 2 and 3 must stay apart from 100.
  const yIt: ScaleContinuousNumeric<number, number> = (itMax > 20 ? scaleSymlog() : scaleLinear())
    .domain([0, itTop])
    .range([hTop, 4]);
  const [d0, d1] = detJDomain(data.detJ);
  const yDet = scaleLog().domain([d0, d1]).range([hBot, 0]).clamp(true);
  return {
    x,
    xTicks,
    yIt,
    itTicks: spacedTicks(itAll, yIt, 13),
    yDet,
    detTicks: decadeTicks(d0, d1, tickCount(hBot, 18)),
    d0,
  };
}

/** One panel's grid, x axis (numbers only when showXNumbers: the panels share it) and y axis. */
function drawPanelAxes(
  panel: G,
  iw: number,
  h: number,
  sc: Pick<CycleScales, 'x' | 'xTicks'>,
  y: ScaleContinuousNumeric<number, number>,
  yTicks: number[],
  yFormat: (d: number, i: number) => string,
  showXNumbers: boolean,
): void {
  const grid = child(panel, 'g', 'grid');
  drawGridY(grid, iw, yTicks, y);
  drawGridX(grid, h, sc.xTicks, sc.x);
  const ax = child(panel, 'g', 'axis-x').attr('transform', `translate(0,${h})`);
  ax.call(
    axisBottom(sc.x)
      .tickValues(sc.xTicks)
      .tickFormat((d) => (showXNumbers ? `${d}` : ''))
      .tickSizeOuter(0),
  );
  styleAxis(ax);
  const ay = child(panel, 'g', 'axis-y');
  ay.call(
    axisLeft(y)
      .tickValues(yTicks)
      .tickFormat((d, i) => yFormat(d as number, i))
      .tickSizeOuter(0),
  );
  styleAxis(ay);
}

/** Iterations: step lines centred on each sample; a negative count is a gap. */
function drawIterationLines(top: G, data: CycleChartData, { x, yIt }: CycleScales): void {
  const n = data.theta2Deg.length;
  const nIt = data.iterations.length;
  child(top, 'g', 'lines')
    .selectAll<SVGPathElement, CycleIterations>('path')
    .data(data.iterations)
    .join('path')
    .attr('fill', 'none')
    .attr('stroke', (d) => METHOD_COLORS[d.method] ?? CHART_STYLE.muted)
    .attr('stroke-width', 1.5)
    .attr('stroke-linejoin', 'round')
    .attr('d', (d, k) => {
      // Overlapping counts (two methods both at 2) would hide each other: dodge each method by 1.5 px.
      const dodge = (k - (nIt - 1) / 2) * 1.5;
      const idx = Array.from({ length: Math.min(n, d.iterations.length) }, (_v, i) => i);
      const gen = line<number>()
        .defined((i) => d.iterations[i] >= 0)
        .curve(curveStep)
        .x((i) => x(data.theta2Deg[i]))
        .y((i) => yIt(d.iterations[i]) + dodge);
      return gen(idx) ?? '';
    });
}

/** |det J| on its log scale, gaps where it is not finite, zeros on the floor. */
function drawDetJ(bot: G, data: CycleChartData, { x, yDet, d0 }: CycleScales): void {
  const detGen = line<number>()
    .defined((i) => Number.isFinite(data.detJ[i]))
    .x((i) => x(data.theta2Deg[i]))
    .y((i) => yDet(Math.max(d0, data.detJ[i])));
  const detIdx = Array.from({ length: Math.min(data.theta2Deg.length, data.detJ.length) }, (_v, i) => i);
  child(bot, 'path', 'detj')
    .attr('fill', 'none')
    .attr('stroke', CHART_STYLE.residual)
    .attr('stroke-width', 1.75)
    .attr('stroke-linejoin', 'round')
    .attr('d', detGen(detIdx) ?? '');
}

/** Vertical lines of one class at these angles (degrees), from the top panel's top to the bottom panel's foot. */
function markerLines(
  markers: G,
  cls: string,
  deg: number[],
  x: ScaleLinear<number, number>,
  yEnd: number,
): Selection<SVGLineElement, number, SVGGElement, unknown> {
  return markers
    .selectAll<SVGLineElement, number>(`line.${cls}`)
    .data(deg)
    .join('line')
    .attr('class', cls)
    .attr('x1', (d) => x(d))
    .attr('x2', (d) => x(d))
    .attr('y1', 0)
    .attr('y2', yEnd);
}

/**
 * Draws (or redraws in place) the lab's cycle chart: two panels over theta2 0..360 degrees sharing the
 * x axis, NR iterations per point for each method (step lines) on top and |det J| (log scale, gaps where
 * the linkage cannot assemble) below, with dashed grey input limits and an orange current-theta2 line.
 */
export function drawCycleChart(svg: SVGSVGElement, data: CycleChartData, options: CycleChartOptions): void {
  const { width, height } = options;
  const s = prepareSvg(svg, width, height);
  const layout = layoutCycleChart(s, data, options);
  const { m, iw, hTop, hBot, yBot0 } = layout;
  const sc = cycleScales(data, layout);

  const plot = child(s, 'g', 'plot').attr('transform', `translate(${m.left},${m.top})`);
  const top = child(plot, 'g', 'panel-top');
  const bot = child(plot, 'g', 'panel-bottom').attr('transform', `translate(0,${yBot0})`);

  // Unassembled stretches: a light band in both panels explains the gaps.
  const runs = unassembledRuns(data.theta2Deg, data.detJ);
  for (const [panel, h] of [
    [top, hTop],
    [bot, hBot],
  ] as const) {
    child(panel, 'g', 'bands')
      .selectAll<SVGRectElement, [number, number]>('rect')
      .data(runs)
      .join('rect')
      .attr('x', (r) => sc.x(r[0]))
      .attr('width', (r) => Math.max(1, sc.x(r[1]) - sc.x(r[0])))
      .attr('y', 0)
      .attr('height', h)
      .attr('fill', CHART_COLORS.unassembledBand);
  }

  // The top panel shares the x axis: tick marks only, the numbers are under the bottom panel.
  drawPanelAxes(top, iw, hTop, sc, sc.yIt, sc.itTicks, (d) => `${d}`, false);
  const detLabels = decadeLabels(sc.detTicks);
  drawPanelAxes(bot, iw, hBot, sc, sc.yDet, sc.detTicks, (_d, i) => detLabels[i], true);
  drawIterationLines(top, data, sc);
  drawDetJ(bot, data, sc);

  // Markers over both panels: input limits (dashed grey) and the current input angle (orange).
  const markers = child(plot, 'g', 'markers');
  markerLines(markers, 'limit', data.limitsDeg.filter(Number.isFinite).map(toAxisDeg), sc.x, yBot0 + hBot)
    .attr('stroke', CHART_STYLE.tolerance)
    .attr('stroke-width', 1.25)
    .attr('stroke-dasharray', '5 4');
  const cur = data.currentDeg;
  markerLines(markers, 'current', cur !== undefined && Number.isFinite(cur) ? [toAxisDeg(cur)] : [], sc.x, yBot0 + hBot)
    .attr('stroke', CHART_STYLE.marker)
    .attr('stroke-width', 1.5);

  drawChartText(
    s,
    {
      title: options.title,
      xLabel: options.xLabel,
      yLabels: [
        { text: options.iterationsLabel, centerY: m.top + hTop / 2 },
        { text: options.detJLabel, centerY: m.top + yBot0 + hBot / 2 },
      ],
    },
    m.left,
    iw,
    width,
    height,
  );
}
