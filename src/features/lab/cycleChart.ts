import { axisBottom, axisLeft } from 'd3-axis';
import type { ScaleContinuousNumeric } from 'd3-scale';
import { scaleLinear, scaleLog, scaleSymlog } from 'd3-scale';
import { curveStep, line } from 'd3-shape';
import type { SweepMethod } from '../../solver/types';
import { CHART_COLORS } from '../../shared/theme/tokens';
import type { Margins } from '../../shared/charts/chartFrame';
import {
  CHART_STYLE,
  child,
  estimateTextWidth,
  minus,
  prepareSvg,
  styleAxis,
  drawGridLines,
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

/**
 * Draws (or redraws in place) the lab's cycle chart: two panels over theta2 0..360 degrees sharing the
 * x axis, NR iterations per point for each method (step lines) on top and |det J| (log scale, gaps where
 * the linkage cannot assemble) below, with dashed grey input limits and an orange current-theta2 line.
 */
export function drawCycleChart(svg: SVGSVGElement, data: CycleChartData, options: CycleChartOptions): void {
  const { width, height } = options;
  const s = prepareSvg(svg, width, height);
  const labelOf = (it: CycleIterations) => options.methodLabels?.[it.method] ?? it.label;
  const legendRows = drawMethodLegend(
    s,
    data.iterations.map((it) => ({
      label: labelOf(it),
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
  const yBot0 = hTop + gapPx;
  const x = scaleLinear().domain([0, 360]).range([0, iw]);
  const xTicks = fittedTicks(
    (c) => angleTicks(0, 360, c),
    x,
    (t) => estimateTextWidth(`${t}`),
    tickCount(iw, 60),
  );
  const n = data.theta2Deg.length;

  const itMax = maxIterations(data.iterations);
  const itAll = iterationTicks(itMax, tickCount(hTop, 24));
  const itTop = itAll[itAll.length - 1];
  // Symlog when one method needs dozens of iterations somewhere: 1, 2 and 3 must stay apart from 100.
  const yIt: ScaleContinuousNumeric<number, number> = (itMax > 20 ? scaleSymlog() : scaleLinear())
    .domain([0, itTop])
    .range([hTop, 4]);
  const itTicks = spacedTicks(itAll, yIt, 13);
  const [d0, d1] = detJDomain(data.detJ);
  const yDet = scaleLog().domain([d0, d1]).range([hBot, 0]).clamp(true);
  const detTicks = decadeTicks(d0, d1, tickCount(hBot, 18));

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
      .attr('x', (r) => x(r[0]))
      .attr('width', (r) => Math.max(1, x(r[1]) - x(r[0])))
      .attr('y', 0)
      .attr('height', h)
      .attr('fill', CHART_COLORS.unassembledBand);
  }

  const gridTop = child(top, 'g', 'grid');
  drawGridLines(gridTop, iw, hTop, itTicks, yIt, xTicks, x);
  const gridBot = child(bot, 'g', 'grid');
  drawGridLines(gridBot, iw, hBot, detTicks, yDet, xTicks, x);

  // The top panel shares the x axis: tick marks only, the numbers are under the bottom panel.
  const axTop = child(top, 'g', 'axis-x').attr('transform', `translate(0,${hTop})`);
  axTop.call(
    axisBottom(x)
      .tickValues(xTicks)
      .tickFormat(() => '')
      .tickSizeOuter(0),
  );
  styleAxis(axTop);
  const ayTop = child(top, 'g', 'axis-y');
  ayTop.call(
    axisLeft(yIt)
      .tickValues(itTicks)
      .tickFormat((d) => `${d}`)
      .tickSizeOuter(0),
  );
  styleAxis(ayTop);
  const axBot = child(bot, 'g', 'axis-x').attr('transform', `translate(0,${hBot})`);
  axBot.call(
    axisBottom(x)
      .tickValues(xTicks)
      .tickFormat((d) => `${d}`)
      .tickSizeOuter(0),
  );
  styleAxis(axBot);
  const ayBot = child(bot, 'g', 'axis-y');
  const detLabels = decadeLabels(detTicks);
  ayBot.call(
    axisLeft(yDet)
      .tickValues(detTicks)
      .tickFormat((_d, i) => detLabels[i])
      .tickSizeOuter(0),
  );
  styleAxis(ayBot);

  // Iterations: step lines centred on each sample; a negative count would be a gap.
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

  const detGen = line<number>()
    .defined((i) => Number.isFinite(data.detJ[i]))
    .x((i) => x(data.theta2Deg[i]))
    .y((i) => yDet(Math.max(d0, data.detJ[i])));
  const detIdx = Array.from({ length: Math.min(n, data.detJ.length) }, (_v, i) => i);
  child(bot, 'path', 'detj')
    .attr('fill', 'none')
    .attr('stroke', CHART_STYLE.residual)
    .attr('stroke-width', 1.75)
    .attr('stroke-linejoin', 'round')
    .attr('d', detGen(detIdx) ?? '');

  // Markers over both panels: input limits (dashed grey) and the current input angle (orange).
  const limits = data.limitsDeg.filter(Number.isFinite).map(toAxisDeg);
  const markers = child(plot, 'g', 'markers');
  markers
    .selectAll<SVGLineElement, number>('line.limit')
    .data(limits)
    .join('line')
    .attr('class', 'limit')
    .attr('x1', (d) => x(d))
    .attr('x2', (d) => x(d))
    .attr('y1', 0)
    .attr('y2', yBot0 + hBot)
    .attr('stroke', CHART_STYLE.tolerance)
    .attr('stroke-width', 1.25)
    .attr('stroke-dasharray', '5 4');
  const cur = data.currentDeg;
  markers
    .selectAll<SVGLineElement, number>('line.current')
    .data(cur !== undefined && Number.isFinite(cur) ? [toAxisDeg(cur)] : [])
    .join('line')
    .attr('class', 'current')
    .attr('x1', (d) => x(d))
    .attr('x2', (d) => x(d))
    .attr('y1', 0)
    .attr('y2', yBot0 + hBot)
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
