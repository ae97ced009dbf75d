import { scaleLinear } from 'd3-scale';
import type { Chart, ChartOptions, ChartSpec, ChartTexts, Curve, ChartScales, MarkerAt, PlotArea } from './chart';
import { createChart } from './chart';
import { estimateTextWidth } from './chartFrame';
import type { AngleAxis } from './ticks';
import { angleAxis, angleTicks, fittedTicks } from './ticks';

/**
 * The θ2 chart: the kit's skeleton (createChart) with θ2 in degrees, 0 to 360, along x. The angle chart
 * is its simplest spec; the rate chart (rateChart.ts) and the transmission chart (transmissionChart.ts)
 * are specs of it too.
 */

/** One curve of output angle (degrees, wrapped to (-180, 180], NaN where the linkage cannot assemble) against theta2. */
export interface AngleSeries {
  label: string;
  valuesDeg: ArrayLike<number>;
  color: string;
  /** Drawn thin and dashed: the other branch, for reference. */
  faint?: boolean;
}

/** What a θ2 chart of several curves draws: θ2 samples (degrees, 0 to 360) and the curves. */
export interface Theta2ChartData<S> {
  theta2Deg: ArrayLike<number>;
  series: S[];
}

/** Data of an angle chart: theta2 samples in degrees (0 to 360) and the curves. */
export type AngleChartData = Theta2ChartData<AngleSeries>;

/** Texts of an angle chart (and of every θ2 chart): title and axis labels. */
export type AngleChartText = ChartTexts;

/** Options of createAngleChart: size (CSS pixels), texts, dead-centre rules, marker host. */
export type AngleChartOptions = ChartOptions & ChartTexts;

/**
 * The marker: current theta2 (degrees) and, for each solid (not faint) series in order, its current
 * value (degrees, NaN when not assembled); the dot takes that series' colour.
 */
export interface AngleMarker {
  theta2Deg: number;
  valuesDeg: number[];
}

/** A live chart of curves against θ2 (angle or rate). */
export type Theta2Chart<S, M> = Chart<Theta2ChartData<S>, M, ChartTexts>;

/** A live angle chart made by createAngleChart. */
export type AngleChart = Theta2Chart<AngleSeries, AngleMarker>;

/** No data yet: what a θ2 chart of curves shows before its first update. */
export const NO_THETA2_DATA: Theta2ChartData<never> = { theta2Deg: [], series: [] };

/** The θ2 axis of a plot area: 0..360 degrees across iw, ticks on the angle lattice whose labels fit (about xCount). */
export function theta2XAxis(plot: PlotArea): Pick<ChartScales, 'x' | 'xTicks'> {
  const x = scaleLinear().domain([0, 360]).range([0, plot.iw]);
  const xTicks = fittedTicks(
    (c) => angleTicks(0, 360, c),
    x,
    (t) => estimateTextWidth(`${t}`),
    plot.xCount,
  );
  return { x, xTicks };
}

/** The frame of a θ2 chart: the θ2 axis and a y axis of this domain and ticks over ih. */
export function theta2Frame(plot: PlotArea, yAxis: AngleAxis): Omit<ChartScales, 'iw' | 'ih'> {
  const y = scaleLinear().domain(yAxis.domain).range([plot.ih, 0]);
  return { ...theta2XAxis(plot), y, yTicks: yAxis.ticks };
}

/**
 * y axis in degrees: the data's range padded by 8 % (at least 5 degrees) and widened by d3's nice to the
 * tick step of about count ticks (angleAxis), within [-180, 180], with its ticks; the full range when empty.
 */
export function angleYAxis(series: readonly AngleSeries[], count = 6): AngleAxis {
  let lo = Infinity;
  let hi = -Infinity;
  for (const s of series) {
    for (let i = 0; i < s.valuesDeg.length; i++) {
      const v = s.valuesDeg[i];
      if (!Number.isFinite(v)) continue;
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
  }
  if (!(lo <= hi)) return angleAxis(-180, 180, count);
  const pad = Math.max(5, (hi - lo) * 0.08);
  return angleAxis(lo - pad, hi + pad, count);
}

/** The marker of a θ2 chart of several curves: a dot for each solid series in order, at the marker's value of it. */
export function solidMarker(
  theta2Deg: number,
  values: readonly number[],
  series: readonly { color: string; faint?: boolean }[],
): MarkerAt {
  const solid = series.filter((s) => !s.faint);
  return { x: theta2Deg, dots: values.slice(0, solid.length).map((y, i) => ({ y, color: solid[i].color })) };
}

/** The angle chart's curves: each series against θ2, wrapped at +-180. */
function angleCurves(data: AngleChartData): Curve[] {
  return data.series.map((s) => ({ ...s, x: data.theta2Deg, y: s.valuesDeg, wrapped: true }));
}

/** The angle chart as a spec: y from angleYAxis, curves wrapped at +-180, a dot on each solid curve. */
export const angleSpec: ChartSpec<AngleChartData, AngleMarker> = {
  frame: (data, plot) => theta2Frame(plot, angleYAxis(data.series, plot.yCount)),
  curves: angleCurves,
  marker: (m, data) => solidMarker(m.theta2Deg, m.valuesDeg, data.series),
};

/**
 * Creates an angle chart in svg (curves of output angle against theta2 with axes, grid, legend, dead-centre
 * rules and a current-theta2 marker) and returns its handle.
 */
export function createAngleChart(svg: SVGSVGElement, options: AngleChartOptions): AngleChart {
  const { title, xLabel, yLabel, ...rest } = options;
  return createChart(svg, rest, { title, xLabel, yLabel }, angleSpec, NO_THETA2_DATA);
}
