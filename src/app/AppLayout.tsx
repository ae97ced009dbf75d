import './AppLayout.css';
import { Suspense, lazy, useCallback, useMemo, useState } from 'react';
import type { AppState } from '../state/appState';
import { Playhead } from '../state/playhead';
import { getMessages } from '../state/i18n';
import type { ParsedUrl } from '../state/url';
import { AnalysisPanel } from './AnalysisPanel';
import { AnglePlotsPanel } from './AnglePlotsPanel';
import { Brand } from './Brand';
import { ControlsPanel } from './ControlsPanel';
import { ConvergencePanel } from './ConvergencePanel';
import { DesignPanel } from './DesignPanel';
import { ExportPanel } from './ExportPanel';
import { LanguageSelect } from './LanguageSelect';
import { MotionPanel } from './MotionPanel';
import { MessagesContext } from './MessagesContext';
import { PageTabs, pageTabId } from './PageTabs';
import { SharePanel } from './SharePanel';
import { shellMessages } from './shellMessages';
import { SkipLink } from './SkipLink';
import { useAnimation } from './useAnimation';
import { useCanvasEdits } from './useCanvasEdits';
import { useDrawnMark } from './useDrawnMark';
import { useCycleFacts } from './useCycleFacts';
import { useDocumentMeta } from './useDocumentMeta';
import { useExports } from './useExports';
import { useFrameMotion } from './useFrameMotion';
import { FramePoseProvider } from './FramePoseProvider';
import { LinkageStage } from './LinkageStage';
import { useShownFrame } from './useShownFrame';
import { useLinkagePose } from './useLinkagePose';
import { usePlotPixels } from './usePlotPixels';
import { useSimulator } from './useSimulator';
import { useStableCallback } from './useStableCallback';
import { useUrlSync } from './useUrlSync';
import { UrlNotice } from './UrlNotice';
import { SolverStatus } from './SolverStatus';
import { useCycleTable } from './useSolver';
import { useDesignMetrics } from './useDesignMetrics';
import { deadCentreXMarks } from './transmissionInputs';

// The solver lab (its charts and tables) loads only when it is opened.
const LabPanel = lazy(() => import('./LabPanel').then((m) => ({ default: m.LabPanel })));
// The transmission plot (its chart module) loads after the first paint.
const TransmissionPanel = lazy(() => import('./TransmissionPanel').then((m) => ({ default: m.TransmissionPanel })));

/** Props of AppLayout: the state parsed from the URL. */
export interface AppLayoutProps {
  initial: ParsedUrl;
}

/** Ids of the main landmark (the skip link's target) and of the page tab panel inside it. */
const MAIN_ID = 'main-content';
const PANEL_ID = 'page-panel';

/**
 * The full app: top bar (title, Simulator / Solver lab tabs, language), controls on the left, the linkage
 * and its plots (or the lab) in the middle, numbers, convergence, export and share on the right.
 */
export function AppLayout({ initial }: AppLayoutProps) {
  const { plotsRef, plotPixels } = usePlotPixels();
  const shownFor = useCallback(
    (s: AppState) => ({ stage: s.page !== 'lab', plotPixels: s.page !== 'lab' ? plotPixels : 0, newton: true }),
    [plotPixels],
  );
  const { state, dispatch, client, solverMode, solverReason, cycle, cycleError, point, plot } = useSimulator(
    initial.state,
    shownFor,
  );
  const solverChoice = useMemo(() => ({ method: state.method, tol: state.tol }), [state.method, state.tol]);
  const table = useCycleTable(client, state.linkage, state.samples, state.branch, solverChoice, true);
  const t = getMessages(state.locale);
  const onLab = state.page === 'lab';
  const { deg, rates, rangeDeg, rocking } = useCycleFacts(cycle, plot, state.direction);
  // The numbers panel follows the state (a few times a second while playing); the canvas and the plot
  // markers follow every frame through the FramePoseProvider below.
  const { local } = useLinkagePose(state, false);
  const motion = useFrameMotion(state, local);
  const design = useDesignMetrics(state.linkage, state.branch);
  const xMarks = useMemo(() => deadCentreXMarks(design?.metrics ?? null, t), [design, t]);
  const { shown, onShown } = useShownFrame();
  const { onPng, onSvg, onCsv, onAnimation, onCanvasSize } = useExports({ state, point, shown, cycle, client, deg, t });
  const [playhead] = useState(() => new Playhead());
  const onStep = useAnimation(state, dispatch, rangeDeg, playhead);
  const getState = useStableCallback(() => state);
  const { onTheta2, onCoupler } = useCanvasEdits(dispatch);
  const shell = shellMessages(state.locale);
  const onViewChange = useCallback((view: AppState['view']) => dispatch({ type: 'setView', view }), [dispatch]);
  useDocumentMeta(t.htmlLang, t.appTitle);
  useUrlSync(state);
  useDrawnMark('fourbar:cycle-drawn', cycle);
  useDrawnMark('fourbar:plot-drawn', plot);

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
              <SharePanel getState={getState} />
            </section>
            <SolverStatus mode={solverMode} reason={solverReason} />
          </aside>
        </div>
      </FramePoseProvider>
    </MessagesContext.Provider>
  );
}
