import type { ChartExport } from '../../shared/charts/exportChart';
import { specDrawing } from '../../shared/charts/exportChart';
import type { MarkerAt } from '../../shared/charts/chart';
import type { RateChartData, RateMarker, RateCurve } from '../../shared/charts/rateChart';
import { rateSpec } from '../../shared/charts/rateChart';
import type { XYChartData } from '../../shared/charts/xyChart';
import { xySpec } from '../../shared/charts/xyChart';
import { formatNumber } from '../../shared/format';
import { COLORS } from '../../shared/theme/tokens';
import type { ForcePlotKind } from '../../shared/state/appState';
import type { CycleForcesView } from './forceCycleData';
import type { PoseForces } from './forceModel';
import { shownMean } from './forceFacts';
import type { ForcesMessages, PinForce } from './forcesMessages';

/** The pin forces' curve colours: F12 the crank's, F32 the coupler's, F43 the rocker's, F14 the ground's. */
export const PIN_COLORS: Record<PinForce, string> = {
  F12: COLORS.crank,
  F32: COLORS.coupler,
  F43: COLORS.rocker,
  F14: COLORS.ground,
};

/** The bearing-load diagram's fit: one newton as long on x as on y, the crank bearing's centre (0, 0) in view. */
export const BEARING_FIT = { equalAspect: true, includeOrigin: true } as const;

/** Logical (CSS pixel) size of an exported force plot: the angle plots' 640 x 360, the polar diagram square. */
export const FORCE_EXPORT_SIZE: Record<ForcePlotKind, { width: number; height: number }> = {
  torque: { width: 640, height: 360 },
  pinForces: { width: 640, height: 360 },
  bearing: { width: 480, height: 480 },
};

/** The unit a force plot is drawn in: N (N·m) or, for large values, kN or MN, so tick labels stay short. */
export interface PlotUnit {
  /** Plotted value = SI value × factor. */
  factor: number;
  prefix: '' | 'k' | 'M';
}

/**
 * The plot unit for values whose typical size is the 95th percentile of |value| (a few samples near a limit
 * position run away and are clipped anyway): kilo from 1000, mega from 1e6.
 */
export function plotUnit(...arrays: ArrayLike<number>[]): PlotUnit {
  const abs: number[] = [];
  for (const a of arrays) for (let i = 0; i < a.length; i++) if (Number.isFinite(a[i])) abs.push(Math.abs(a[i]));
  abs.sort((x, y) => x - y);
  const typical = abs.length ? abs[Math.min(abs.length - 1, Math.floor(0.95 * abs.length))] : 0;
  if (typical >= 1e6) return { factor: 1e-6, prefix: 'M' };
  if (typical >= 1e3) return { factor: 1e-3, prefix: 'k' };
  return { factor: 1, prefix: '' };
}

/** The values in the plot unit. */
function scaled(a: ArrayLike<number>, u: PlotUnit): Float64Array {
  const out = new Float64Array(a.length);
  for (let i = 0; i < a.length; i++) out[i] = a[i] * u.factor;
  return out;
}

/** Texts and data of a chart against θ2 (torque or pin forces), and the unit it is drawn in. */
export interface Theta2Inputs {
  data: RateChartData;
  title: string;
  xLabel: string;
  yLabel: string;
  unit: PlotUnit;
}

const EMPTY = new Float64Array(0);

/** The torque chart: T12 against θ2 and, faint, its mean over the turn (when the turn has one). */
export function torqueInputs(c: CycleForcesView | null, t: ForcesMessages): Theta2Inputs {
  const unit = plotUnit(c ? c.forces.torque : EMPTY);
  const torqueUnit = `${unit.prefix}N·m`;
  const series: RateCurve[] = [
    { label: 'T12', values: c ? scaled(c.forces.torque, unit) : EMPTY, color: COLORS.force },
  ];
  if (c && Number.isFinite(c.stats.mean)) {
    const mean = shownMean(c.stats) * unit.factor;
    series.push({
      label: t.legendMean(formatNumber(mean, 4), torqueUnit),
      values: new Float64Array(c.theta2Deg.length).fill(mean),
      color: COLORS.force,
      faint: true,
    });
  }
  return {
    data: { theta2Deg: c ? c.theta2Deg : EMPTY, series },
    title: t.chartTorque,
    xLabel: t.axisTheta2,
    yLabel: t.axisTorque(torqueUnit),
    unit,
  };
}

/** The pin-force chart: |F12|, |F32|, |F43| and |F14| against θ2, on a y axis from exactly 0 (magnitudes). */
export function pinForceInputs(c: CycleForcesView | null, t: ForcesMessages): Theta2Inputs {
  const m = c?.magnitudes ?? null;
  const unit = m ? plotUnit(m.f12, m.f32, m.f43, m.f14) : plotUnit();
  const v = (a: Float64Array | undefined) => (a ? scaled(a, unit) : EMPTY);
  const series: RateCurve[] = [
    { label: '|F12|', values: v(m?.f12), color: PIN_COLORS.F12 },
    { label: '|F32|', values: v(m?.f32), color: PIN_COLORS.F32 },
    { label: '|F43|', values: v(m?.f43), color: PIN_COLORS.F43 },
    { label: '|F14|', values: v(m?.f14), color: PIN_COLORS.F14 },
  ];
  return {
    data: { theta2Deg: c ? c.theta2Deg : EMPTY, series, yFloor: 0 },
    title: t.chartPinForces,
    xLabel: t.axisTheta2,
    yLabel: t.axisForce(`${unit.prefix}N`),
    unit,
  };
}

/** Texts and data of the bearing-load diagram. */
export interface BearingInputs {
  data: XYChartData;
  title: string;
  xLabel: string;
  yLabel: string;
  unit: PlotUnit;
}

/** The bearing-load diagram: F12 = (F12x, F12y) over the turn, a closed curve round the crank bearing. */
export function bearingInputs(c: CycleForcesView | null, t: ForcesMessages): BearingInputs {
  const unit = c ? plotUnit(c.magnitudes.f12) : plotUnit();
  const n = `${unit.prefix}N`;
  return {
    data: {
      series: [
        {
          label: 'F12',
          color: PIN_COLORS.F12,
          x: c ? scaled(c.forces.f12x, unit) : EMPTY,
          y: c ? scaled(c.forces.f12y, unit) : EMPTY,
        },
      ],
    },
    title: t.chartBearing,
    xLabel: t.axisFx(n),
    yLabel: t.axisFy(n),
    unit,
  };
}

/** The torque chart's marker at θ2 (degrees): this pose's T12 in the plot unit (NaN where undetermined: no dot). */
export function torqueMarker(theta2Deg: number, p: PoseForces, u: PlotUnit): RateMarker {
  return { theta2Deg, values: [p.forces ? p.forces.torque * u.factor : Number.NaN] };
}

/** The pin-force chart's marker: this pose's four magnitudes in the plot unit. */
export function pinForceMarker(theta2Deg: number, p: PoseForces, u: PlotUnit): RateMarker {
  const f = p.forces;
  const mag = (v: { x: number; y: number }) => Math.hypot(v.x, v.y) * u.factor;
  return { theta2Deg, values: f ? [mag(f.F12), mag(f.F32), mag(f.F43), mag(f.F14)] : [] };
}

/**
 * The bearing diagram's θ2 cursor: a radius from the crank bearing's centre (the origin) to this pose's F12 and a
 * dot there, in the plot unit (none if undetermined). A vertical line at F12x would cross the curve elsewhere too.
 */
export function bearingMarker(p: PoseForces, u: PlotUnit): MarkerAt {
  const f = p.forces;
  return f
    ? { x: f.F12.x * u.factor, dots: [{ y: f.F12.y * u.factor, color: PIN_COLORS.F12 }], from: { x: 0, y: 0 } }
    : { x: Number.NaN, dots: [] };
}

/** A force plot as a chart to export (exportChart), drawn as on screen at FORCE_EXPORT_SIZE with its marker. */
export function forceChartExport(
  kind: ForcePlotKind,
  c: CycleForcesView | null,
  p: PoseForces,
  theta2Deg: number,
  t: ForcesMessages,
): ChartExport {
  const size = FORCE_EXPORT_SIZE[kind];
  if (kind === 'bearing') {
    const { data, unit, ...text } = bearingInputs(c, t);
    return { ...size, draw: specDrawing(xySpec(BEARING_FIT), text, data, bearingMarker(p, unit)) };
  }
  const { data, unit, ...text } = kind === 'torque' ? torqueInputs(c, t) : pinForceInputs(c, t);
  const marker = kind === 'torque' ? torqueMarker(theta2Deg, p, unit) : pinForceMarker(theta2Deg, p, unit);
  return { ...size, draw: specDrawing(rateSpec, text, data, marker) };
}
