import { axisBottom, axisLeft } from 'd3-axis';
import { select } from 'd3-selection';
import { COLORS } from '../theme/tokens';
import type { AngleMarker } from './theta2Chart';
import { plotIndices } from './theta2Chart';
import type { Margins } from './chartFrame';
import {
  child,
  drawChartText,
  drawGridX,
  drawGridY,
  drawLegend,
  estimateTextWidth,
  prepareSvg,
  styleAxis,
} from './chartFrame';
import { chartMarker } from './markerLayer';
import { angleTicks, fittedTicks, tickCount } from './ticks';
import type { XMark } from './xMarks';
import { drawXMarks } from './xMarks';
import type { ScaleLinear } from 'd3-scale';
import { scaleLinear } from 'd3-scale';
import { linePath } from './line';

/** Transmission angle mu (degrees in [0, 180], NaN where the linkage cannot assemble) against theta2 (degrees, 0 to 360). */
export interface TransmissionChartData {
  theta2Deg: ArrayLike<number>;
  muDeg: ArrayLike<number>;
}

/** The usable band of mu, degrees, lo < hi. */
export interface MuBand {
  loDeg: number;
  hiDeg: number;
}

/** Texts of the transmission chart: title, axis labels and the three legend entries. */
export interface TransmissionChartText {
  title: string;
  xLabel: string;
  yLabel: string;
  legendMu: string;
  legendOutside: string;
  legendBand: string;
}

/** Options of createTransmissionChart; sizes in CSS pixels. */
export interface TransmissionChartOptions extends TransmissionChartText {
  /** Chart width; 0 (not laid out yet) draws nothing until resize. */
  width: number;
  /** Chart height; 0 draws nothing until resize. */
  height: number;
  /** The usable band; default 40 to 140 degrees. */
  band?: MuBand;
  /** Faint theta2 rules (dead centres); default none. */
  xMarks?: readonly XMark[];
  /** Default { top: 46, right: 14, bottom: 40, left: 50 }, as the angle charts. */
  margins?: Margins;
  /** A box laid over the SVG to draw the marker in (on screen); default inside the SVG. */
  markerHost?: HTMLElement;
}

/** A live transmission chart; every method redraws only what its change touches. */
export interface TransmissionChart {
  update(data: TransmissionChartData): void;
  /** Moves the current-theta2 marker (valuesDeg[0] is mu); null hides it. */
  setMarker(marker: AngleMarker | null): void;
  /** Moves the band and the highlighted stretches outside it. */
  setBand(band: MuBand): void;
  setXMarks(marks: readonly XMark[]): void;
  resize(width: number, height: number): void;
  setText(text: TransmissionChartText): void;
  /** A copy of the x scale (theta2 degrees to plot pixels) or the y scale (mu degrees to plot pixels). */
  scale(name: 'x' | 'y'): ScaleLinear<number, number>;
}

/** A stretch of theta2 (degrees, x0 <= x1) where mu lies outside the band. */
export interface OutsideRun {
  x0: number;
  x1: number;
}

/** The default usable band of the transmission angle, degrees. */
export const DEFAULT_MU_BAND: MuBand = { loDeg: 40, hiDeg: 140 };

const DEFAULT_MARGINS: Margins = { top: 46, right: 14, bottom: 40, left: 50 };
const MU_TICKS = [0, 30, 60, 90, 120, 150, 180];
const MU_COLOR = COLORS.angle;

/**
 * The stretches of theta2 where mu is outside [lo, hi]: a run starts and ends where the straight line between
 * two samples crosses the band's edge, or at a sample next to a gap (NaN) or at either end of the data.
 * Samples exactly on an edge count as inside.
 */
export function outsideBandRuns(
  theta2Deg: ArrayLike<number>,
  muDeg: ArrayLike<number>,
  loDeg: number,
  hiDeg: number,
): OutsideRun[] {
  const n = Math.min(theta2Deg.length, muDeg.length);
  const runs: OutsideRun[] = [];
  const outside = (y: number) => y < loDeg || y > hiDeg;
  const cross = (i: number, j: number) => {
    // Where the segment from sample i to sample j meets the edge on j's or i's outer side.
    const yi = muDeg[i];
    const yj = muDeg[j];
    const out = outside(yi) ? yi : yj;
    const edge = out < loDeg ? loDeg : hiDeg;
    return theta2Deg[i] + ((edge - yi) / (yj - yi)) * (theta2Deg[j] - theta2Deg[i]);
  };
  let start: number | null = null;
  for (let i = 0; i < n; i++) {
    const y = muDeg[i];
    const fin = Number.isFinite(y);
    const prevFin = i > 0 && Number.isFinite(muDeg[i - 1]);
    if (start === null) {
      if (fin && outside(y)) start = prevFin && !outside(muDeg[i - 1]) ? cross(i - 1, i) : theta2Deg[i];
      continue;
    }
    if (!fin) {
      runs.push({ x0: start, x1: theta2Deg[i - 1] });
      start = null;
    } else if (!outside(y)) {
      runs.push({ x0: start, x1: cross(i - 1, i) });
      start = null;
    }
  }
  if (start !== null) runs.push({ x0: start, x1: theta2Deg[n - 1] });
  return runs;
}

let clipCounter = 0;

/**
 * Creates the transmission chart in svg: mu against theta2 on a fixed 0 to 180 degree axis, the usable band
 * shaded, the stretches outside it shaded and the curve drawn in the warning colour there, faint dead-centre
 * rules and the current-theta2 marker. Returns its handle; the scales live in it. Draws nothing at size 0.
 */
export function createTransmissionChart(svg: SVGSVGElement, options: TransmissionChartOptions): TransmissionChart {
  let width = Math.max(0, options.width);
  let height = Math.max(0, options.height);
  const m = options.margins ?? DEFAULT_MARGINS;
  let text: TransmissionChartText = { ...options };
  let band = options.band ?? DEFAULT_MU_BAND;
  let xMarks: readonly XMark[] = options.xMarks ?? [];
  let data: TransmissionChartData = { theta2Deg: [], muDeg: [] };
  let marker: AngleMarker | null = null;
  const clipId = `mu-outside-clip-${++clipCounter}`;
  const laidOut = () => width > 0 && height > 0;
  const frame = () => {
    const iw = Math.max(10, width - m.left - m.right);
    const ih = Math.max(10, height - m.top - m.bottom);
    return {
      iw,
      ih,
      x: scaleLinear().domain([0, 360]).range([0, iw]),
      y: scaleLinear().domain([0, 180]).range([ih, 0]),
    };
  };
  let f = frame();

  const s = select(svg);
  child(s, 'rect', 'bg');
  const defs = child(s, 'defs', 'defs');
  const clip = child(defs, 'clipPath', 'mu-clip').attr('id', clipId);
  const clipAbove = child(clip, 'rect', 'above');
  const clipBelow = child(clip, 'rect', 'below');
  const plot = child(s, 'g', 'plot');
  const bandRect = child(plot, 'rect', 'mu-band');
  const outsideG = child(plot, 'g', 'mu-outside-runs');
  const gridX = child(plot, 'g', 'grid-x');
  const gridY = child(plot, 'g', 'grid-y');
  const ax = child(plot, 'g', 'axis-x');
  const ay = child(plot, 'g', 'axis-y');
  const marksG = child(plot, 'g', 'x-marks');
  const lines = child(plot, 'g', 'lines');
  const muPath = child(lines, 'path', 'mu-line');
  const muOutPath = child(lines, 'path', 'mu-line-outside');
  const mark = chartMarker(plot.node() as SVGGElement, options.markerHost);

  const drawAxes = () => {
    const { iw, ih, x, y } = f;
    const xTicks = fittedTicks(
      (c) => angleTicks(0, 360, c),
      x,
      (t) => estimateTextWidth(`${t}`),
      Math.min(8, tickCount(iw, 40)),
    );
    const yTicks = ih < 120 ? [0, 60, 120, 180] : MU_TICKS;
    drawGridX(gridX, ih, xTicks, x);
    drawGridY(gridY, iw, yTicks, y);
    ax.attr('transform', `translate(0,${ih})`).call(
      axisBottom(x)
        .tickValues(xTicks)
        .tickFormat((d) => `${d}`)
        .tickSizeOuter(0),
    );
    styleAxis(ax);
    ay.call(
      axisLeft(y)
        .tickValues(yTicks)
        .tickFormat((d) => `${d}`)
        .tickSizeOuter(0),
    );
    styleAxis(ay);
  };

  const drawBand = () => {
    const { iw, ih, x, y } = f;
    const yHi = y(band.hiDeg);
    const yLo = y(band.loDeg);
    bandRect
      .attr('x', 0)
      .attr('width', iw)
      .attr('y', yHi)
      .attr('height', Math.max(0, yLo - yHi))
      .attr('fill', COLORS.muBandFill)
      .attr('data-lo', band.loDeg)
      .attr('data-hi', band.hiDeg);
    clipAbove
      .attr('x', 0)
      .attr('y', -1)
      .attr('width', iw)
      .attr('height', Math.max(0, yHi + 1));
    clipBelow
      .attr('x', 0)
      .attr('y', yLo)
      .attr('width', iw)
      .attr('height', Math.max(0, ih - yLo + 1));
    const runs = outsideBandRuns(data.theta2Deg, data.muDeg, band.loDeg, band.hiDeg);
    outsideG
      .selectAll<SVGRectElement, OutsideRun>('rect.mu-outside')
      .data(runs)
      .join('rect')
      .attr('class', 'mu-outside')
      .attr('x', (r) => x(r.x0))
      .attr('width', (r) => Math.max(1, x(r.x1) - x(r.x0)))
      .attr('y', 0)
      .attr('height', ih)
      .attr('fill', COLORS.muOutsideFill)
      .attr('data-x0', (r) => r.x0)
      .attr('data-x1', (r) => r.x1);
  };

  const drawLine = () => {
    const { x, y } = f;
    const idx = plotIndices(data.muDeg, Math.max(64, Math.round(2 * f.iw)));
    // Hundredths of a pixel: finer digits only lengthen the path text the browser parses on every redraw.
    const d = linePath(
      idx,
      (i) => x(data.theta2Deg[i]),
      (i) => y(data.muDeg[i]),
      (i) => Number.isFinite(data.muDeg[i]),
      2,
    );
    muPath.attr('d', d).attr('fill', 'none').attr('stroke', MU_COLOR).attr('stroke-width', 1.75);
    muOutPath
      .attr('d', d)
      .attr('fill', 'none')
      .attr('stroke', COLORS.muOutside)
      .attr('stroke-width', 2.5)
      .attr('clip-path', `url(#${clipId})`);
  };

  const drawMarker = () => {
    const t2 = marker?.theta2Deg ?? Number.NaN;
    const box = { left: m.left, top: m.top, height: f.ih };
    if (!marker || !Number.isFinite(t2)) {
      mark.draw({ x: null, dots: [] }, box, width, height);
      return;
    }
    const cx = f.x(Math.min(360, Math.max(0, t2)));
    const mu = marker.valuesDeg[0];
    const outside = mu < band.loDeg || mu > band.hiDeg;
    const dots = Number.isFinite(mu) ? [{ cx, cy: f.y(mu), color: outside ? COLORS.muOutside : MU_COLOR }] : [];
    mark.draw({ x: cx, dots }, box, width, height);
  };

  const drawText = () => {
    drawChartText(
      s,
      { title: text.title, xLabel: text.xLabel, yLabels: [{ text: text.yLabel, centerY: m.top + f.ih / 2 }] },
      m.left,
      f.iw,
      width,
      height,
    );
    drawLegend(
      s,
      [
        { label: text.legendMu, color: MU_COLOR },
        { label: text.legendOutside, color: COLORS.muOutside },
        { label: text.legendBand, color: COLORS.ok, faint: true },
      ],
      14,
      33,
    );
  };

  const drawAll = () => {
    if (!laidOut()) return;
    prepareSvg(svg, width, height);
    plot.attr('transform', `translate(${m.left},${m.top})`);
    drawBand();
    drawAxes();
    drawXMarks(marksG, xMarks, f.x, f.ih);
    drawLine();
    drawText();
    drawMarker();
  };

  drawAll();
  return {
    update(next) {
      data = next;
      if (!laidOut()) return;
      drawBand();
      drawLine();
    },
    setMarker(next) {
      marker = next;
      if (laidOut()) drawMarker();
    },
    setBand(next) {
      if (next.loDeg === band.loDeg && next.hiDeg === band.hiDeg) return;
      band = { ...next };
      if (!laidOut()) return;
      drawBand();
      drawMarker();
    },
    setXMarks(next) {
      xMarks = next;
      if (laidOut()) drawXMarks(marksG, xMarks, f.x, f.ih);
    },
    resize(w, h) {
      if (w === width && h === height) return;
      width = Math.max(0, w);
      height = Math.max(0, h);
      f = frame();
      drawAll();
    },
    setText(next) {
      text = { ...next };
      if (laidOut()) drawText();
    },
    scale(name) {
      return (name === 'x' ? f.x : f.y).copy();
    },
  };
}
