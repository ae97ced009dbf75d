import { AnalysisPanel } from '../features/simulator/AnalysisPanel';
import { DesignPanel } from '../features/simulator/DesignPanel';
import { ExportPanel } from '../features/export/ExportPanel';
import type { EmbedPanel } from '../shared/url/url';
import { SolverStatus } from '../shared/jobs/SolverStatus';
import { SimulatorPlots } from './SimulatorPlots';
import { ForcesSection } from '../features/forces/ForcesSection';
import type { SimulatorSession } from './useSimulatorSession';
import { exportBlocked } from './exportBlocked';

/** Props of EmbedPanels: the session, which panels the widget shows and whether θ2 is locked. */
export interface EmbedPanelsProps {
  session: SimulatorSession;
  show: (panel: EmbedPanel) => boolean;
  theta2Locked: boolean;
}

/** The widget's panels under the linkage, as its URL asks: numbers and design, plots, forces, export; then the solver's status. */
export function EmbedPanels({ session, show, theta2Locked }: EmbedPanelsProps) {
  const { state, dispatch, t, cycle, cycleError, point, table, design, plotsRef } = session;
  const { onPng, onSvg, onCsv, onAnimation, solverMode, solverReason } = session;
  return (
    <>
      {show('info') ? (
        <section className="card embed-card">
          <AnalysisPanel
            cycle={cycle}
            table={table}
            point={point}
            branch={state.design.branch}
            nrStart={state.solver.nrStart}
          />
        </section>
      ) : null}
      {show('info') ? (
        <section className="card embed-card" aria-label={t.sectionDesign}>
          <DesignPanel
            design={design}
            muBandLoDeg={state.display.muBandLoDeg}
            muBandHiDeg={state.display.muBandHiDeg}
            dispatch={dispatch}
            theta2Locked={theta2Locked}
            compact
          />
        </section>
      ) : null}
      {show('plots') ? (
        <section className="card embed-card embed-plots" ref={plotsRef}>
          <SimulatorPlots session={session} />
        </section>
      ) : null}
      {show('forces') ? (
        <ForcesSection state={state} dispatch={dispatch} className="card embed-card" withSettings={false} />
      ) : null}
      {show('export') ? (
        <section className="card embed-card">
          <ExportPanel
            onPng={onPng}
            onSvg={onSvg}
            onCsv={onCsv}
            onAnimation={onAnimation}
            blocked={exportBlocked(design, t)}
            compact
          />
        </section>
      ) : null}
      <SolverStatus mode={solverMode} reason={solverReason} />
      {cycleError ? (
        <p className="note note-error" role="alert">
          {cycleError}
        </p>
      ) : null}
    </>
  );
}
