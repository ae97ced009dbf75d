import { axisBottom, axisLeft } from 'd3-axis';
import { scaleLinear, scaleLog } from 'd3-scale';
import { line } from 'd3-shape';
import type { Margins } from './chartFrame';
import {
  CHART_STYLE,
  child,
  drawLegend,
  minus,
  prepareSvg,
  styleAxis,
  drawGridLines,
  drawChartText,
} from './chartFrame';

/** One NR run: residual norm |f| (length unit) at each iteration, 0 = the start. */
export interface ConvergenceRun {
  label: string;
  iterations: number[];
  residuals: number[];
  color: string;
  faint?: boolean;
}

/** Options of drawConvergenceChart; sizes in CSS pixels. */
export interface ConvergenceChartOptions {
  width: number;
  height: number;
  title: string;
  xLabel: string;
  yLabel: string;
  /** Convergence tolerance drawn as a dashed line (length unit); omitted when not finite. */
  tolerance?: number;
  toleranceLabel?: string;
  /** Text shown in the middle when there is no run to plot. */
  emptyText?: string;
  /** Default { top: 46, right: 14, bottom: 40, left: 64 }. */
  margins?: Margins;
}

const DEFAULT_MARGINS: Margins = { top: 46, right: 14, bottom: 40, left: 64 };

/**
 * Log-scale y domain for residuals: from a power of ten at or below the smallest positive value
 * (or the tolerance) to one at or above the largest. Exact zeros are drawn at the floor, so the floor
 * sits one decade below the smallest positive residual.
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
  const d0 = 10 ** (Math.floor(Math.log10(lo)) - 1);
  let d1 = 10 ** Math.ceil(Math.log10(hi));
  if (d1 <= d0) d1 = d0 * 10;
  return [d0, d1];
}

/** Formats a power of ten as 1e-3 (typographic minus); other values are not labelled. */
export function formatPowerOfTen(v: number): string {
  const e = Math.round(Math.log10(v));
  return Math.abs(v / 10 ** e - 1) < 1e-9 ? minus(`1e${e}`) : '';
}

/**
 * Draws (or redraws in place) the NR convergence chart: residual |f| against iteration on a log scale,
 * like the report's figure 4.3, with the tolerance as a dashed line. Zero residuals sit on the floor.
 */
export function drawConvergenceChart(
  svg: SVGSVGElement,
  runs: ConvergenceRun[],
  options: ConvergenceChartOptions,
): void {
  const m = options.margins ?? DEFAULT_MARGINS;
  const { width, height } = options;
  const s = prepareSvg(svg, width, height);
  const iw = Math.max(10, width - m.left - m.right);
  const ih = Math.max(10, height - m.top - m.bottom);
  const maxIt = Math.max(1, ...runs.map((r) => (r.iterations.length ? r.iterations[r.iterations.length - 1] : 0)));
  const x = scaleLinear().domain([0, maxIt]).range([0, iw]);
  const [d0, d1] = residualDomain(runs, options.tolerance);
  const y = scaleLog().domain([d0, d1]).range([ih, 0]).clamp(true);
  const plot = child(s, 'g', 'plot').attr('transform', `translate(${m.left},${m.top})`);

  const decades: number[] = [];
  const e0 = Math.round(Math.log10(d0));
  const e1 = Math.round(Math.log10(d1));
  const every = Math.max(1, Math.ceil((e1 - e0) / 8));
  for (let e = e0; e <= e1; e += every) decades.push(10 ** e);
  const xTicks = x.ticks(Math.min(maxIt, 10)).filter((t) => Number.isInteger(t));

  const grid = child(plot, 'g', 'grid');
  drawGridLines(grid, iw, ih, decades, y);

  const ax = child(plot, 'g', 'axis-x').attr('transform', `translate(0,${ih})`);
  ax.call(
    axisBottom(x)
      .tickValues(xTicks)
      .tickFormat((d) => `${d}`)
      .tickSizeOuter(0),
  );
  styleAxis(ax);
  const ay = child(plot, 'g', 'axis-y');
  ay.call(
    axisLeft(y)
      .tickValues(decades)
      .tickFormat((d) => formatPowerOfTen(Number(d)))
      .tickSizeOuter(0),
  );
  styleAxis(ay);

  const tol = options.tolerance;
  const tolG = child(plot, 'g', 'tolerance');
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
    .text(options.toleranceLabel ?? '');

  const floor = (v: number) => (v > 0 && Number.isFinite(v) ? v : d0);
  const gen = line<[number, number]>()
    .x((d) => x(d[0]))
    .y((d) => y(floor(d[1])));
  const runsG = child(plot, 'g', 'runs');
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
    .attr('d', (d) => gen(d.iterations.map((it, i) => [it, d.residuals[i]] as [number, number])) ?? '');
  runSel
    .selectAll<SVGCircleElement, [number, number, string, boolean]>('circle')
    .data((d) =>
      d.iterations.map((it, i) => [it, d.residuals[i], d.color, d.faint === true] as [number, number, string, boolean]),
    )
    .join('circle')
    .attr('cx', (d) => x(d[0]))
    .attr('cy', (d) => y(floor(d[1])))
    .attr('r', (d) => (d[3] ? 2 : 3))
    .attr('fill', (d) => (d[1] > 0 ? d[2] : '#ffffff'))
    .attr('stroke', (d) => d[2])
    .attr('stroke-width', 1.25);

  drawChartText(
    s,
    { title: options.title, xLabel: options.xLabel, yLabels: [{ text: options.yLabel, centerY: m.top + ih / 2 }] },
    m.left,
    iw,
    width,
    height,
    { plot, text: runs.length === 0 ? (options.emptyText ?? '') : null, centerY: m.top + ih / 2 },
  );

  drawLegend(s, runs, 14, 33);
}
