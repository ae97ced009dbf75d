import './AppLayout.css';
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
import { PAGES } from './pages';
import { SkipLink } from './SkipLink';
import { useDocumentMeta } from './useDocumentMeta';
import { useAfterFirstFrame } from '../shared/hooks/useAfterFirstFrame';
import { useSimulatorSession } from './useSimulatorSession';
import type { ShownFor, SimulatorSession } from './useSimulatorSession';
import { FramePoseProvider } from '../features/simulator/FramePoseProvider';
import { useUrlSync } from './useUrlSync';
import { UrlNotice } from './UrlNotice';

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

/** Ids of the main landmark (the skip link's target) and of the page tab panel inside it. */
const MAIN_ID = 'main-content';
const PANEL_ID = 'page-panel';

/**
 * The full app: top bar (title, Simulator / Solver lab tabs, language), controls on the left, the linkage
 * and its plots (or the lab) in the middle, numbers, convergence, export and share on the right.
 */
export function AppLayout({ initial }: AppLayoutProps) {
  const session = useSimulatorSession(initial.state, appViews, true);
  const { state, dispatch, cycle, point, t, playhead } = session;
  const page = PAGES[state.shell.page];
  const pageClass = (prefix: string) => (page.layoutClass ? ` ${prefix}-${page.layoutClass}` : '');
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
      <FramePoseProvider
        state={state}
        playhead={playhead}
        scrub={session.scrub}
        ghostShown={state.shell.page !== 'lab'}
      >
        <SkipLink targetId={MAIN_ID} label={shell.skipToMain} />
        <div className={`app${pageClass('app')}`} data-ready={ready ? 'true' : 'false'}>
          <header className="topbar">
            <Brand />
            <PageTabs page={state.shell.page} locale={state.shell.locale} dispatch={dispatch} panelId={PANEL_ID} />
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
          {page.sideColumns && <ControlsColumn session={session} label={shell.controlsLabel} phone={phone} />}
          <main className="app-main" id={MAIN_ID} tabIndex={-1}>
            <div
              className={`main${pageClass('main')}`}
              // One panel element per page: a page opens at its top, not at the last page's scroll.
              key={state.shell.page}
              id={PANEL_ID}
              role="tabpanel"
              aria-labelledby={pageTabId(state.shell.page)}
            >
              {page.view({ session, lateShown: resultsShown })}
            </div>
          </main>
          {page.sideColumns && <ResultsColumn session={session} label={shell.resultsLabel} shown={resultsShown} />}
        </div>
      </FramePoseProvider>
    </MessagesContext.Provider>
  );
}

/** The results column, or its empty landmark until it mounts just after the first frame. */
function ResultsColumn({ session, label, shown }: { session: SimulatorSession; label: string; shown: boolean }) {
  return shown ? <ResultsSidebar session={session} label={label} /> : <aside className="rightbar" aria-label={label} />;
}
