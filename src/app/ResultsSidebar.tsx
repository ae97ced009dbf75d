import { useCallback } from 'react';
import type { Page } from '../shared/state/appState';
import { AnalysisPanel } from '../features/simulator/AnalysisPanel';
import { ConvergencePanel } from '../features/simulator/ConvergencePanel';
import { DesignPanel } from '../features/simulator/DesignPanel';
import { MotionPanel } from '../features/simulator/MotionPanel';
import { useFrameMotion } from '../features/simulator/useFrameMotion';
import { useLinkagePose } from '../features/simulator/useLinkagePose';
import { ExportPanel } from '../features/export/ExportPanel';
import { SharePanel } from '../features/share/SharePanel';
import { PrintReportSection } from './PrintReportSection';
import { ForcesSection } from '../features/forces/ForcesSection';
import { useLatest } from '../shared/hooks/useLatest';
import { SolverStatus } from '../shared/jobs/SolverStatus';
import { PanelSection } from '../shared/ui/PanelSection';
import { HoldingSection } from '../shared/ui/Held';
import type { SimulatorSession } from './useSimulatorSession';
import { exportBlocked } from './exportBlocked';
import { PAGES } from './pages';

/** Props of ResultsSidebar: the simulator session and the sidebar's accessible name. */
export interface ResultsSidebarProps {
  session: SimulatorSession;
  label: string;
}

/** The full app's right sidebar: numbers, design, motion, NR convergence, export, share and the solver's status. */
export function ResultsSidebar({ session, label }: ResultsSidebarProps) {
  const { state, dispatch, t, cycle, cycleError, point, table, design } = session;
  // The numbers panel follows the state (a few times a second while playing); the canvas and the plot
  // markers follow every frame through the FramePoseProvider.
  const { local } = useLinkagePose(state, false);
  const motion = useFrameMotion(state, local);
  const stateRef = useLatest(state);
  const locale = state.shell.locale;
  // While Play runs, a card off screen keeps its last render (the state commits a few times a second).
  const hold = state.motion.playing;
  // Stable per language, so the memoised Share panel does not re-render with every state change.
  const pageLabel = useCallback((p: Page) => PAGES[p].label[locale], [locale]);
  return (
    <aside className="rightbar" aria-label={label}>
      <PanelSection holdOffScreen={hold} className="card" id="sec-analysis" title={t.sectionAnalysis}>
        <AnalysisPanel
          cycle={cycle}
          table={table}
          point={point}
          branch={state.design.branch}
          nrStart={state.solver.nrStart}
        />
        {cycleError ? (
          <p className="note note-error" role="alert">
            {cycleError}
          </p>
        ) : null}
      </PanelSection>
      <PanelSection holdOffScreen={hold} className="card" id="sec-design" title={t.sectionDesign}>
        <DesignPanel
          design={design}
          muBandLoDeg={state.display.muBandLoDeg}
          muBandHiDeg={state.display.muBandHiDeg}
          dispatch={dispatch}
        />
      </PanelSection>
      <PanelSection holdOffScreen={hold} className="card" id="sec-motion-results" title={t.motionPanelTitle}>
        <MotionPanel motion={motion} theta2Rad={local.theta2Rad} lengthUnit={state.design.lengthUnit} />
      </PanelSection>
      <ForcesSection state={state} dispatch={dispatch} holdOffScreen={hold} />
      <HoldingSection className="card convergence-card" holdOffScreen={hold}>
        <ConvergencePanel point={point} nrStart={state.solver.nrStart} dispatch={dispatch} />
      </HoldingSection>
      <PanelSection holdOffScreen={hold} className="card" id="sec-export" title={t.sectionExport}>
        <ExportPanel
          onPng={session.onPng}
          onSvg={session.onSvg}
          onCsv={session.onCsv}
          onAnimation={session.onAnimation}
          blocked={exportBlocked(session.design, session.t)}
        />
      </PanelSection>
      <PrintReportSection session={session} />
      <PanelSection holdOffScreen={hold} className="card" id="sec-share" title={t.sectionShare}>
        <SharePanel stateRef={stateRef} pageLabel={pageLabel} />
      </PanelSection>
      <SolverStatus mode={session.solverMode} reason={session.solverReason} />
    </aside>
  );
}
