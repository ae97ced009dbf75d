import './AppLayout.css';
import { Suspense, lazy } from 'react';
import type { ParsedUrl } from '../shared/url/url';
import { AnalysisPanel } from '../features/simulator/AnalysisPanel';
import { AnglePlotsPanel } from '../features/simulator/PlotsPanel';
import { Brand } from './Brand';
import { ControlsPanel } from '../features/simulator/ControlsPanel';
import { ConvergencePanel } from '../features/simulator/ConvergencePanel';
import { DesignPanel } from '../features/simulator/DesignPanel';
import { ExportPanel } from '../features/export/ExportPanel';
import { LanguageSelect } from './LanguageSelect';
import { MotionPanel } from '../features/simulator/MotionPanel';
import { MessagesContext } from '../shared/i18n/MessagesContext';
import { PageTabs, pageTabId } from './PageTabs';
import { SharePanel } from '../features/share/SharePanel';
import { shellMessages } from './shellMessages';
import { SkipLink } from './SkipLink';
import { useDocumentMeta } from './useDocumentMeta';
import { useSimulatorSession } from './useSimulatorSession';
import type { ShownFor } from './useSimulatorSession';
import { useFrameMotion } from '../features/simulator/useFrameMotion';
import { FramePoseProvider } from '../features/simulator/FramePoseProvider';
import { LinkageStage } from '../features/simulator/LinkageStage';
import { useLinkagePose } from '../features/simulator/useLinkagePose';
import { useLatest } from '../shared/hooks/useLatest';
import { useUrlSync } from './useUrlSync';
import { UrlNotice } from './UrlNotice';
import { SolverStatus } from '../shared/jobs/SolverStatus';

// The solver lab (its charts and tables) loads only when it is opened.
const LabPanel = lazy(() => import('../features/lab/LabPanel').then((m) => ({ default: m.LabPanel })));
// The transmission plot (its chart module) loads after the first paint.
const TransmissionPanel = lazy(() =>
  import('../features/simulator/TransmissionPanel').then((m) => ({ default: m.TransmissionPanel })),
);

/** Props of AppLayout: the state parsed from the URL. */
export interface AppLayoutProps {
  initial: ParsedUrl;
}

/** The full app solves the stage and the plots on the simulator page, the NR runs always (the lab uses them too). */
const appViews: ShownFor = (s, plotPixels) => ({
  stage: s.page !== 'lab',
  plotPixels: s.page !== 'lab' ? plotPixels : 0,
  newton: true,
});

/** Ids of the main landmark (the skip link's target) and of the page tab panel inside it. */
const MAIN_ID = 'main-content';
const PANEL_ID = 'page-panel';

/**
 * The full app: top bar (title, Simulator / Solver lab tabs, language), controls on the left, the linkage
 * and its plots (or the lab) in the middle, numbers, convergence, export and share on the right.
 */
export function AppLayout({ initial }: AppLayoutProps) {
  const session = useSimulatorSession(initial.state, appViews, true);
  const { state, dispatch, client, solverMode, solverReason, cycle, cycleError, point, table, t } = session;
  const { deg, rates, rocking, design, xMarks, playhead, onStep, onShown, plotsRef } = session;
  const { onPng, onSvg, onCsv, onAnimation, onCanvasSize, onTheta2, onCoupler, onViewChange } = session;
  const onLab = state.page === 'lab';
  // The numbers panel follows the state (a few times a second while playing); the canvas and the plot
  // markers follow every frame through the FramePoseProvider below.
  const { local } = useLinkagePose(state, false);
  const motion = useFrameMotion(state, local);
  const stateRef = useLatest(state);
  const shell = shellMessages(state.locale);
  useDocumentMeta(t.htmlLang, t.appTitle);
  useUrlSync(state);

  return (
    <MessagesContext.Provider value={t}>
      <FramePoseProvider state={state} playhead={playhead} ghostShown={!onLab}>
        <SkipLink targetId={MAIN_ID} label={shell.skipToMain} />
        <div className="app" data-ready={cycle && point ? 'true' : 'false'}>
          <header className="topbar">
            <Brand />
            <PageTabs page={state.page} dispatch={dispatch} panelId={PANEL_ID} />
            <LanguageSelect locale={state.locale} dispatch={dispatch} />
          </header>
          <UrlNotice ignored={initial.ignored} />
          <aside className="sidebar" aria-label={shell.controlsLabel}>
            <ControlsPanel state={state} dispatch={dispatch} rocking={rocking} onStep={onStep} />
          </aside>
          <main className="app-main" id={MAIN_ID} tabIndex={-1}>
            <div
              className={`main${onLab ? ' main-lab' : ''}`}
              id={PANEL_ID}
              role="tabpanel"
              aria-labelledby={pageTabId(state.page)}
            >
              {onLab ? (
                <Suspense fallback={<p className="note">{t.labRun}…</p>}>
                  <LabPanel client={client} state={state} dispatch={dispatch} />
                </Suspense>
              ) : (
                <>
                  <section className="card stage">
                    <LinkageStage
                      cycle={cycle}
                      design={design}
                      onViewChange={onViewChange}
                      onTheta2={onTheta2}
                      onCoupler={onCoupler}
                      onSize={onCanvasSize}
                      hint={shell.canvasHint({ crank: true, coupler: true })}
                      onShown={onShown}
                    />
                  </section>
                  <section className="card plots" aria-label={t.sectionPlots} ref={plotsRef}>
                    <AnglePlotsPanel
                      deg={deg}
                      showOther={state.showGhost}
                      layout={state.plotLayout}
                      dispatch={dispatch}
                      xMarks={xMarks}
                      kind={state.plotKind}
                      rates={rates}
                    />
                  </section>
                  <section className="card transmission-card" aria-label={t.chartTransmission}>
                    <Suspense fallback={null}>
                      <TransmissionPanel
                        deg={deg}
                        muBandLoDeg={state.muBandLoDeg}
                        muBandHiDeg={state.muBandHiDeg}
                        xMarks={xMarks}
                      />
                    </Suspense>
                  </section>
                </>
              )}
            </div>
          </main>
          <aside className="rightbar" aria-label={shell.resultsLabel}>
            <section className="card" aria-labelledby="sec-analysis">
              <h2 id="sec-analysis" className="section-title">
                {t.sectionAnalysis}
              </h2>
              <AnalysisPanel cycle={cycle} table={table} point={point} branch={state.branch} nrStart={state.nrStart} />
              {cycleError ? (
                <p className="note note-error" role="alert">
                  {cycleError}
                </p>
              ) : null}
            </section>
            <section className="card" aria-labelledby="sec-design">
              <h2 id="sec-design" className="section-title">
                {t.sectionDesign}
              </h2>
              <DesignPanel
                design={design}
                muBandLoDeg={state.muBandLoDeg}
                muBandHiDeg={state.muBandHiDeg}
                dispatch={dispatch}
              />
            </section>
            <section className="card" aria-labelledby="sec-motion-results">
              <h2 id="sec-motion-results" className="section-title">
                {t.motionPanelTitle}
              </h2>
              <MotionPanel motion={motion} theta2Rad={local.theta2Rad} />
            </section>
            <section className="card convergence-card">
              <ConvergencePanel point={point} nrStart={state.nrStart} dispatch={dispatch} />
            </section>
            <section className="card" aria-labelledby="sec-export">
              <h2 id="sec-export" className="section-title">
                {t.sectionExport}
              </h2>
              <ExportPanel onPng={onPng} onSvg={onSvg} onCsv={onCsv} onAnimation={onAnimation} />
            </section>
            <section className="card" aria-labelledby="sec-share">
              <h2 id="sec-share" className="section-title">
                {t.sectionShare}
              </h2>
              <SharePanel stateRef={stateRef} />
            </section>
            <SolverStatus mode={solverMode} reason={solverReason} />
          </aside>
        </div>
      </FramePoseProvider>
    </MessagesContext.Provider>
  );
}
