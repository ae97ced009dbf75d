import { quantileSorted } from 'd3-array';
import { axisBottom, axisLeft } from 'd3-axis';
import { select } from 'd3-selection';
import type { AngleChartSize, AngleFrame } from './angleChart';
import { angleChartSize, markerGeometry, plotIndices } from './angleChart';
import type { Margins } from './chartFrame';
import {
  child,
  drawChartText,
  drawGridX,
  drawGridY,
  drawLegend,
  estimateTextWidth,
  minus,
  prepareSvg,
  styleAxis,
} from './chartFrame';
import { chartMarker } from './markerLayer';
import { angleTicks, fittedTicks, tickCount } from './ticks';
import type { LinearScale } from './scales';
import { linearScale, niceLinearDomain } from './scales';
import { linePath } from './linePath';

/** One curve of a rate (rad/s or rad/s², NaN where not assembled or at a limit) against theta2. */
export interface RateSeries {
  label: string;
  values: ArrayLike<number>;
  color: string;
  /** Drawn thin and dashed: the other branch, for reference. */
  faint?: boolean;
}

/** Data of a rate chart: theta2 samples in degrees (0 to 360) and the curves. */
export interface RateChartData {
  theta2Deg: ArrayLike<number>;
  series: RateSeries[];
}

/** Texts of a rate chart. */
export interface RateChartText {
  title: string;
  xLabel: string;
  yLabel: string;
}

/** Options of createRateChart; sizes in CSS pixels, defaults as the angle chart's (angleChartSize). */
export interface RateChartOptions extends RateChartText {
  width: number;
  height: number;
  margins?: Margins;
  xTickSpacing?: number;
  xMaxTicks?: number;
  yTickSpacing?: number;
  /** A box laid over the SVG to draw the marker in (on screen); default inside the SVG. */
  markerHost?: HTMLElement;
}

/** The marker: current theta2 (degrees) and each solid series' current value (NaN when undetermined). */
export interface RateMarker {
  theta2Deg: number;
  values: number[];
}

/** A live rate chart; the same handle as the angle chart's: each method redraws only what its change touches. */
export interface RateChart {
  update(data: RateChartData): void;
  setMarker(marker: RateMarker | null): void;
  resize(width: number, height: number): void;
  setText(text: RateChartText): void;
  /** A copy of the x scale (theta2 degrees to pixels) or the y scale (rate to pixels). */
  scale(name: 'x' | 'y'): LinearScale;
}

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
  return niceLinearDomain(lo - pad, hi + pad, count);
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
  const x = linearScale([0, 360], [0, iw]);
  const yCount = tickCount(ih, size.yTickSpacing);
  const y = linearScale(rateDomain(series, yCount), [ih, 0]);
  const xTicks = fittedTicks(
    (c) => angleTicks(0, 360, c),
    x,
    (t) => estimateTextWidth(`${t}`),
    xCount,
  );
  return { iw, ih, x, y, xTicks, yTicks: y.ticks(yCount) };
}

/** Formats a y tick: d3's tick format for the domain, with a typographic minus. */
function yTickFormat(y: LinearScale, count: number): (d: number) => string {
  const f = y.tickFormat(count);
  return (d) => minus(f(d));
}

const EMPTY_DATA: RateChartData = { theta2Deg: [], series: [] };
let clipCounter = 0;

/**
 * Creates a rate chart in svg: curves of ω or α against theta2 with axes, grid, legend and a current-theta2
 * marker, on a y domain that stays readable near limit positions (rateDomain): curves are clipped to the
 * plot and a small triangle marks each place a solid curve leaves it (clipMarks). Returns the handle.
 */
export function createRateChart(svg: SVGSVGElement, options: RateChartOptions): RateChart {
  let size = angleChartSize(options);
  let text: RateChartText = { title: options.title, xLabel: options.xLabel, yLabel: options.yLabel };
  let data = EMPTY_DATA;
  let marker: RateMarker | null = null;
  let frame = rateFrame(data.series, size);
  let legendKey = '';
  const laidOut = () => size.width > 0 && size.height > 0;
  const clipId = `rate-clip-${++clipCounter}`;

  const s = select(svg);
  child(s, 'rect', 'bg');
  const defs = child(s, 'defs', 'defs');
  const clipRect = child(child(defs, 'clipPath', 'clip').attr('id', clipId), 'rect', 'clip-rect');
  const plot = child(s, 'g', 'plot');
  const gridX = child(plot, 'g', 'grid-x');
  const gridY = child(plot, 'g', 'grid-y');
  const ax = child(plot, 'g', 'axis-x');
  const ay = child(plot, 'g', 'axis-y');
  const lines = child(plot, 'g', 'lines').attr('clip-path', `url(#${clipId})`);
  const clips = child(plot, 'g', 'clip-marks');
  const mark = chartMarker(plot.node() as SVGGElement, options.markerHost);

  const drawAxes = () => {
    const { iw, ih, x, y, xTicks, yTicks } = frame;
    clipRect.attr('x', 0).attr('y', 0).attr('width', iw).attr('height', ih);
    drawGridX(gridX, ih, xTicks, x);
    ax.attr('transform', `translate(0,${ih})`).call(
      axisBottom(x)
        .tickValues(xTicks)
        .tickFormat((d) => `${d}`)
        .tickSizeOuter(0),
    );
    styleAxis(ax);
    drawGridY(gridY, iw, yTicks, y);
    ay.call(axisLeft(y).tickValues(yTicks).tickFormat(yTickFormat(y, yTicks.length)).tickSizeOuter(0));
    styleAxis(ay);
  };

  const drawLines = () => {
    const { x, y } = frame;
    const path = (values: ArrayLike<number>) => {
      const idx = plotIndices(values, Math.max(64, Math.round(2 * frame.iw)));
      // Hundredths of a pixel: finer digits only lengthen the path text the browser parses on every redraw.
      return linePath(
        idx,
        (i) => x(data.theta2Deg[i]),
        (i) => y(values[i]),
        (i) => Number.isFinite(values[i]),
        2,
      );
    };
    lines
      .selectAll<SVGPathElement, RateSeries>('path')
      .data(data.series)
      .join('path')
      .attr('fill', 'none')
      .attr('stroke', (d) => d.color)
      .attr('stroke-width', (d) => (d.faint ? 1 : 1.75))
      .attr('stroke-dasharray', (d) => (d.faint ? '4 3' : null))
      .attr('stroke-opacity', (d) => (d.faint ? 0.55 : 1))
      .attr('stroke-linejoin', 'round')
      .attr('d', (d) => path(d.values));
    const domain = y.domain() as [number, number];
    const marks = data.series
      .filter((d) => !d.faint)
      .flatMap((d) => clipMarks(data.theta2Deg, d.values, domain).map((m) => ({ ...m, color: d.color })));
    clips
      .selectAll<SVGPathElement, ClipMark & { color: string }>('path')
      .data(marks)
      .join('path')
      .attr('fill', (d) => d.color)
      .attr('d', (d) => {
        const cx = x(d.theta2Deg);
        // A small triangle on the edge the curve leaves through, pointing outwards.
        return d.side === 'above'
          ? `M${cx - 4},6L${cx + 4},6L${cx},0Z`
          : `M${cx - 4},${frame.ih - 6}L${cx + 4},${frame.ih - 6}L${cx},${frame.ih}Z`;
      });
    svg.dataset.clipMarks = String(marks.length);
    const key = data.series.map((d) => `${d.label}|${d.color}|${d.faint === true}`).join('\n');
    if (key !== legendKey) {
      legendKey = key;
      drawLegend(s, data.series, 14, 33);
    }
  };

  const drawMarker = () => {
    const box = { left: size.margins.left, top: size.margins.top, height: frame.ih };
    const at = marker ? { theta2Deg: marker.theta2Deg, valuesDeg: marker.values } : null;
    mark.draw(markerGeometry(at, data.series, frame), box, size.width, size.height);
  };

  const drawText = () => {
    const m = size.margins;
    drawChartText(
      s,
      { title: text.title, xLabel: text.xLabel, yLabels: [{ text: text.yLabel, centerY: m.top + frame.ih / 2 }] },
      m.left,
      frame.iw,
      size.width,
      size.height,
    );
  };

  const drawAll = () => {
    if (!laidOut()) return;
    prepareSvg(svg, size.width, size.height);
    plot.attr('transform', `translate(${size.margins.left},${size.margins.top})`);
    drawAxes();
    drawLines();
    drawText();
    drawMarker();
  };

  drawAll();
  return {
    update(next) {
      data = next;
      frame = rateFrame(data.series, size);
      if (!laidOut()) return;
      drawAxes();
      drawLines();
      drawMarker();
    },
    setMarker(next) {
      marker = next;
      if (laidOut()) drawMarker();
    },
    resize(width, height) {
      if (width === size.width && height === size.height) return;
      size = angleChartSize({ ...size, width, height });
      frame = rateFrame(data.series, size);
      drawAll();
    },
    setText(next) {
      if (next.title === text.title && next.xLabel === text.xLabel && next.yLabel === text.yLabel) return;
      text = { ...next };
      if (laidOut()) drawText();
    },
    scale(name) {
      return (name === 'x' ? frame.x : frame.y).copy();
    },
  };
}

/**
 * Draws a complete rate chart into svg in one call (the off-screen path of PNG and SVG export) and returns its
 * handle: createRateChart, update(data), setMarker(marker).
 */
export function drawRateChart(
  svg: SVGSVGElement,
  data: RateChartData,
  marker: RateMarker | null,
  options: RateChartOptions,
): RateChart {
  const chart = createRateChart(svg, options);
  chart.update(data);
  chart.setMarker(marker);
  return chart;
}
