import { axisBottom, axisLeft } from 'd3-axis';
import { select } from 'd3-selection';
import type { Selection } from 'd3-selection';
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
import type { AngleAxis } from './ticks';
import { angleAxis, angleTicks, fittedTicks, tickCount } from './ticks';
import type { MarkerDotPx, MarkerPlacement } from './markerLayer';
import { chartMarker } from './markerLayer';
import type { XMark } from './xMarks';
import { drawXMarks } from './xMarks';
import type { ScaleLinear } from 'd3-scale';
import { scaleLinear } from 'd3-scale';
import { linePath } from './line';

/** One curve of output angle (degrees, wrapped to (-180, 180], NaN where the linkage cannot assemble) against theta2. */
export interface AngleSeries {
  label: string;
  valuesDeg: ArrayLike<number>;
  color: string;
  /** Drawn thin and dashed: the other branch, for reference. */
  faint?: boolean;
}

/** Data of an angle chart: theta2 samples in degrees (0 to 360) and the curves. */
export type AngleChartData = Theta2ChartData<AngleSeries>;

/** Texts of an angle chart. */
export interface AngleChartText {
  title: string;
  xLabel: string;
  yLabel: string;
}

/** Options of createAngleChart; sizes in CSS pixels. */
export interface AngleChartOptions extends AngleChartText {
  /** Chart width; 0 (not laid out yet) draws nothing until resize. */
  width: number;
  /** Chart height; 0 (not laid out yet) draws nothing until resize. */
  height: number;
  /** Default { top: 46, right: 14, bottom: 40, left: 50 }. */
  margins?: Margins;
  /** Pixels of plot width per x tick, at most xMaxTicks; default 40 (60 degree steps from 160 px of plot width up). */
  xTickSpacing?: number;
  /** Most x ticks asked of d3, so a wide chart keeps 60 degree steps; default 8. */
  xMaxTicks?: number;
  /** Pixels of plot height per y tick; default 34. */
  yTickSpacing?: number;
  /** Faint vertical rules on the theta2 axis (dead centres); default none. */
  xMarks?: readonly XMark[];
  /** A box laid over the SVG to draw the marker in (on screen: moving it repaints nothing); default inside the SVG. */
  markerHost?: HTMLElement;
}

/**
 * The marker: current theta2 (degrees) and, for each solid (not faint) series in order, its current
 * value (degrees, NaN when not assembled); the dot takes that series' colour.
 */
export interface AngleMarker {
  theta2Deg: number;
  valuesDeg: number[];
}

/** A live angle chart made by createAngleChart. */
export type AngleChart = Theta2Chart<AngleSeries, AngleMarker>;

const DEFAULT_MARGINS: Margins = { top: 46, right: 14, bottom: 40, left: 50 };
const DEFAULT_X_TICK_SPACING = 40;
const DEFAULT_X_MAX_TICKS = 8;
const DEFAULT_Y_TICK_SPACING = 34;

/**
 * Points of a wrapped angle curve ready for d3's line with defined(): NaN samples become gaps, and where
 * the angle wraps between two samples (a jump of more than 180 degrees) the curve runs to the +-180 edge,
 * breaks and continues from the opposite edge, so no vertical stroke crosses the plot.
 */
export function wrappedSegments(x: ArrayLike<number>, yDeg: ArrayLike<number>): [number, number][] {
  const out: [number, number][] = [];
  const n = Math.min(x.length, yDeg.length);
  for (let i = 0; i < n; i++) {
    const y = yDeg[i];
    if (i > 0) {
      const y0 = yDeg[i - 1];
      if (Number.isFinite(y0) && Number.isFinite(y) && Math.abs(y - y0) > 180) {
        const up = y < y0; // e.g. 179 -> -179: the unwrapped angle goes up through 180
        const yUnwrapped = up ? y + 360 : y - 360;
        const edge = up ? 180 : -180;
        const f = (edge - y0) / (yUnwrapped - y0);
        const xe = x[i - 1] + f * (x[i] - x[i - 1]);
        out.push([xe, edge], [xe, Number.NaN], [xe, -edge]);
      }
    }
    out.push([x[i], Number.isFinite(y) ? y : Number.NaN]);
  }
  return out;
}

/**
 * Indices to plot when a series has more samples than the chart has pixels: every k-th sample for at
 * most maxPoints, plus the first and last sample of every assembled run (so gaps start and end where
 * they really do) and both samples around every wrap (so the edge crossing is placed exactly).
 */
export function plotIndices(yDeg: ArrayLike<number>, maxPoints: number): number[] {
  const n = yDeg.length;
  const out: number[] = [];
  if (n <= maxPoints) {
    for (let i = 0; i < n; i++) out.push(i);
    return out;
  }
  const stride = Math.ceil(n / Math.max(2, maxPoints));
  for (let i = 0; i < n; i++) {
    const y = yDeg[i];
    const fin = Number.isFinite(y);
    const prevFin = i > 0 && Number.isFinite(yDeg[i - 1]);
    const nextFin = i < n - 1 && Number.isFinite(yDeg[i + 1]);
    const edge = fin && (!prevFin || !nextFin);
    const wrap = fin && ((prevFin && Math.abs(y - yDeg[i - 1]) > 180) || (nextFin && Math.abs(yDeg[i + 1] - y) > 180));
    if (i % stride === 0 || i === n - 1 || edge || wrap || (!fin && prevFin)) out.push(i);
  }
  return out;
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

/** Size options of an angle chart with every default filled in (CSS pixels). */
export interface AngleChartSize {
  width: number;
  height: number;
  margins: Margins;
  xTickSpacing: number;
  xMaxTicks: number;
  yTickSpacing: number;
}

/** Fills in the documented defaults of the size options. */
export function angleChartSize(options: Omit<AngleChartOptions, keyof AngleChartText | 'xMarks'>): AngleChartSize {
  return {
    width: Math.max(0, options.width),
    height: Math.max(0, options.height),
    margins: options.margins ?? DEFAULT_MARGINS,
    xTickSpacing: options.xTickSpacing ?? DEFAULT_X_TICK_SPACING,
    xMaxTicks: options.xMaxTicks ?? DEFAULT_X_MAX_TICKS,
    yTickSpacing: options.yTickSpacing ?? DEFAULT_Y_TICK_SPACING,
  };
}

/** The plot area (pixels inside the margins), the scales and the ticks of an angle chart. */
export interface AngleFrame {
  iw: number;
  ih: number;
  x: ScaleLinear<number, number>;
  y: ScaleLinear<number, number>;
  xTicks: number[];
  yTicks: number[];
}

/** Scales and ticks for these curves at this size: x 0..360 degrees, y from angleYAxis; tick counts follow the pixel size. */
export function angleFrame(series: readonly AngleSeries[], size: AngleChartSize): AngleFrame {
  const m = size.margins;
  const iw = Math.max(10, size.width - m.left - m.right);
  const ih = Math.max(10, size.height - m.top - m.bottom);
  const xCount = Math.min(size.xMaxTicks, tickCount(iw, size.xTickSpacing));
  const x = scaleLinear().domain([0, 360]).range([0, iw]);
  const yAxis = angleYAxis(series, tickCount(ih, size.yTickSpacing));
  const y = scaleLinear().domain(yAxis.domain).range([ih, 0]);
  const xTicks = fittedTicks(
    (c) => angleTicks(0, 360, c),
    x,
    (t) => estimateTextWidth(`${t}`),
    xCount,
  );
  return { iw, ih, x, y, xTicks, yTicks: yAxis.ticks };
}

/** SVG path data of one curve in plot pixels: gaps where NaN, breaks at wraps, at most two samples per pixel. */
export function seriesPath(theta2Deg: ArrayLike<number>, valuesDeg: ArrayLike<number>, frame: AngleFrame): string {
  const { x, y } = frame;
  // At most two samples per horizontal pixel: n = 3600 on a 300 px chart would only cost time.
  const idx = plotIndices(valuesDeg, Math.max(64, Math.round(2 * frame.iw)));
  const xs = idx.map((i) => theta2Deg[i]);
  const ys = idx.map((i) => valuesDeg[i]);
  // Hundredths of a pixel: finer digits only lengthen the path text the browser parses on every redraw.
  return linePath(
    wrappedSegments(xs, ys),
    (d) => x(d[0]),
    (d) => y(d[1]),
    (d) => Number.isFinite(d[1]),
    2,
  );
}

/** Where the marker goes: its line's x (null when hidden) and a dot on each solid series whose value is finite and in the y domain. */
export function markerGeometry(
  marker: AngleMarker | null,
  series: readonly Pick<AngleSeries, 'color' | 'faint'>[],
  frame: Pick<AngleFrame, 'x' | 'y'>,
): MarkerPlacement {
  if (!marker || !Number.isFinite(marker.theta2Deg)) return { x: null, dots: [] };
  const cx = frame.x(Math.min(360, Math.max(0, marker.theta2Deg)));
  const [y0, y1] = frame.y.domain();
  const solid = series.filter((s) => !s.faint);
  const dots: MarkerDotPx[] = [];
  marker.valuesDeg.forEach((v, i) => {
    if (i < solid.length && Number.isFinite(v) && v >= y0 && v <= y1) {
      dots.push({ cx, cy: frame.y(v), color: solid[i].color });
    }
  });
  return { x: cx, dots };
}

/** What the θ2 charts (angle and rate) draw: θ2 samples (degrees) and the curves. */
export interface Theta2ChartData<S> {
  theta2Deg: ArrayLike<number>;
  series: S[];
}

/** A live chart against θ2; every method redraws only what its change touches. */
export interface Theta2Chart<S, M> {
  /** Replaces the curves; the axes are redrawn only when their domain, ticks or size change. */
  update(data: Theta2ChartData<S>): void;
  /** Moves the current-theta2 marker (null hides it); nothing else is redrawn. */
  setMarker(marker: M | null): void;
  /** Sets the chart size in CSS pixels; a no-op when unchanged. */
  resize(width: number, height: number): void;
  /** Sets the title and axis labels; a no-op when unchanged. */
  setText(text: AngleChartText): void;
  /** Replaces the faint theta2 rules (dead centres); nothing else is redrawn. */
  setXMarks(marks: readonly XMark[]): void;
  /** A copy of the x scale (theta2 degrees to plot pixels) or the y scale (the quantity to plot pixels). */
  scale(name: 'x' | 'y'): ScaleLinear<number, number>;
}

/** What makes a θ2 chart an angle chart or a rate chart: its y axis, its curves and its marker. */
export interface Theta2ChartSpec<S extends Pick<AngleSeries, 'label' | 'color' | 'faint'>, M> {
  /** Scales and ticks for these curves at this size. */
  frame(series: readonly S[], size: AngleChartSize): AngleFrame;
  /** The y tick labels of a frame. */
  yTickFormat(frame: AngleFrame): (value: number) => string;
  /** SVG path data of one curve in plot pixels. */
  path(series: S, theta2Deg: ArrayLike<number>, frame: AngleFrame): string;
  /** The marker as the angle chart's: θ2 and each solid series' value. */
  marker(marker: M): AngleMarker;
  /** Clips the curves to the plot and calls this after drawing them (the rate chart's out-of-range marks). */
  clipped?: (g: Selection<SVGGElement, unknown, null, undefined>, data: Theta2ChartData<S>, frame: AngleFrame) => void;
}

let clipCounter = 0;

/**
 * Creates a chart of curves against θ2 in svg (axes, grid, legend, dead-centre rules and a current-theta2
 * marker) and returns its handle; the scales live in the handle. The spec says what is plotted. Options are
 * read once here; resize and setText change size and texts later. Draws nothing while width or height is 0.
 */
export function createTheta2Chart<S extends Pick<AngleSeries, 'label' | 'color' | 'faint'>, M>(
  svg: SVGSVGElement,
  options: AngleChartOptions,
  spec: Theta2ChartSpec<S, M>,
): Theta2Chart<S, M> {
  let size = angleChartSize(options);
  let text: AngleChartText = { title: options.title, xLabel: options.xLabel, yLabel: options.yLabel };
  let data: Theta2ChartData<S> = { theta2Deg: [], series: [] };
  let marker: M | null = null;
  let xMarks: readonly XMark[] = options.xMarks ?? [];
  let frame = spec.frame(data.series, size);
  // What the axes and legend were last drawn for: they are redrawn only when this changes.
  let xAxisKey = '';
  let yAxisKey = '';
  let legendKey = '';
  const laidOut = () => size.width > 0 && size.height > 0;

  const s = select(svg);
  child(s, 'rect', 'bg'); // first child, so the background stays under the plot
  const clipId = `theta2-clip-${++clipCounter}`;
  const clipPath = spec.clipped ? child(child(s, 'defs', 'defs'), 'clipPath', 'clip').attr('id', clipId) : null;
  const clipRect = clipPath ? child(clipPath, 'rect', 'clip-rect') : null;
  const plot = child(s, 'g', 'plot');
  const gridX = child(plot, 'g', 'grid-x');
  const gridY = child(plot, 'g', 'grid-y');
  const ax = child(plot, 'g', 'axis-x');
  const ay = child(plot, 'g', 'axis-y');
  const marksG = child(plot, 'g', 'x-marks');
  const lines = child(plot, 'g', 'lines');
  const after = spec.clipped ? child(plot, 'g', 'clip-marks') : null;
  if (clipPath) lines.attr('clip-path', `url(#${clipId})`);
  const mark = chartMarker(plot.node() as SVGGElement, options.markerHost);

  const drawAxes = () => {
    const { iw, ih, x, y, xTicks, yTicks } = frame;
    clipRect?.attr('x', 0).attr('y', 0).attr('width', iw).attr('height', ih);
    const xKey = `${iw} ${ih} ${xTicks.join(',')}`;
    if (xKey !== xAxisKey) {
      xAxisKey = xKey;
      drawGridX(gridX, ih, xTicks, x);
      ax.attr('transform', `translate(0,${ih})`).call(
        axisBottom(x)
          .tickValues(xTicks)
          .tickFormat((d) => `${d}`)
          .tickSizeOuter(0),
      );
      styleAxis(ax);
    }
    const yKey = `${iw} ${ih} ${y.domain().join(',')} ${yTicks.join(',')}`;
    if (yKey !== yAxisKey) {
      yAxisKey = yKey;
      drawGridY(gridY, iw, yTicks, y);
      const yFormat = spec.yTickFormat(frame);
      ay.call(
        axisLeft(y)
          .tickValues(yTicks)
          .tickFormat((d) => yFormat(Number(d)))
          .tickSizeOuter(0),
      );
      styleAxis(ay);
    }
  };

  const drawLines = () => {
    lines
      .selectAll<SVGPathElement, S>('path')
      .data(data.series)
      .join('path')
      .attr('fill', 'none')
      .attr('stroke', (d) => d.color)
      .attr('stroke-width', (d) => (d.faint ? 1 : 1.75))
      .attr('stroke-dasharray', (d) => (d.faint ? '4 3' : null))
      .attr('stroke-opacity', (d) => (d.faint ? 0.55 : 1))
      .attr('stroke-linejoin', 'round')
      .attr('d', (d) => spec.path(d, data.theta2Deg, frame));
    if (after) spec.clipped?.(after, data, frame);
    const key = data.series.map((d) => `${d.label}|${d.color}|${d.faint === true}`).join('\n');
    if (key !== legendKey) {
      legendKey = key;
      drawLegend(s, data.series, 14, 33);
    }
  };

  const drawMarker = () => {
    const { left, top } = size.margins;
    const at = marker === null ? null : spec.marker(marker);
    mark.draw(markerGeometry(at, data.series, frame), { left, top, height: frame.ih }, size.width, size.height);
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
    drawXMarks(marksG, xMarks, frame.x, frame.ih);
    drawMarker();
  };

  drawAll();
  return {
    update(next) {
      data = next;
      frame = spec.frame(data.series, size);
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
      frame = spec.frame(data.series, size);
      drawAll();
    },
    setText(next) {
      if (next.title === text.title && next.xLabel === text.xLabel && next.yLabel === text.yLabel) return;
      text = { ...next };
      if (laidOut()) drawText();
    },
    setXMarks(next) {
      xMarks = next;
      if (laidOut()) drawXMarks(marksG, xMarks, frame.x, frame.ih);
    },
    scale(name) {
      return (name === 'x' ? frame.x : frame.y).copy();
    },
  };
}

/**
 * Creates an angle chart in svg (curves of output angle against theta2 with axes, grid, legend, dead-centre
 * rules and a current-theta2 marker) and returns its handle.
 */
export function createAngleChart(svg: SVGSVGElement, options: AngleChartOptions): AngleChart {
  return createTheta2Chart<AngleSeries, AngleMarker>(svg, options, {
    frame: angleFrame,
    yTickFormat: () => (d) => minus(`${d}`),
    path: (series, theta2Deg, frame) => seriesPath(theta2Deg, series.valuesDeg, frame),
    marker: (m) => m,
  });
}

/** Draws a whole chart in one call (the off-screen path of PNG and SVG export): its update and marker. */
export function drawChart<D, M, C extends { update(data: D): void; setMarker(marker: M | null): void }>(
  chart: C,
  data: D,
  marker: M | null,
): C {
  chart.update(data);
  chart.setMarker(marker);
  return chart;
}

/** Draws a complete angle chart into svg in one call (the off-screen path of PNG export) and returns its handle. */
export function drawAngleChart(
  svg: SVGSVGElement,
  data: AngleChartData,
  marker: AngleMarker | null,
  options: AngleChartOptions,
): AngleChart {
  return drawChart(createAngleChart(svg, options), data, marker);
}
