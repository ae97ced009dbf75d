import './AppLayout.css';
import { Suspense, lazy } from 'react';
import type { ParsedUrl } from '../shared/url/url';
import { Brand } from './Brand';
import { ControlsColumn } from './ControlsColumn';
import { useMediaQuery } from '../shared/hooks/useMediaQuery';
import { PHONE_MEDIA } from '../shared/theme/tokens';
import { DesignBar } from '../features/designs/DesignBar';
import { LanguageSelect } from './LanguageSelect';
import { MessagesContext } from '../shared/i18n/MessagesContext';
import { PageTabs, pageTabId } from './PageTabs';
import { ResultsSidebar } from './ResultsSidebar';
import { shellMessages } from './shellMessages';
import { SimulatorPage } from './SimulatorPage';
import { SkipLink } from './SkipLink';
import { useDocumentMeta } from './useDocumentMeta';
import { useAfterFirstFrame } from '../shared/hooks/useAfterFirstFrame';
import { useSimulatorSession } from './useSimulatorSession';
import type { ShownFor } from './useSimulatorSession';
import { FramePoseProvider } from '../features/simulator/FramePoseProvider';
import { useUrlSync } from './useUrlSync';
import { UrlNotice } from './UrlNotice';
import { createSolverPool } from '../workers/solverClient';

// The solver lab (its charts and tables) and the synthesis page load only when they are opened.
const LabPanel = lazy(() => import('../features/lab/LabPanel').then((m) => ({ default: m.LabPanel })));
const SynthesisPage = lazy(() =>
  import('../features/synthesis/SynthesisPage').then((m) => ({ default: m.SynthesisPage })),
);

/** Props of AppLayout: the state parsed from the URL. */
export interface AppLayoutProps {
  initial: ParsedUrl;
}

/** The full app solves the stage and the plots on the simulator page, the NR runs always (the lab uses them too). */
const appViews: ShownFor = (s, plotPixels) => ({
  stage: s.shell.page === 'simulator',
  plotPixels: s.shell.page === 'simulator' ? plotPixels : 0,
  newton: true,
});

/** The synthesis page's pool of solver workers (cores − 1, at least one), made on its first run. */
const createSynthesisPool = () => createSolverPool();

/** Ids of the main landmark (the skip link's target) and of the page tab panel inside it. */
const MAIN_ID = 'main-content';
const PANEL_ID = 'page-panel';

/**
 * The full app: top bar (title, Simulator / Solver lab tabs, language), controls on the left, the linkage
 * and its plots (or the lab) in the middle, numbers, convergence, export and share on the right.
 */
export function AppLayout({ initial }: AppLayoutProps) {
  const session = useSimulatorSession(initial.state, appViews, true);
  const { state, dispatch, client, cycle, point, t, playhead } = session;
  const onLab = state.shell.page === 'lab';
  const onSynthesis = state.shell.page === 'synthesis';
  // A phone's simulator page: the phone bar at the bottom and the other controls in a sheet (ControlsColumn).
  const phone = useMediaQuery(PHONE_MEDIA) && state.shell.page === 'simulator';
  const shell = shellMessages(state.shell.locale);
  // Ready: what the first screen shows is drawn with the solver's answers. On a phone the results column is
  // below the fold (under the linkage and the plots): the page is ready without it, and it mounts once the first
  // answers are drawn, so it does not hold them up. Elsewhere it is on screen and comes just after the first
  // frame: the first render posts the solver's jobs sooner, and the worker solves while the column renders (the
  // first load, docs/ARCHITECTURE.md). The transmission plot, below the fold too, comes with the column.
  const answered = Boolean(cycle && point);
  const resultsShown = useAfterFirstFrame(!phone || answered);
  const ready = answered && (resultsShown || phone);
  useDocumentMeta(t.htmlLang, t.appTitle);
  useUrlSync(state);

  return (
    <MessagesContext.Provider value={t}>
      <FramePoseProvider state={state} playhead={playhead} scrub={session.scrub} ghostShown={!onLab}>
        <SkipLink targetId={MAIN_ID} label={shell.skipToMain} />
        <div className={`app${onSynthesis ? ' app-synthesis' : ''}`} data-ready={ready ? 'true' : 'false'}>
          <header className="topbar">
            <Brand />
            <PageTabs
              page={state.shell.page}
              dispatch={dispatch}
              panelId={PANEL_ID}
              synthesisLabel={shell.viewSynthesis}
            />
            <DesignBar
              state={state}
              dispatch={dispatch}
              undo={session.undo}
              redo={session.redo}
              canUndo={session.canUndo}
              canRedo={session.canRedo}
            />
            <LanguageSelect locale={state.shell.locale} dispatch={dispatch} />
          </header>
          <UrlNotice ignored={initial.ignored} />
          {onSynthesis ? null : <ControlsColumn session={session} label={shell.controlsLabel} phone={phone} />}
          <main className="app-main" id={MAIN_ID} tabIndex={-1}>
            <div
              className={`main${onLab ? ' main-lab' : ''}${onSynthesis ? ' main-synthesis' : ''}`}
              // One panel element per page: a page opens at its top, not at the last page's scroll.
              key={state.shell.page}
              id={PANEL_ID}
              role="tabpanel"
              aria-labelledby={pageTabId(state.shell.page)}
            >
              {onSynthesis ? (
                <Suspense fallback={<p className="note">{shell.viewSynthesis}…</p>}>
                  <SynthesisPage state={state} dispatch={dispatch} createPool={createSynthesisPool} />
                </Suspense>
              ) : onLab ? (
                <Suspense fallback={<p className="note">{t.labRun}…</p>}>
                  <LabPanel client={client} state={state} dispatch={dispatch} />
                </Suspense>
              ) : (
                <SimulatorPage session={session} lateShown={resultsShown} />
              )}
            </div>
          </main>
          {onSynthesis ? null : resultsShown ? (
            <ResultsSidebar session={session} label={shell.resultsLabel} />
          ) : (
            <aside className="rightbar" aria-label={shell.resultsLabel} />
          )}
        </div>
      </FramePoseProvider>
    </MessagesContext.Provider>
  );
}
