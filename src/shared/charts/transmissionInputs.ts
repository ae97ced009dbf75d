import type { AngleMarker } from './theta2Chart';
import type { MuBand, TransmissionChartData, TransmissionChartText } from './transmissionChart';
import type { XMark } from './xMarks';
import { radToDeg, radToDeg360, wrapDeg180 } from '../../solver/angles';
import type { Branch } from '../../solver/types';
import type { DesignMetrics } from '../../solver/metrics';
import { deadCentreMarks } from '../linkage/designFacts';
import { formatNumber } from '../format';
import type { Messages } from '../i18n/messages';
import type { PointResponse } from '../solution';
import type { CycleDegrees } from './chartInputs';

/** Everything the transmission chart shows but its size and marker. */
export interface TransmissionChartInputs extends TransmissionChartText {
  data: TransmissionChartData;
  band: MuBand;
  xMarks: readonly XMark[];
}

/** mu = |theta4 - theta3| folded into [0, 180] degrees along the branch's cycle (NaN in gaps). */
export function transmissionData(deg: CycleDegrees | null, branch: Branch): TransmissionChartData {
  if (!deg) return { theta2Deg: new Float64Array(0), muDeg: new Float64Array(0) };
  const { theta3, theta4 } = deg[branch];
  const n = Math.min(theta3.length, theta4.length);
  const muDeg = new Float64Array(n);
  for (let i = 0; i < n; i++) muDeg[i] = Math.abs(wrapDeg180(theta4[i] - theta3[i]));
  return { theta2Deg: deg.theta2Deg, muDeg };
}

/** The dead-centre rules of every theta2 axis, labelled in the UI language; none unless a crank drives a rocker. */
export function deadCentreXMarks(metrics: DesignMetrics | null, t: Messages): XMark[] {
  return deadCentreMarks(metrics).map((m) => ({
    xDeg: m.theta2Deg,
    label: m.kind === 'extended' ? t.markExtended : t.markFolded,
  }));
}

/** The transmission chart's texts, band and rules. */
export function transmissionInputs(
  data: TransmissionChartData,
  band: MuBand,
  xMarks: readonly XMark[],
  t: Messages,
): TransmissionChartInputs {
  return {
    data,
    band,
    xMarks,
    title: t.chartTransmission,
    xLabel: t.axisTheta2,
    yLabel: t.axisMu,
    legendMu: t.legendMu,
    legendOutside: t.legendOutsideBand,
    legendBand: t.legendBand(formatNumber(band.loDeg, 4), formatNumber(band.hiDeg, 4)),
  };
}

/** The marker of the transmission chart: theta2 and mu of the pose (degrees), NaN when not assembled. */
export function muMarker(point: PointResponse | null): AngleMarker {
  const pose = point ? point.pose : null;
  return {
    theta2Deg: point ? radToDeg360(point.theta2Rad) : Number.NaN,
    valuesDeg: [pose ? radToDeg(pose.mu) : Number.NaN],
  };
}
