import { extent } from 'd3-array';
import { scaleLinear } from 'd3-scale';
import type { ScaleContinuousNumeric, ScaleLinear } from 'd3-scale';
import type { Chart, ChartOptions, ChartSpec, ChartTexts, ChartScales, MarkerAt, PlotArea } from './chart';
import { createChart } from './chart';
import { estimateTextWidth, minus } from './chartFrame';
import { fittedTicks } from './ticks';

/**
 * The x–y chart: the kit's skeleton with both axes linear from the data, for plots whose x is not θ2
 * (the synthesis page's structural error against x with its precision points) and, with equalAspect,
 * geometry and polar diagrams (a bearing load F12 drawn as (Fx, Fy) round the origin).
 */

/** One series: y against x (same length, any units; NaN in either is a gap), as a line, dots or both. */
export interface XYSeries {
  label: string;
  color: string;
  x: ArrayLike<number>;
  y: ArrayLike<number>;
  /** Drawn thin and dashed, for reference; default false. */
  faint?: boolean;
  /** Draw the line; default true. */
  line?: boolean;
  /** A dot at every finite point (precision points); default false. */
  dots?: boolean;
}

/** Data of an x–y chart. */
export interface XYChartData {
  series: XYSeries[];
  /** The x domain these data are plotted on (an input's reachable range), not padded or made nice; default the fit's. */
  xDomain?: [number, number];
}

/** How an x–y chart fits its data: equal units per pixel on both axes, the origin in view. */
export interface XYFit {
  /** One unit is as long on x as on y (polar and geometry plots); the shorter axis' domain is widened about its centre; default false. */
  equalAspect?: boolean;
  /** Both domains hold 0 (a polar diagram's centre); default false. */
  includeOrigin?: boolean;
  /** A fixed x domain (θ2 from 0 to 360°), not padded or made nice; default from the data. */
  xDomain?: [number, number];
}

/** Options of createXYChart: size (CSS pixels), texts, x rules, marker host and the fit. */
export interface XYChartOptions extends ChartOptions, ChartTexts, XYFit {}

/** A live x–y chart; its marker is a vertical line at x with dots at given y (data units). */
export type XYChart = Chart<XYChartData, MarkerAt>;

/** The finite values of one coordinate of every series. */
function finiteValues(series: readonly XYSeries[], key: 'x' | 'y'): number[] {
  const out: number[] = [];
  for (const s of series) for (let i = 0; i < s[key].length; i++) if (Number.isFinite(s[key][i])) out.push(s[key][i]);
  return out;
}

/**
 * A data range padded by 5 % each side (a single value by 10 % of itself, or 1), holding 0 when asked;
 * [-1, 1] (or [0, 1] with the origin) without finite data.
 */
export function paddedExtent(values: readonly number[], includeOrigin = false): [number, number] {
  let [lo, hi] = extent(values);
  if (lo === undefined || hi === undefined) return includeOrigin ? [0, 1] : [-1, 1];
  if (includeOrigin) {
    lo = Math.min(lo, 0);
    hi = Math.max(hi, 0);
  }
  if (!(hi > lo)) {
    const d = Math.abs(lo) > 0 ? Math.abs(lo) * 0.1 : 1;
    return [lo - d, hi + d];
  }
  const pad = (hi - lo) * 0.05;
  return [lo - pad, hi + pad];
}

/** Widens the domain with fewer units per pixel about its centre, so both axes have the same units per pixel. */
export function equalAspectDomains(
  x: [number, number],
  y: [number, number],
  iw: number,
  ih: number,
): { x: [number, number]; y: [number, number] } {
  const k = Math.max((x[1] - x[0]) / iw, (y[1] - y[0]) / ih);
  const widen = (d: [number, number], px: number): [number, number] => {
    const c = (d[0] + d[1]) / 2;
    return [c - (k * px) / 2, c + (k * px) / 2];
  };
  return { x: widen(x, iw), y: widen(y, ih) };
}

/** Ticks of a linear scale whose labels (d3's format, sized by labelSize in pixels) keep apart along the axis: at most about count. */
function fittedLinearTicks(
  scale: ScaleLinear<number, number>,
  count: number,
  labelSize: (label: string) => number,
): number[] {
  return fittedTicks(
    (c) => scale.ticks(c),
    scale,
    (t) => labelSize(minus(scale.tickFormat(count)(t))),
    count,
  );
}

/**
 * The x–y frame: both domains from the data (paddedExtent), made nice by d3 for about the ticks that fit,
 * or, with equalAspect, widened to equal units per pixel instead (a nice domain would undo it).
 */
export function xyFrame(data: XYChartData, plot: PlotArea, fit: XYFit = {}): Omit<ChartScales, 'iw' | 'ih'> {
  // The data's own domain (the reachable range of an input that rocks) wins over the fit's full turn.
  const fixedX = data.xDomain ?? fit.xDomain;
  let xd = fixedX ?? paddedExtent(finiteValues(data.series, 'x'), fit.includeOrigin);
  let yd = paddedExtent(finiteValues(data.series, 'y'), fit.includeOrigin);
  if (fit.equalAspect) ({ x: xd, y: yd } = equalAspectDomains(xd, yd, plot.iw, plot.ih));
  const x = scaleLinear().domain(xd).range([0, plot.iw]);
  const y = scaleLinear().domain(yd).range([plot.ih, 0]);
  if (!fit.equalAspect) {
    if (!fixedX) x.nice(plot.xCount);
    y.nice(plot.yCount);
  }
  // y labels stack vertically: they need the font's height between them, not their width.
  const xTicks = fittedLinearTicks(x, plot.xCount, (s) => estimateTextWidth(s));
  const yTicks = fittedLinearTicks(y, plot.yCount, () => 14);
  return { x, y, xTicks, yTicks };
}

/** d3's tick format for a scale's ticks, with a typographic minus. */
const tickFormatOf = (scale: ScaleContinuousNumeric<number, number>, ticks: readonly number[]) => {
  const f = scale.tickFormat(Math.max(1, ticks.length));
  return (d: number) => minus(f(d));
};

/** The x–y chart as a spec, for this fit. */
export function xySpec(fit: XYFit = {}): ChartSpec<XYChartData, MarkerAt> {
  return {
    frame: (data, plot) => xyFrame(data, plot, fit),
    curves: (data) => data.series.map((s) => ({ ...s })),
    xTickFormat: (frame) => tickFormatOf(frame.x, frame.xTicks),
    yTickFormat: (frame) => tickFormatOf(frame.y, frame.yTicks),
    marker: (m) => m,
    clipToPlot: true,
  };
}

/**
 * Creates an x–y chart in svg: series as lines with gaps and dots, both axes linear from the data (equal
 * aspect and the origin on request), grid, legend, x rules and a marker; returns its handle (scales in it).
 */
export function createXYChart(svg: SVGSVGElement, options: XYChartOptions): XYChart {
  const { title, xLabel, yLabel, equalAspect, includeOrigin, xDomain, ...rest } = options;
  const spec = xySpec({ equalAspect, includeOrigin, xDomain });
  return createChart(svg, rest, { title, xLabel, yLabel }, spec, { series: [] });
}
