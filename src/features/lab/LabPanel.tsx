import './LabPanel.css';
import type { Dispatch } from 'react';
import { nearestLimitDeg } from '../../study/limits';
import type { LabResult } from '../../study/workPrecision';
import type { Action, AppState } from '../../shared/state/appState';
import { formatDeg, formatSci } from '../../shared/format';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { LabJobs } from './jobs';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { labMessagesFor } from './labMessages';
import type { LabMessages } from './labMessages';
import { LiveChartView } from '../../shared/charts/LiveChartView';
import { useLab } from './useLab';
import { useLabCharts } from './useLabCharts';
import { useLabExports } from './useLabExports';
import { LabToolbar } from './LabToolbar';
import { LabTable } from './LabTable';
import { LabMethodChoice } from './LabMethodChoice';
import { LabExportButtons } from './LabExportButtons';
import { HardCasesCard } from './HardCasesCard';

/** Props of LabPanel: the solver client, the app state and its dispatch. */
export interface LabPanelProps {
  client: JobRunner<LabJobs> | null;
  state: AppState;
  dispatch: Dispatch<Action>;
}

/** The distance from θ2 to the nearest limit of the linkage's motion, and the smallest sin μ of the cycle. */
function LabLimits({ result, theta2Deg, lt }: { result: LabResult; theta2Deg: number; lt: LabMessages }) {
  const nearest = nearestLimitDeg(theta2Deg, result.limitsDeg);
  return (
    <>
      <p className="note" data-testid="lab-limit">
        {nearest
          ? lt.labNearestLimit(formatDeg(nearest.distanceDeg, 4), formatDeg(nearest.limitDeg, 4))
          : lt.labNoLimit}
      </p>
      <p className="note">
        {lt.labMinSin(formatSci(result.minSinMu.value, 3), formatDeg(result.minSinMu.theta2Deg, 2))}
      </p>
    </>
  );
}

/**
 * The solver lab: a work-precision study of the current linkage computed in the worker (progress,
 * cancel), the per-method counts of failed, wrong-branch and falsely converged points, iterations
 * and |det J| along the cycle, the distance to the nearest limit, the method and tolerance that
 * drive the main view, hard-case presets, and PNG/CSV export of the diagram.
 */
export function LabPanel({ client, state, dispatch }: LabPanelProps) {
  const t = useMessages();
  const lt = labMessagesFor(state.shell.locale);
  const lab = useLab(client, state.design.linkage, state.design.branch, state.lab.stepDeg);
  const result = lab.result;
  const charts = useLabCharts(result, t, lt, state.solver.method, state.solver.tol, state.motion.theta2Deg);
  const exports = useLabExports(result, charts.chartOptions, t);

  return (
    <div className="lab" data-testid="solver-lab" data-ready={result && !lab.running ? 'true' : 'false'}>
      <section className="card lab-card" aria-labelledby="lab-title">
        <h2 id="lab-title" className="section-title">
          {lt.labTitle}
        </h2>
        <p className="note">{lt.labIntro}</p>
        <LabToolbar lab={lab} stepDeg={state.lab.stepDeg} canRun={client !== null} lt={lt} dispatch={dispatch} />
        <LiveChartView {...charts.diagram} label={lt.labDiagramTitle} className="lab-diagram" testId="work-precision" />
        <LabTable series={result?.series ?? []} method={state.solver.method} tol={state.solver.tol} lt={lt} />
        <LabMethodChoice method={state.solver.method} tol={state.solver.tol} lt={lt} dispatch={dispatch} />
        {result ? <LabLimits result={result} theta2Deg={state.motion.theta2Deg} lt={lt} /> : null}
        <LiveChartView {...charts.cycle} label={lt.labCycleTitle} className="lab-cycle" held={!result} />
        <LabExportButtons exports={exports} disabled={!result} lt={lt} />
        <p className="note">{lt.labWhatItMeans}</p>
      </section>
      <HardCasesCard lt={lt} dispatch={dispatch} />
    </div>
  );
}
