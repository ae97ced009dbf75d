import type { AngleChartData, AngleMarker } from './theta2Chart';
import { CHART_STYLE } from './chartFrame';
import type { ConvergenceRun } from './convergenceChart';
import type { Branch } from '../../solver/types';
import { radToDeg180, radToDeg360 } from '../../solver/angles';
import type { NrStart } from '../state/appState';
import { formatDeg } from '../format';
import type { Messages } from '../i18n/messages';
import type { CycleResponse, PlotSeries, PointResponse } from '../solution';

/** The angle charts the app shows and exports. */
export type AngleChartKind = 'theta3' | 'theta4' | 'both';

/** Text and data of one angle chart, without its size or marker. */
export interface AngleChartInputs {
  data: AngleChartData;
  title: string;
  xLabel: string;
  yLabel: string;
}

/** Text and data of the convergence chart, without its size. */
export interface ConvergenceInputs {
  runs: ConvergenceRun[];
  title: string;
  xLabel: string;
  yLabel: string;
  tolerance: number;
  toleranceLabel: string;
  emptyText: string;
}

const EMPTY = new Float64Array(0);

/** Degrees wrapped to (-180, 180] from radians; NaN stays NaN (a gap). */
export function toWrappedDeg(rad: ArrayLike<number>): Float64Array {
  const out = new Float64Array(rad.length);
  for (let i = 0; i < rad.length; i++) out[i] = radToDeg180(rad[i]);
  return out;
}

/** Both branches' output angles in wrapped degrees, computed once per cycle. */
export interface CycleDegrees {
  theta2Deg: Float64Array;
  open: { theta3: Float64Array; theta4: Float64Array };
  crossed: { theta3: Float64Array; theta4: Float64Array };
}

/** A plotted cycle's angles in wrapped degrees (a branch not solved has empty series). */
export function plotDegrees(plot: PlotSeries): CycleDegrees {
  const branch = (b: { theta3: Float64Array; theta4: Float64Array } | null) =>
    b ? { theta3: toWrappedDeg(b.theta3), theta4: toWrappedDeg(b.theta4) } : { theta3: EMPTY, theta4: EMPTY };
  return { theta2Deg: plot.theta2Deg, open: branch(plot.open), crossed: branch(plot.crossed) };
}

/** A cycle's angles on its view grid in wrapped degrees (what the plots show while no plot is solved). */
export function cycleDegrees(cycle: CycleResponse): CycleDegrees {
  return {
    theta2Deg: cycle.theta2Deg,
    open: { theta3: toWrappedDeg(cycle.open.theta3), theta4: toWrappedDeg(cycle.open.theta4) },
    crossed: { theta3: toWrappedDeg(cycle.crossed.theta3), theta4: toWrappedDeg(cycle.crossed.theta4) },
  };
}

/** Inputs of an angle chart: the branch's curves (the other branch faint when showOther) and labels. */
export function angleChartInputs(
  kind: AngleChartKind,
  deg: CycleDegrees | null,
  branch: Branch,
  showOther: boolean,
  t: Messages,
): AngleChartInputs {
  const cur = deg ? deg[branch] : null;
  const oth = deg ? deg[branch === 'open' ? 'crossed' : 'open'] : null;
  const other = ` (${t.legendOtherBranch})`;
  const series: AngleChartData['series'] = [];
  const add = (key: 'theta3' | 'theta4', color: string, label: string) => {
    if (showOther) series.push({ label: label + other, valuesDeg: oth ? oth[key] : EMPTY, color, faint: true });
    series.push({ label, valuesDeg: cur ? cur[key] : EMPTY, color });
  };
  if (kind === 'theta3' || kind === 'both') add('theta3', CHART_STYLE.theta3, 'θ3');
  if (kind === 'theta4' || kind === 'both') add('theta4', CHART_STYLE.theta4, 'θ4');
  const title = kind === 'theta3' ? t.chartTheta3 : kind === 'theta4' ? t.chartTheta4 : t.chartBoth;
  const yLabel = kind === 'theta3' ? t.axisTheta3 : kind === 'theta4' ? t.axisTheta4 : t.axisAngle;
  return {
    data: { theta2Deg: deg ? deg.theta2Deg : EMPTY, series },
    title,
    xLabel: t.axisTheta2,
    yLabel,
  };
}

/** The marker of an angle chart: the solved pose's theta2 and its angles (degrees) in the order of the chart's solid series; NaN when not assembled. */
export function angleMarker(kind: AngleChartKind, point: PointResponse | null): AngleMarker {
  const pose = point ? point.pose : null;
  const values: number[] = [];
  const val = (key: 'theta3' | 'theta4') => (pose ? radToDeg180(pose[key]) : Number.NaN);
  if (kind === 'theta3' || kind === 'both') values.push(val('theta3'));
  if (kind === 'theta4' || kind === 'both') values.push(val('theta4'));
  const theta2Deg = point ? radToDeg360(point.theta2Rad) : Number.NaN;
  return { theta2Deg, valuesDeg: values };
}

/** Inputs of the convergence chart: the chosen start solid, the other faint, the solver's tolerance (length unit). */
export function convergenceInputs(point: PointResponse | null, start: NrStart, t: Messages): ConvergenceInputs {
  const runs: ConvergenceRun[] = [];
  const main = point ? (start === 'continuation' ? point.continuation : point.cold) : null;
  const alt = point ? (start === 'continuation' ? point.cold : point.continuation) : null;
  const run = (s: typeof main, faint: boolean): ConvergenceRun | null =>
    s && s.log.length
      ? {
          label: `${s.start === 'continuation' ? t.nrContinuation : t.nrCold} (${s.iterations})`,
          iterations: s.log.map((r) => r.iteration),
          residuals: s.log.map((r) => r.residual),
          color: s.start === 'continuation' ? CHART_STYLE.residual : CHART_STYLE.marker,
          faint,
        }
      : null;
  const a = run(alt, true);
  const b = run(main, false);
  if (a) runs.push(a);
  if (b) runs.push(b);
  const theta2 = point ? formatDeg(radToDeg360(point.theta2Rad), 2) : '—';
  const tolerance = main ? main.tolerance : Number.NaN;
  return {
    runs,
    title: t.chartConvergence(theta2),
    xLabel: t.axisIteration,
    yLabel: t.axisResidual,
    tolerance,
    toleranceLabel: Number.isFinite(tolerance) ? `tol ${tolerance.toExponential(0).replace('-', '\u2212')}` : '',
    emptyText: t.noConvergenceData,
  };
}
