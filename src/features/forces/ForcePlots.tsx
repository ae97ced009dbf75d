import { useMemo } from 'react';
import { radToDeg360 } from '../../solver/angles';
import { downloadPng, downloadText } from '../../shared/canvas/download';
import { exportChart } from '../../shared/charts/exportChart';
import { RateChartView } from '../../shared/charts/RateChartView';
import { fileStem } from '../../shared/fileNames';
import { useFrameDerived, useFrameSelect } from '../../shared/linkage/FramePoseContext';
import type { FramePose } from '../../shared/linkage/FramePoseContext';
import type { ValueSource } from '../../shared/state/externalValue';
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
import type { ForceSetup, PoseForces } from './forceModel';
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

/** The frame's θ2 (degrees) and the forces at its pose. */
interface ForcesAt {
  theta2Deg: number;
  pose: PoseForces;
}

/** The frame's θ2 and its pose's forces for a setup. */
function forcesAt(setup: ForceSetup, f: FramePose): ForcesAt {
  const { theta2Rad, pose } = f.local;
  return { theta2Deg: radToDeg360(theta2Rad), pose: poseForces(setup, theta2Rad, pose) };
}

/** The PNG (2x) and SVG buttons under a force plot: the plot as on screen, with the marker of the pose on screen. */
function ExportRow({
  kind,
  cycle,
  at,
  stem,
  t,
  title,
}: {
  kind: ForcePlotKind;
  cycle: CycleForcesView | null;
  /** The pose on screen's forces, read when a button is pressed. */
  at: ValueSource<ForcesAt>;
  stem: string;
  t: ForcesMessages;
  title: string;
}) {
  const name = `${stem}_${SUBJECT[kind]}`;
  const chart = () => {
    const { pose, theta2Deg } = at.get();
    return forceChartExport(kind, cycle, pose, theta2Deg, t);
  };
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
  // The frame on screen's branch and direction (Play's rocking input switches them) re-render the plots, with the
  // committed state's lengths, forces and input motion; the markers follow every frame by themselves.
  const committed = useFrameSelect(committedOf);
  const branch = useFrameSelect(branchOf);
  const direction = useFrameSelect(directionOf);
  const state = useMemo(
    () => ({
      ...committed,
      design: { ...committed.design, branch },
      motion: { ...committed.motion, direction },
    }),
    [committed, branch, direction],
  );
  const t = forcesMessages.get(state.shell.locale);
  const cycle = useForceCycle(state);
  const setup = useForceSetup(state);
  const at = useFrameDerived((f) => forcesAt(setup, f), [setup]);
  const stem = fileStem(state.design.linkage, state.design.branch);
  const torque = useMemo(() => torqueInputs(cycle, t), [cycle, t]);
  const pins = useMemo(() => pinForceInputs(cycle, t), [cycle, t]);
  const bearing = useMemo(() => bearingInputs(cycle, t), [cycle, t]);
  const title = kind === 'torque' ? t.chartTorque : kind === 'pinForces' ? t.chartPinForces : t.chartBearing;
  // Each marker reads the frame's forces from `at` (solved once per frame).
  const torqueAt = useFrameDerived(() => torqueMarker(at.get().theta2Deg, at.get().pose, torque.unit), [at, torque]);
  const pinsAt = useFrameDerived(() => pinForceMarker(at.get().theta2Deg, at.get().pose, pins.unit), [at, pins]);
  const bearingAt = useFrameDerived(() => bearingMarker(at.get().pose, bearing.unit), [at, bearing]);
  return (
    <>
      <div className={`plots-grid plots-together forces-plot forces-plot-${kind}`} data-testid={`forces-plot-${kind}`}>
        {kind === 'torque' ? (
          <RateChartView inputs={torque} marker={torqueAt} label={t.chartTorque} />
        ) : kind === 'pinForces' ? (
          <RateChartView inputs={pins} marker={pinsAt} label={t.chartPinForces} />
        ) : (
          <BearingChartView inputs={bearing} marker={bearingAt} label={t.chartBearing} />
        )}
      </div>
      <ExportRow kind={kind} cycle={cycle} at={at} stem={stem} t={t} title={title} />
      <p className="footnote">{kind === 'bearing' ? t.bearingFootnote : t.plotFootnote}</p>
    </>
  );
}

const committedOf = (f: FramePose) => f.committed;
const branchOf = (f: FramePose) => f.state.design.branch;
const directionOf = (f: FramePose) => f.state.motion.direction;
