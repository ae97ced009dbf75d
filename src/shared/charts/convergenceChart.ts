import { axisBottom, axisLeft } from 'd3-axis';
import { select } from 'd3-selection';
import type { Selection } from 'd3-selection';
import type { Margins } from './chartFrame';
import type { ChartScales } from './chart';
import {
  CHART_STYLE,
  child,
  drawChartText,
  drawGridY,
  drawLegend,
  estimateTextWidth,
  minus,
  prepareSvg,
  sameChartTexts,
  styleAxis,
} from './chartFrame';
import { dec, decadeTicks, fittedTicks, integerTicks, niceLogDomain, tickCount } from './ticks';
import type { ScaleContinuousNumeric, ScaleLinear } from 'd3-scale';
import { scaleLinear, scaleLog } from 'd3-scale';
import { linePath } from './line';

/** One NR run: residual norm |f| (length unit) at each iteration, 0 = the start. */
export interface ConvergenceRun {
  label: string;
  iterations: number[];
  residuals: number[];
  color: string;
  faint?: boolean;
}

/** Data of the convergence chart: the runs and the convergence tolerance (length unit; no line when absent or not finite). */
export interface ConvergenceChartData {
  runs: ConvergenceRun[];
  tolerance?: number;
}

/** Texts of the convergence chart. */
export interface ConvergenceChartText {
  title: string;
  xLabel: string;
  yLabel: string;
  /** Label of the dashed tolerance line; default none. */
  toleranceLabel?: string;
  /** Text shown in the middle when there is no run to plot; default none. */
  emptyText?: string;
}

/** Options of createConvergenceChart; sizes in CSS pixels. */
export interface ConvergenceChartOptions extends ConvergenceChartText {
  /** Chart width; 0 (not laid out yet) draws nothing until resize. */
  width: number;
  /** Chart height; 0 (not laid out yet) draws nothing until resize. */
  height: number;
  /** Default { top: 46, right: 14, bottom: 40, left: 64 }. */
  margins?: Margins;
  /** Pixels of plot width per iteration tick; default 40. */
  xTickSpacing?: number;
  /** Pixels of plot height per decade tick; default 22. */
  yTickSpacing?: number;
}

/** A live convergence chart made by createConvergenceChart; every method redraws only what its change touches. */
export interface ConvergenceChart {
  /** Replaces the runs and tolerance; the axes are redrawn only when their domain changes. */
  update(data: ConvergenceChartData): void;
  /** Sets the chart size in CSS pixels; a no-op when unchanged. */
  resize(width: number, height: number): void;
  /** Sets the texts; only the texts are redrawn. */
  setText(text: ConvergenceChartText): void;
  /** A copy of the x scale (iteration to plot pixels) or the y scale (residual, log, to plot pixels). */
  scale(name: 'x'): ScaleLinear<number, number>;
  scale(name: 'y'): ScaleContinuousNumeric<number, number>;
}

const DEFAULT_MARGINS: Margins = { top: 46, right: 14, bottom: 40, left: 64 };
const DEFAULT_X_TICK_SPACING = 40;
const DEFAULT_Y_TICK_SPACING = 22;

/**
 * Log-scale y domain for residuals: the positive residuals and the tolerance widened to whole decades
 * (d3's scaleLog nice), then one decade lower, because exact zeros are drawn on the floor.
 */
export function residualDomain(runs: readonly ConvergenceRun[], tolerance?: number): [number, number] {
  let lo = Infinity;
  let hi = 0;
  for (const r of runs) {
    for (const v of r.residuals) {
      if (!(v > 0) || !Number.isFinite(v)) continue;
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
  }
  if (tolerance !== undefined && tolerance > 0 && Number.isFinite(tolerance)) {
    lo = Math.min(lo, tolerance);
    hi = Math.max(hi, tolerance);
  }
  if (!(hi > 0) || !Number.isFinite(lo)) return [1e-16, 1];
  const [d0, d1] = niceLogDomain(lo, hi);
  const floor = dec(1, Math.round(Math.log10(d0)) - 1);
  return [floor, Math.max(d1, dec(1, Math.round(Math.log10(floor)) + 1))];
}

/** Formats a power of ten as 1e-3 (typographic minus); other values are not labelled. */
export function formatPowerOfTen(v: number): string {
  const e = Math.round(Math.log10(v));
  return Math.abs(v / 10 ** e - 1) < 1e-9 ? minus(`1e${e}`) : '';
}

/** Size options of the convergence chart with every default filled in (CSS pixels). */
interface ConvergenceSize {
  width: number;
  height: number;
  margins: Margins;
  xTickSpacing: number;
  yTickSpacing: number;
}

/** The plot area (pixels inside the margins), the scales and the ticks of the convergence chart. */
export interface ConvergenceFrame extends Omit<ChartScales, 'y'> {
  /** Residual (log) to plot pixels. */
  y: ScaleContinuousNumeric<number, number>;
}

/** Scales and ticks for these runs at this size: x 0..last iteration, y residualDomain; tick counts follow the pixel size. */
export function convergenceFrame(data: ConvergenceChartData, size: ConvergenceSize): ConvergenceFrame {
  const m = size.margins;
  const iw = Math.max(10, size.width - m.left - m.right);
  const ih = Math.max(10, size.height - m.top - m.bottom);
  const maxIt = Math.max(1, ...data.runs.map((r) => (r.iterations.length ? r.iterations[r.iterations.length - 1] : 0)));
  const x = scaleLinear().domain([0, maxIt]).range([0, iw]);
  const [d0, d1] = residualDomain(data.runs, data.tolerance);
  const y = scaleLog().domain([d0, d1]).range([ih, 0]).clamp(true);
  return {
    iw,
    ih,
    x,
    y,
    xTicks: fittedTicks(
      (c) => integerTicks(0, maxIt, c),
      x,
      (t) => estimateTextWidth(`${t}`),
      tickCount(iw, size.xTickSpacing),
    ),
    yTicks: decadeTicks(d0, d1, tickCount(ih, size.yTickSpacing)),
  };
}

/** One dot of a run: iteration, residual, colour and whether the run is faint. */
type RunDot = [number, number, string, boolean];

type G = Selection<SVGGElement, unknown, null, undefined>;

/** The groups of the convergence chart's SVG, made once in their drawing order. */
function convergenceParts(svg: SVGSVGElement) {
  const s = select(svg);
  child(s, 'rect', 'bg'); // first child, so the background stays under the plot
  const plot = child(s, 'g', 'plot');
  const grid = child(plot, 'g', 'grid');
  const ax = child(plot, 'g', 'axis-x');
  const ay = child(plot, 'g', 'axis-y');
  const tolG = child(plot, 'g', 'tolerance');
  const runsG = child(plot, 'g', 'runs');
  return { s, plot, grid, ax, ay, tolG, runsG };
}

/** The groups of a convergence chart's SVG. */
type ConvergenceParts = ReturnType<typeof convergenceParts>;

/** Draws the axes and the grid, each only when its key (size, domain, ticks) differs from the last drawn. */
function drawConvergenceAxes(parts: ConvergenceParts, frame: ConvergenceFrame, keys: { x: string; y: string }): void {
  const { iw, ih, x, y, xTicks, yTicks } = frame;
  const xKey = `${iw} ${ih} ${x.domain().join(',')} ${xTicks.join(',')}`;
  if (xKey !== keys.x) {
    keys.x = xKey;
    parts.ax.attr('transform', `translate(0,${ih})`).call(
      axisBottom(x)
        .tickValues(xTicks)
        .tickFormat((d) => `${d}`)
        .tickSizeOuter(0),
    );
    styleAxis(parts.ax);
  }
  const yKey = `${iw} ${ih} ${y.domain().join(',')} ${yTicks.join(',')}`;
  if (yKey !== keys.y) {
    keys.y = yKey;
    drawGridY(parts.grid, iw, yTicks, y);
    parts.ay.call(
      axisLeft(y)
        .tickValues(yTicks)
        .tickFormat((d) => formatPowerOfTen(Number(d)))
        .tickSizeOuter(0),
    );
    styleAxis(parts.ay);
  }
}

/** The dashed tolerance line and its label at the right end; nothing when the tolerance is absent or not finite. */
function drawTolerance(tolG: G, frame: ConvergenceFrame, tol: number | undefined, label: string): void {
  const { iw, y } = frame;
  const tolData = tol !== undefined && tol > 0 && Number.isFinite(tol) ? [tol] : [];
  tolG
    .selectAll<SVGLineElement, number>('line')
    .data(tolData)
    .join('line')
    .attr('x1', 0)
    .attr('x2', iw)
    .attr('y1', (d) => y(d))
    .attr('y2', (d) => y(d))
    .attr('stroke', CHART_STYLE.tolerance)
    .attr('stroke-dasharray', '5 4');
  tolG
    .selectAll<SVGTextElement, number>('text')
    .data(tolData)
    .join('text')
    .attr('x', iw - 4)
    .attr('y', (d) => y(d) - 4)
    .attr('text-anchor', 'end')
    .attr('fill', CHART_STYLE.muted)
    .text(label);
}

/** One group per run: its line (faint runs dashed and thinner) and a dot per iteration, hollow where |f| is 0. */
function drawRunLines(runsG: G, runs: readonly ConvergenceRun[], frame: ConvergenceFrame): void {
  const { x, y } = frame;
  const d0 = y.domain()[0];
  const floor = (v: number) => (v > 0 && Number.isFinite(v) ? v : d0);
  const path = (r: ConvergenceRun) =>
    linePath(
      r.iterations,
      (it) => x(it),
      (_it, i) => y(floor(r.residuals[i])),
    );
  const runSel = runsG
    .selectAll<SVGGElement, ConvergenceRun>('g.run')
    .data(runs)
    .join((enter) => {
      const g = enter.append('g').attr('class', 'run');
      g.append('path');
      return g;
    });
  runSel
    .select('path')
    .attr('fill', 'none')
    .attr('stroke', (d) => d.color)
    .attr('stroke-width', (d) => (d.faint ? 1 : 1.75))
    .attr('stroke-dasharray', (d) => (d.faint ? '4 3' : null))
    .attr('stroke-opacity', (d) => (d.faint ? 0.6 : 1))
    .attr('d', path);
  runSel
    .selectAll<SVGCircleElement, RunDot>('circle')
    .data((d) => d.iterations.map((it, i): RunDot => [it, d.residuals[i], d.color, d.faint === true]))
    .join('circle')
    .attr('cx', (d) => x(d[0]))
    .attr('cy', (d) => y(floor(d[1])))
    .attr('r', (d) => (d[3] ? 2 : 3))
    .attr('fill', (d) => (d[1] > 0 ? d[2] : CHART_STYLE.background))
    .attr('stroke', (d) => d[2])
    .attr('stroke-width', 1.25);
}

/** Size options with their defaults filled in. */
function convergenceSize(options: ConvergenceChartOptions): ConvergenceSize {
  return {
    width: Math.max(0, options.width),
    height: Math.max(0, options.height),
    margins: options.margins ?? DEFAULT_MARGINS,
    xTickSpacing: options.xTickSpacing ?? DEFAULT_X_TICK_SPACING,
    yTickSpacing: options.yTickSpacing ?? DEFAULT_Y_TICK_SPACING,
  };
}

/**
 * Creates the NR convergence chart in svg (residual |f| against iteration on a log scale, the tolerance
 * as a dashed line, zero residuals on the floor) and returns its handle; the scales live in the handle.
 * Options are read once here. Draws nothing while width or height is 0.
 */
export function createConvergenceChart(svg: SVGSVGElement, options: ConvergenceChartOptions): ConvergenceChart {
  let size = convergenceSize(options);
  let text: ConvergenceChartText = { ...options };
  let data: ConvergenceChartData = { runs: [] };
  let frame = convergenceFrame(data, size);
  // What the axes and legend were last drawn for: they are redrawn only when this changes.
  const keys = { x: '', y: '', legend: '' };
  let wasEmpty: boolean | null = null;
  const laidOut = () => size.width > 0 && size.height > 0;
  const parts = convergenceParts(svg);

  const drawRuns = () => {
    drawTolerance(parts.tolG, frame, data.tolerance, text.toleranceLabel ?? '');
    drawRunLines(parts.runsG, data.runs, frame);
    const key = data.runs.map((d) => `${d.label}|${d.color}|${d.faint === true}`).join('\n');
    if (key !== keys.legend) {
      keys.legend = key;
      drawLegend(parts.s, data.runs, 14, 33);
    }
  };
  const drawText = () => {
    const m = size.margins;
    const empty = data.runs.length === 0;
    wasEmpty = empty;
    const centerY = m.top + frame.ih / 2;
    drawChartText(
      parts.s,
      { title: text.title, xLabel: text.xLabel, yLabels: [{ text: text.yLabel, centerY }] },
      m.left,
      frame.iw,
      size.width,
      size.height,
      { plot: parts.plot, text: empty ? (text.emptyText ?? '') : null, centerY },
    );
  };
  const drawAll = () => {
    if (!laidOut()) return;
    prepareSvg(svg, size.width, size.height);
    parts.plot.attr('transform', `translate(${size.margins.left},${size.margins.top})`);
    drawConvergenceAxes(parts, frame, keys);
    drawRuns();
    drawText();
  };

  drawAll();
  return {
    update(next) {
      data = next;
      frame = convergenceFrame(data, size);
      if (!laidOut()) return;
      drawConvergenceAxes(parts, frame, keys);
      drawRuns();
      if (wasEmpty !== (data.runs.length === 0)) drawText();
    },
    resize(width, height) {
      if (width === size.width && height === size.height) return;
      size = { ...size, width, height };
      frame = convergenceFrame(data, size);
      drawAll();
    },
    setText(next) {
      if (sameChartTexts(next, text)) return;
      const labelChanged = next.toleranceLabel !== text.toleranceLabel;
      text = { ...next };
      if (!laidOut()) return;
      drawText();
      if (labelChanged) drawRuns();
    },
    scale: ((name: 'x' | 'y') => (name === 'x' ? frame.x.copy() : frame.y.copy())) as ConvergenceChart['scale'],
  };
}

/** Draws a complete convergence chart into svg in one call (the off-screen path of PNG export) and returns its handle. */
export function drawConvergenceChart(
  svg: SVGSVGElement,
  data: ConvergenceChartData,
  options: ConvergenceChartOptions,
): ConvergenceChart {
  const chart = createConvergenceChart(svg, options);
  chart.update(data);
  return chart;
}
