import { axisBottom, axisLeft } from 'd3-axis';
import { scaleLinear } from 'd3-scale';
import { select } from 'd3-selection';
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

/** One curve of output angle (degrees, wrapped to (-180, 180], NaN where the linkage cannot assemble) against theta2. */
export interface AngleSeries {
  label: string;
  valuesDeg: ArrayLike<number>;
  color: string;
  /** Drawn thin and dashed: the other branch, for reference. */
  faint?: boolean;
}

/** Data of an angle chart: theta2 samples in degrees (0 to 360) and the curves. */
export interface AngleChartData {
  theta2Deg: ArrayLike<number>;
  series: AngleSeries[];
}

/** Options of drawAngleChart; sizes in CSS pixels. */
export interface AngleChartOptions {
  width: number;
  height: number;
  title: string;
  xLabel: string;
  yLabel: string;
  /** Default { top: 46, right: 14, bottom: 40, left: 50 }. */
  margins?: Margins;
}

/** The marker: current theta2 (degrees) and the current value of each series (degrees, NaN when not assembled). */
export interface AngleMarker {
  theta2Deg: number;
  valuesDeg: number[];
}

const DEFAULT_MARGINS: Margins = { top: 46, right: 14, bottom: 40, left: 50 };

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

/** y domain in degrees: the data's range padded and rounded to 30 degrees, within [-180, 180]; full range when empty. */
export function angleDomain(series: readonly AngleSeries[]): [number, number] {
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
  if (!(lo <= hi)) return [-180, 180];
  const pad = Math.max(5, (hi - lo) * 0.08);
  return [Math.max(-180, Math.floor((lo - pad) / 30) * 30), Math.min(180, Math.ceil((hi + pad) / 30) * 30)];
}

/**
 * Draws (or redraws in place) an angle chart into svg: axes with units, light grid, one path per series
 * with gaps where the linkage cannot assemble, and a legend. Call updateAngleMarker to move the marker.
 */
export function drawAngleChart(svg: SVGSVGElement, data: AngleChartData, options: AngleChartOptions): void {
  const m = options.margins ?? DEFAULT_MARGINS;
  const { width, height } = options;
  const s = prepareSvg(svg, width, height);
  const iw = Math.max(10, width - m.left - m.right);
  const ih = Math.max(10, height - m.top - m.bottom);
  const x = scaleLinear().domain([0, 360]).range([0, iw]);
  const y = scaleLinear().domain(angleDomain(data.series)).range([ih, 0]);
  const plot = child(s, 'g', 'plot').attr('transform', `translate(${m.left},${m.top})`);

  const span = y.domain()[1] - y.domain()[0];
  const yStep = span > 180 ? 60 : span > 90 ? 30 : 15;
  const yTicks: number[] = [];
  for (let v = Math.ceil(y.domain()[0] / yStep) * yStep; v <= y.domain()[1]; v += yStep) yTicks.push(v);
  const xTicks = [0, 60, 120, 180, 240, 300, 360];

  const grid = child(plot, 'g', 'grid');
  drawGridLines(grid, iw, ih, yTicks, y, xTicks, x);

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
      .tickValues(yTicks)
      .tickFormat((d) => minus(`${d}`))
      .tickSizeOuter(0),
  );
  styleAxis(ay);

  const gen = line<[number, number]>()
    .defined((d) => Number.isFinite(d[1]))
    .x((d) => x(d[0]))
    .y((d) => y(d[1]));
  const lines = child(plot, 'g', 'lines');
  lines
    .selectAll<SVGPathElement, AngleSeries>('path')
    .data(data.series)
    .join('path')
    .attr('fill', 'none')
    .attr('stroke', (d) => d.color)
    .attr('stroke-width', (d) => (d.faint ? 1 : 1.75))
    .attr('stroke-dasharray', (d) => (d.faint ? '4 3' : null))
    .attr('stroke-opacity', (d) => (d.faint ? 0.55 : 1))
    .attr('stroke-linejoin', 'round')
    .attr('d', (d) => {
      // At most two samples per horizontal pixel: n = 3600 on a 300 px chart would only cost time.
      const idx = plotIndices(d.valuesDeg, Math.max(64, Math.round(2 * iw)));
      const xs = idx.map((i) => data.theta2Deg[i]);
      const ys = idx.map((i) => d.valuesDeg[i]);
      return gen(wrappedSegments(xs, ys)) ?? '';
    });

  drawChartText(
    s,
    { title: options.title, xLabel: options.xLabel, yLabels: [{ text: options.yLabel, centerY: m.top + ih / 2 }] },
    m.left,
    iw,
    width,
    height,
  );

  drawLegend(s, data.series, 14, 33);

  const marker = child(plot, 'g', 'marker');
  child(marker, 'line', 'mline')
    .attr('y1', 0)
    .attr('y2', ih)
    .attr('stroke', CHART_STYLE.marker)
    .attr('stroke-width', 1.25);
  svg.dataset.iw = String(iw);
  svg.dataset.ih = String(ih);
  svg.dataset.y0 = String(y.domain()[0]);
  svg.dataset.y1 = String(y.domain()[1]);
}

/** Moves the current-theta2 marker of a chart drawn by drawAngleChart; dots only where the value is finite. */
export function updateAngleMarker(svg: SVGSVGElement, marker: AngleMarker, colors: readonly string[]): void {
  const iw = Number(svg.dataset.iw);
  const ih = Number(svg.dataset.ih);
  const y0 = Number(svg.dataset.y0);
  const y1 = Number(svg.dataset.y1);
  if (!(iw > 0) || !(ih > 0)) return;
  const plot = svg.querySelector<SVGGElement>(':scope > g.plot');
  const g = plot?.querySelector<SVGGElement>(':scope > g.marker');
  if (!g) return;
  const m = select(g);
  const visible = Number.isFinite(marker.theta2Deg);
  m.attr('display', visible ? null : 'none');
  if (!visible) return;
  const sx = (Math.min(360, Math.max(0, marker.theta2Deg)) / 360) * iw;
  m.select('line.mline').attr('x1', sx).attr('x2', sx);
  const pts = marker.valuesDeg
    .map((v, i) => ({ v, c: colors[i] ?? CHART_STYLE.marker }))
    .filter((p) => Number.isFinite(p.v) && p.v >= y0 && p.v <= y1);
  m.selectAll<SVGCircleElement, { v: number; c: string }>('circle')
    .data(pts)
    .join('circle')
    .attr('cx', sx)
    .attr('cy', (d) => ih - ((d.v - y0) / (y1 - y0)) * ih)
    .attr('r', 4)
    .attr('fill', (d) => d.c)
    .attr('stroke', '#ffffff')
    .attr('stroke-width', 1.5);
}
