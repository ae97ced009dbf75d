import { COLORS } from '../theme/tokens';
import type { Chart, ChartOptions, ChartSpec, ChartTexts, DefsSel, ChartScales, GSel } from './chart';
import { createChart } from './chart';
import { child } from './chartFrame';
import type { AngleMarker } from './theta2Chart';
import { theta2Frame } from './theta2Chart';

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
export interface TransmissionChartText extends ChartTexts {
  legendMu: string;
  legendOutside: string;
  legendBand: string;
}

/** Options of createTransmissionChart: the θ2 chart's (sizes in CSS pixels), its texts and the band. */
export interface TransmissionChartOptions extends ChartOptions, TransmissionChartText {
  /** The usable band; default 40 to 140 degrees. */
  band?: MuBand;
}

/** A live transmission chart: the θ2 chart's handle (its marker's valuesDeg[0] is mu) and the band. */
export interface TransmissionChart extends Chart<TransmissionChartData, AngleMarker, TransmissionChartText> {
  /** Moves the band and the highlighted stretches outside it; a no-op when unchanged. */
  setBand(band: MuBand): void;
}

/** The default usable band of the transmission angle, degrees. */
export const DEFAULT_MU_BAND: MuBand = { loDeg: 40, hiDeg: 140 };

const MU_TICKS = [0, 30, 60, 90, 120, 150, 180];
const MU_COLOR = COLORS.angle;

/** A stretch of theta2 (degrees, x0 <= x1) where mu lies outside the band. */
export interface OutsideRun {
  x0: number;
  x1: number;
}

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

/** The band shaded across the plot (data-lo, data-hi), and the clip of the warning-coloured curve to above and below it. */
function drawBandAndClip(g: GSel, defs: DefsSel, band: MuBand, frame: ChartScales, clipId: string): void {
  const { iw, ih, y } = frame;
  const yHi = y(band.hiDeg);
  const yLo = y(band.loDeg);
  child(g, 'rect', 'mu-band')
    .attr('x', 0)
    .attr('width', iw)
    .attr('y', yHi)
    .attr('height', Math.max(0, yLo - yHi))
    .attr('fill', COLORS.muBandFill)
    .attr('data-lo', band.loDeg)
    .attr('data-hi', band.hiDeg);
  const clip = child(defs, 'clipPath', 'mu-clip').attr('id', clipId);
  child(clip, 'rect', 'above')
    .attr('x', 0)
    .attr('y', -1)
    .attr('width', iw)
    .attr('height', Math.max(0, yHi + 1));
  child(clip, 'rect', 'below')
    .attr('x', 0)
    .attr('y', yLo)
    .attr('width', iw)
    .attr('height', Math.max(0, ih - yLo + 1));
}

/** The stretches of θ2 where mu is outside the band, shaded down the plot (data-x0, data-x1 in degrees). */
function drawOutsideRuns(g: GSel, data: TransmissionChartData, band: MuBand, frame: ChartScales): void {
  const { x, ih } = frame;
  const runs = outsideBandRuns(data.theta2Deg, data.muDeg, band.loDeg, band.hiDeg);
  child(g, 'g', 'mu-outside-runs')
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
}

/**
 * The transmission chart as a spec of the θ2 chart, for the band band() gives at each draw: mu on a fixed
 * 0 to 180 degree axis, the band and the stretches outside it shaded under the grid, the curve drawn again
 * in the warning colour through a clip to above and below the band, the marker's dot red outside the band.
 */
export function transmissionSpec(
  band: () => MuBand,
): ChartSpec<TransmissionChartData, AngleMarker, TransmissionChartText> {
  const clipId = `mu-outside-clip-${++clipCounter}`;
  return {
    frame: (_data, plot) =>
      theta2Frame(plot, { domain: [0, 180], ticks: plot.ih < 120 ? [0, 60, 120, 180] : MU_TICKS }),
    curves: (data) => [
      { label: '', color: MU_COLOR, x: data.theta2Deg, y: data.muDeg, className: 'mu-line' },
      {
        label: '',
        color: COLORS.muOutside,
        x: data.theta2Deg,
        y: data.muDeg,
        className: 'mu-line-outside',
        strokeWidth: 2.5,
        clipId,
      },
    ],
    legend: (_curves, text) => [
      { label: text.legendMu, color: MU_COLOR },
      { label: text.legendOutside, color: COLORS.muOutside },
      { label: text.legendBand, color: COLORS.ok, faint: true },
    ],
    marker(m) {
      const mu = m.valuesDeg[0];
      const b = band();
      const outside = mu < b.loDeg || mu > b.hiDeg;
      return { x: m.theta2Deg, dots: [{ y: mu, color: outside ? COLORS.muOutside : MU_COLOR }] };
    },
    under: {
      className: 'mu-band-layer',
      draw(g, data, frame, defs) {
        drawBandAndClip(g, defs, band(), frame, clipId);
        drawOutsideRuns(g, data, band(), frame);
      },
    },
  };
}

/**
 * Creates the transmission chart in svg: mu against theta2 on a fixed 0 to 180 degree axis, the usable band
 * shaded, the stretches outside it shaded and the curve drawn in the warning colour there, faint dead-centre
 * rules and the current-theta2 marker. Returns its handle; the scales live in it. Draws nothing at size 0.
 */
export function createTransmissionChart(svg: SVGSVGElement, options: TransmissionChartOptions): TransmissionChart {
  const { title, xLabel, yLabel, legendMu, legendOutside, legendBand, band: band0, ...rest } = options;
  let band = band0 ?? DEFAULT_MU_BAND;
  const text = { title, xLabel, yLabel, legendMu, legendOutside, legendBand };
  const empty: TransmissionChartData = { theta2Deg: [], muDeg: [] };
  const chart = createChart(
    svg,
    rest,
    text,
    transmissionSpec(() => band),
    empty,
  );
  return {
    ...chart,
    setBand(next) {
      if (next.loDeg === band.loDeg && next.hiDeg === band.hiDeg) return;
      band = { ...next };
      chart.refresh();
    },
  };
}
