import { scaleLinear, scaleLog } from 'd3-scale';
import type { Chart, ChartScales, ChartSizeOptions, ChartSpec, ChartTexts, GSel, PlotArea } from './chart';
import { createChart } from './chart';
import { CHART_STYLE, drawHLines, estimateTextWidth, minus } from './chartFrame';
import { dec, decadeTicks, fittedTicks, integerTicks, niceLogDomain } from './ticks';

/**
 * The NR convergence chart: the kit's skeleton (createChart) with the residual |f| on a log y against the
 * iteration, exact zeros on the floor (hollow dots), the tolerance as a dashed line and an empty state.
 */

/** One NR run: residual norm |f| (length unit) at each iteration, 0 = the start. */
export interface ConvergenceRun {
  label: string;
  iterations: number[];
  residuals: number[];
  color: string;
  faint?: boolean;
}

/**
 * Data of the convergence chart: the runs and the convergence tolerance (length unit; no line when absent or not
 * finite) with the label written at its right end (default none).
 */
export interface ConvergenceChartData {
  runs: ConvergenceRun[];
  tolerance?: number;
  toleranceLabel?: string;
}

/** Texts of the convergence chart. */
export interface ConvergenceChartText extends ChartTexts {
  /** Text shown in the middle when there is no run to plot; default none. */
  emptyText?: string;
}

/** A live convergence chart made by createConvergenceChart (no marker). */
export type ConvergenceChart = Chart<ConvergenceChartData, never, ConvergenceChartText>;

/** Size options of the convergence chart: room on the left for 1e−16, a decade tick per 22 px of height. */
export const CONVERGENCE_SIZE: Omit<ChartSizeOptions, 'width' | 'height'> = {
  margins: { top: 46, right: 14, bottom: 40, left: 64 },
  xTickSpacing: 40,
  xMaxTicks: Infinity,
  yTickSpacing: 22,
};

/** No run yet: what the chart shows before its first update. */
export const NO_CONVERGENCE_DATA: ConvergenceChartData = { runs: [] };

/** The tolerance when it can be drawn (positive and finite), else undefined. */
const drawnTolerance = (tol: number | undefined) =>
  tol !== undefined && tol > 0 && Number.isFinite(tol) ? tol : undefined;

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
  const tol = drawnTolerance(tolerance);
  if (tol !== undefined) {
    lo = Math.min(lo, tol);
    hi = Math.max(hi, tol);
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

/**
 * The convergence chart's frame: x 0..last iteration with whole-number ticks whose labels fit, y residualDomain
 * (log) with decade ticks, its floor at the domain's foot (exact zeros are drawn there).
 */
export function convergenceFrame(data: ConvergenceChartData, plot: PlotArea): Omit<ChartScales, 'iw' | 'ih'> {
  const maxIt = Math.max(1, ...data.runs.map((r) => (r.iterations.length ? r.iterations[r.iterations.length - 1] : 0)));
  const x = scaleLinear().domain([0, maxIt]).range([0, plot.iw]);
  const [d0, d1] = residualDomain(data.runs, data.tolerance);
  const y = scaleLog().domain([d0, d1]).range([plot.ih, 0]);
  return {
    x,
    y,
    xTicks: fittedTicks(
      (c) => integerTicks(0, maxIt, c),
      x,
      (t) => estimateTextWidth(`${t}`),
      plot.xCount,
    ),
    yTicks: decadeTicks(d0, d1, plot.yCount),
    // Always the domain's foot: a floor shown only while some run has an exact zero made the axis flip between two
    // layouts as θ2 stepped between poses that converge to 0 and poses that stop at 1e-17.
    yFloor: d0,
  };
}

/** The dashed tolerance line and its label at the right end; nothing when the tolerance is absent or not finite. */
function drawTolerance(g: GSel, data: ConvergenceChartData, frame: ChartScales): void {
  const { iw, y } = frame;
  const tol = drawnTolerance(data.tolerance);
  const shown = tol === undefined ? [] : [tol];
  drawHLines(g, 'tol', shown, iw, y, CHART_STYLE.tolerance, '5 4');
  g.selectAll<SVGTextElement, number>('text')
    .data(shown)
    .join('text')
    .attr('x', iw - 4)
    .attr('y', (d) => y(d) - 4)
    .attr('text-anchor', 'end')
    .attr('fill', CHART_STYLE.muted)
    .text(data.toleranceLabel ?? '');
}

/** The convergence chart as a spec: a line and a dot per iteration for each run, the tolerance over them. */
export const convergenceSpec: ChartSpec<ConvergenceChartData, never, ConvergenceChartText> = {
  frame: convergenceFrame,
  curves: (data) =>
    data.runs.map((r) => ({
      label: r.label,
      color: r.color,
      faint: r.faint,
      x: r.iterations,
      y: r.residuals,
      dots: true,
    })),
  xTickFormat: () => (v) => `${v}`,
  yTickFormat: () => formatPowerOfTen,
  empty: (data, text) => (data.runs.length === 0 ? (text.emptyText ?? '') : null),
  over: { className: 'tolerance', draw: drawTolerance },
};

/**
 * Creates the NR convergence chart in svg at width x height CSS pixels (0: not laid out yet, nothing drawn until
 * resize) with these texts, and returns its handle; the scales live in the handle.
 */
export function createConvergenceChart(
  svg: SVGSVGElement,
  width: number,
  height: number,
  text: ConvergenceChartText,
): ConvergenceChart {
  return createChart(svg, { ...CONVERGENCE_SIZE, width, height }, text, convergenceSpec, NO_CONVERGENCE_DATA);
}
