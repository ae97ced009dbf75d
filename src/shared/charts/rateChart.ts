import { quantileSorted } from 'd3-array';
import type { Selection } from 'd3-selection';
import type { AngleChartOptions, AngleChartSize, AngleFrame, Theta2Chart, Theta2ChartData } from './theta2Chart';
import { createTheta2Chart, drawChart, plotIndices } from './theta2Chart';
import { estimateTextWidth, minus } from './chartFrame';
import { angleTicks, fittedTicks, tickCount } from './ticks';
import type { ScaleLinear } from 'd3-scale';
import { scaleLinear } from 'd3-scale';
import { linePath } from './line';

/** One curve of a rate (rad/s or rad/s², NaN where not assembled or at a limit) against theta2. */
export interface RateSeries {
  label: string;
  values: ArrayLike<number>;
  color: string;
  /** Drawn thin and dashed: the other branch, for reference. */
  faint?: boolean;
}

/** Data of a rate chart: theta2 samples in degrees (0 to 360) and the curves. */
export type RateChartData = Theta2ChartData<RateSeries>;

/** Options of createRateChart: the angle chart's (sizes in CSS pixels, its defaults). */
export type RateChartOptions = AngleChartOptions;

/** The marker: current theta2 (degrees) and each solid series' current value (NaN when undetermined). */
export interface RateMarker {
  theta2Deg: number;
  values: number[];
}

/** A live rate chart: the angle chart's handle (createTheta2Chart) for rate curves. */
export type RateChart = Theta2Chart<RateSeries, RateMarker>;

/** Quantiles the clipped domain is built on, and how many of their spreads it may reach beyond them. */
export const ROBUST_QUANTILES = [0.05, 0.95] as const;
export const ROBUST_REACH = 1;

/**
 * The y domain: the data's range when it is compact; where a few samples run away (near a limit position)
 * the range is cut at the 5 % and 95 % quantiles widened by ROBUST_REACH times their spread, then padded by
 * 6 % and made nice for about count ticks. [-1, 1] with no finite data; a constant curve gets +-10 % (or +-1).
 */
export function rateDomain(series: readonly RateSeries[], count = 6): [number, number] {
  const vals: number[] = [];
  for (const s of series) {
    for (let i = 0; i < s.values.length; i++) {
      const v = s.values[i];
      if (Number.isFinite(v)) vals.push(v);
    }
  }
  if (vals.length === 0) return [-1, 1];
  vals.sort((a, b) => a - b);
  const min = vals[0];
  const max = vals[vals.length - 1];
  const qlo = quantileSorted(vals, ROBUST_QUANTILES[0]) ?? min;
  const qhi = quantileSorted(vals, ROBUST_QUANTILES[1]) ?? max;
  const spread = qhi - qlo;
  let lo = Math.max(min, qlo - ROBUST_REACH * spread);
  let hi = Math.min(max, qhi + ROBUST_REACH * spread);
  if (!(hi > lo)) {
    const d = Math.abs(lo) > 0 ? Math.abs(lo) * 0.1 : 1;
    lo -= d;
    hi += d;
  }
  const pad = (hi - lo) * 0.06;
  return scaleLinear()
    .domain([lo - pad, hi + pad])
    .nice(count)
    .domain() as [number, number];
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

/** The rate chart's scales and ticks: the angle chart's frame with a rate y scale. */
type RateFrame = AngleFrame;

function rateFrame(series: readonly RateSeries[], size: AngleChartSize): RateFrame {
  const m = size.margins;
  const iw = Math.max(10, size.width - m.left - m.right);
  const ih = Math.max(10, size.height - m.top - m.bottom);
  const xCount = Math.min(size.xMaxTicks, tickCount(iw, size.xTickSpacing));
  const x = scaleLinear().domain([0, 360]).range([0, iw]);
  const yCount = tickCount(ih, size.yTickSpacing);
  const y = scaleLinear().domain(rateDomain(series, yCount)).range([ih, 0]);
  const xTicks = fittedTicks(
    (c) => angleTicks(0, 360, c),
    x,
    (t) => estimateTextWidth(`${t}`),
    xCount,
  );
  return { iw, ih, x, y, xTicks, yTicks: y.ticks(yCount) };
}

/** Formats a y tick: d3's tick format for the domain, with a typographic minus. */
function yTickFormat(y: ScaleLinear<number, number>, count: number): (d: number) => string {
  const f = y.tickFormat(count);
  return (d) => minus(f(d));
}

/** SVG path data of a rate curve in plot pixels: gaps where NaN, at most two samples per pixel. */
function ratePath(values: ArrayLike<number>, theta2Deg: ArrayLike<number>, frame: RateFrame): string {
  const { x, y } = frame;
  const idx = plotIndices(values, Math.max(64, Math.round(2 * frame.iw)));
  // Hundredths of a pixel: finer digits only lengthen the path text the browser parses on every redraw.
  return linePath(
    idx,
    (i) => x(theta2Deg[i]),
    (i) => y(values[i]),
    (i) => Number.isFinite(values[i]),
    2,
  );
}

/** A small triangle on the edge each solid curve leaves the plot through, pointing outwards (clipMarks). */
function drawClipMarks(
  g: Selection<SVGGElement, unknown, null, undefined>,
  data: RateChartData,
  frame: RateFrame,
): void {
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
  const svg = g.node()?.ownerSVGElement;
  if (svg) svg.dataset.clipMarks = String(marks.length);
}

/**
 * Creates a rate chart in svg: curves of ω or α against theta2 with axes, grid, legend and a current-theta2
 * marker, on a y domain that stays readable near limit positions (rateDomain): curves are clipped to the
 * plot and a small triangle marks each place a solid curve leaves it (clipMarks). Returns the handle.
 */
export function createRateChart(svg: SVGSVGElement, options: RateChartOptions): RateChart {
  return createTheta2Chart<RateSeries, RateMarker>(svg, options, {
    frame: rateFrame,
    yTickFormat: (frame) => yTickFormat(frame.y, frame.yTicks.length),
    path: (series, theta2Deg, frame) => ratePath(series.values, theta2Deg, frame),
    marker: (m) => ({ theta2Deg: m.theta2Deg, valuesDeg: m.values }),
    clipped: drawClipMarks,
  });
}

/** Draws a complete rate chart into svg in one call (the off-screen path of PNG and SVG export). */
export function drawRateChart(
  svg: SVGSVGElement,
  data: RateChartData,
  marker: RateMarker | null,
  options: RateChartOptions,
): RateChart {
  return drawChart(createRateChart(svg, options), data, marker);
}
