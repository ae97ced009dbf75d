import { quantileSorted } from 'd3-array';
import { scaleLinear } from 'd3-scale';
import type { ChartSpec, ChartScales, GSel } from './chart';
import { createChart } from './chart';
import { minus } from './chartFrame';
import type { AngleChartOptions, Theta2Chart, Theta2ChartData } from './theta2Chart';
import { NO_THETA2_DATA, solidMarker, theta2Frame } from './theta2Chart';

/** One curve of a rate (rad/s or rad/s², NaN where not assembled or at a limit) against theta2. */
export interface RateCurve {
  label: string;
  values: ArrayLike<number>;
  color: string;
  /** Drawn thin and dashed: the other branch, for reference. */
  faint?: boolean;
}

/** Data of a rate chart: theta2 samples in degrees (0 to 360), the curves and where the y axis may start. */
export interface RateChartData extends Theta2ChartData<RateCurve> {
  /** The y domain's fixed lower end, for values that cannot fall below it (magnitudes: 0); default from the data. */
  yFloor?: number;
}

/** Options of createRateChart: the angle chart's (sizes in CSS pixels, its defaults). */
export type RateChartOptions = AngleChartOptions;

/** The marker: current theta2 (degrees) and each solid series' current value (NaN when undetermined). */
export interface RateMarker {
  theta2Deg: number;
  values: number[];
}

/** A live rate chart: the θ2 chart's handle for rate curves. */
export type RateChart = Theta2Chart<RateCurve, RateMarker>;

/** Quantiles the clipped domain is built on, and how many of their spreads it may reach beyond them. */
export const ROBUST_QUANTILES = [0.05, 0.95] as const;
export const ROBUST_REACH = 1;

/**
 * The y domain: the data's range when it is compact; where a few samples run away (near a limit position)
 * the range is cut at the 5 % and 95 % quantiles widened by ROBUST_REACH times their spread, then padded by
 * 6 % and made nice for about count ticks. [-1, 1] with no finite data; a constant curve gets +-10 % (or +-1).
 * With a floor the domain starts at exactly floor (no padding below it) and only its top is padded and made nice.
 */
export function rateDomain(series: readonly RateCurve[], count = 6, floor?: number): [number, number] {
  const vals: number[] = [];
  for (const s of series) {
    for (let i = 0; i < s.values.length; i++) {
      const v = s.values[i];
      if (Number.isFinite(v)) vals.push(v);
    }
  }
  if (vals.length === 0) return floor === undefined ? [-1, 1] : [floor, floor + 1];
  vals.sort((a, b) => a - b);
  const min = vals[0];
  const max = vals[vals.length - 1];
  const qlo = quantileSorted(vals, ROBUST_QUANTILES[0]) ?? min;
  const qhi = quantileSorted(vals, ROBUST_QUANTILES[1]) ?? max;
  const spread = qhi - qlo;
  let lo = Math.max(min, qlo - ROBUST_REACH * spread);
  let hi = Math.min(max, qhi + ROBUST_REACH * spread);
  if (floor !== undefined) {
    lo = floor;
    hi = Math.max(hi, floor);
  }
  if (!(hi > lo)) {
    const d = Math.abs(lo) > 0 ? Math.abs(lo) * 0.1 : 1;
    if (floor === undefined) lo -= d;
    hi += d;
  }
  const pad = (hi - lo) * 0.06;
  const [niceLo, niceHi] = scaleLinear()
    .domain([floor ?? lo - pad, hi + pad])
    .nice(count)
    .domain();
  // nice may step a floor that is not on the tick lattice down past it; the floor holds.
  return [floor ?? niceLo, niceHi];
}

/** Where a curve leaves the y domain: theta2 (degrees) of the crossing or of the first sample outside, and the side. */
export interface ClipMark {
  theta2Deg: number;
  side: 'above' | 'below';
}

/**
 * The places a curve leaves [lo, hi]: between an inside and an outside sample at the interpolated crossing,
 * and where an outside run starts after a gap or at the first sample. Runs outside are marked once.
 */
export function clipMarks(
  theta2Deg: ArrayLike<number>,
  values: ArrayLike<number>,
  domain: [number, number],
): ClipMark[] {
  const [lo, hi] = domain;
  const out: ClipMark[] = [];
  const n = Math.min(theta2Deg.length, values.length);
  const side = (v: number): 'above' | 'below' | null => (v > hi ? 'above' : v < lo ? 'below' : null);
  for (let i = 0; i < n; i++) {
    const v = values[i];
    if (!Number.isFinite(v)) continue;
    const s = side(v);
    if (!s) continue;
    const p = i > 0 ? values[i - 1] : Number.NaN;
    if (Number.isFinite(p) && side(p) === s) continue;
    if (Number.isFinite(p) && side(p) === null) {
      const edge = s === 'above' ? hi : lo;
      const f = (edge - p) / (v - p);
      out.push({ theta2Deg: theta2Deg[i - 1] + f * (theta2Deg[i] - theta2Deg[i - 1]), side: s });
    } else {
      out.push({ theta2Deg: theta2Deg[i], side: s });
    }
  }
  return out;
}

/** A small triangle on the edge each solid curve leaves the plot through, pointing outwards (clipMarks). */
function drawClipMarks(g: GSel, data: RateChartData, frame: ChartScales): void {
  const { x, ih } = frame;
  const domain = frame.y.domain() as [number, number];
  const marks = data.series
    .filter((d) => !d.faint)
    .flatMap((d) => clipMarks(data.theta2Deg, d.values, domain).map((m) => ({ ...m, color: d.color })));
  g.selectAll<SVGPathElement, ClipMark & { color: string }>('path')
    .data(marks)
    .join('path')
    .attr('fill', (d) => d.color)
    .attr('d', (d) => {
      const cx = x(d.theta2Deg);
      return d.side === 'above'
        ? `M${cx - 4},6L${cx + 4},6L${cx},0Z`
        : `M${cx - 4},${ih - 6}L${cx + 4},${ih - 6}L${cx},${ih}Z`;
    });
  // e2e reads how many marks there are.
  const svg = g.node()?.ownerSVGElement;
  if (svg) svg.dataset.clipMarks = String(marks.length);
}

/**
 * The rate chart as a spec of the θ2 chart: y from rateDomain (starting at data.yFloor when set) with d3's ticks and
 * tick format, curves clipped to the plot, a triangle where a solid curve leaves it (clipMarks), a dot on each solid
 * curve.
 */
export const rateSpec: ChartSpec<RateChartData, RateMarker> = {
  frame(data, plot) {
    const domain = rateDomain(data.series, plot.yCount, data.yFloor);
    return theta2Frame(plot, { domain, ticks: scaleLinear().domain(domain).ticks(plot.yCount) });
  },
  yTickFormat(frame) {
    const f = frame.y.tickFormat(frame.yTicks.length);
    return (d) => minus(f(d));
  },
  curves: (data) => data.series.map((s) => ({ ...s, x: data.theta2Deg, y: s.values })),
  marker: (m, data) => solidMarker(m.theta2Deg, m.values, data.series),
  clipToPlot: true,
  over: { className: 'clip-marks', draw: drawClipMarks },
};

/**
 * Creates a rate chart in svg: curves of ω or α against theta2 with axes, grid, legend and a current-theta2
 * marker, on a y domain that stays readable near limit positions (rateDomain): curves are clipped to the
 * plot and a small triangle marks each place a solid curve leaves it (clipMarks). Returns the handle.
 */
export function createRateChart(svg: SVGSVGElement, options: RateChartOptions): RateChart {
  const { title, xLabel, yLabel, ...rest } = options;
  return createChart(svg, rest, { title, xLabel, yLabel }, rateSpec, NO_THETA2_DATA);
}
