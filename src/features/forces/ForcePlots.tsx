import { useMemo } from 'react';
import { radToDeg360 } from '../../solver/angles';
import { downloadPng, downloadText } from '../../shared/canvas/download';
import { exportChart } from '../../shared/charts/exportChart';
import { RateChartView } from '../../shared/charts/RateChartView';
import { fileStem } from '../../shared/fileNames';
import { useFramePose } from '../../shared/linkage/FramePoseContext';
import type { ForcePlotKind } from '../../shared/state/appState';
import { BearingChartView } from './BearingChartView';
import type { CycleForcesView } from './forceCycleData';
import {
  bearingInputs,
  bearingMarker,
  forceChartExport,
  pinForceInputs,
  pinForceMarker,
  torqueInputs,
  torqueMarker,
} from './forceCharts';
import type { PoseForces } from './forceModel';
import { poseForces } from './forceModel';
import { forcesMessages } from './forcesMessages';
import type { ForcesMessages } from './forcesMessages';
import { useForceCycle } from './useForceCycle';
import { useForceSetup } from './useForceSetup';

/** Props of ForcePlots: which force plot shows. */
export interface ForcePlotsProps {
  kind: ForcePlotKind;
}

/** File name parts of each force plot's export. */
const SUBJECT: Record<ForcePlotKind, string> = {
  torque: 'torque-vs-theta2',
  pinForces: 'pin-forces-vs-theta2',
  bearing: 'bearing-load-F12',
};

/** The PNG (2x) and SVG buttons under a force plot: the plot as on screen, with this pose's marker. */
function ExportRow({
  kind,
  cycle,
  pose,
  theta2Deg,
  stem,
  t,
  title,
}: {
  kind: ForcePlotKind;
  cycle: CycleForcesView | null;
  pose: PoseForces;
  theta2Deg: number;
  stem: string;
  t: ForcesMessages;
  title: string;
}) {
  const name = `${stem}_${SUBJECT[kind]}`;
  const chart = () => forceChartExport(kind, cycle, pose, theta2Deg, t);
  return (
    <div className="export-buttons forces-export">
      <button
        type="button"
        className="btn btn-small"
        aria-label={t.exportWhat(title, 'PNG')}
        onClick={() => void exportChart(chart(), '2x').then((bytes) => downloadPng(bytes, `${name}_2x.png`))}
      >
        {t.exportPng}
      </button>
      <button
        type="button"
        className="btn btn-small"
        aria-label={t.exportWhat(title, 'SVG')}
        onClick={() => downloadText(exportChart(chart(), 'svg'), `${name}.svg`, 'image/svg+xml;charset=utf-8')}
      >
        {t.exportSvg}
      </button>
    </div>
  );
}

/**
 * The forces' plots (loaded when one is chosen): input torque T12 against θ2 with its mean, the pin-force
 * magnitudes against θ2, or the crank bearing's load F12 as a polar (x–y) diagram; solved over one turn at n
 * samples, with the frame on screen as the marker, and PNG and SVG buttons.
 */
export function ForcePlots({ kind }: ForcePlotsProps) {
  const { state, local } = useFramePose();
  const t = forcesMessages.get(state.shell.locale);
  const cycle = useForceCycle(state);
  const setup = useForceSetup(state);
  const pose = useMemo(() => poseForces(setup, local.theta2Rad, local.pose), [setup, local]);
  const theta2Deg = radToDeg360(local.theta2Rad);
  const stem = fileStem(state.design.linkage, state.design.branch);
  const torque = useMemo(() => torqueInputs(cycle, t), [cycle, t]);
  const pins = useMemo(() => pinForceInputs(cycle, t), [cycle, t]);
  const bearing = useMemo(() => bearingInputs(cycle, t), [cycle, t]);
  const title = kind === 'torque' ? t.chartTorque : kind === 'pinForces' ? t.chartPinForces : t.chartBearing;
  return (
    <>
      <div className={`plots-grid plots-together forces-plot forces-plot-${kind}`} data-testid={`forces-plot-${kind}`}>
        {kind === 'torque' ? (
          <RateChartView inputs={torque} marker={torqueMarker(theta2Deg, pose, torque.unit)} label={t.chartTorque} />
        ) : kind === 'pinForces' ? (
          <RateChartView inputs={pins} marker={pinForceMarker(theta2Deg, pose, pins.unit)} label={t.chartPinForces} />
        ) : (
          <BearingChartView inputs={bearing} marker={bearingMarker(pose, bearing.unit)} label={t.chartBearing} />
        )}
      </div>
      <ExportRow kind={kind} cycle={cycle} pose={pose} theta2Deg={theta2Deg} stem={stem} t={t} title={title} />
      <p className="footnote">{kind === 'bearing' ? t.bearingFootnote : t.plotFootnote}</p>
    </>
  );
}
