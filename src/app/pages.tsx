import { Suspense, lazy } from 'react';
import type { ReactNode } from 'react';
import type { Locale, Page } from '../shared/state/appState';
import { SimulatorPage } from './SimulatorPage';
import type { SimulatorSession } from './useSimulatorSession';
import { createSolverPool } from '../workers/solverClient';
import type { MechanismPageProps } from '../features/mechanism/MechanismPage';

// The solver lab (its charts and tables) and the synthesis page load only when they are opened.
const LabPanel = lazy(() => import('../features/lab/LabPanel').then((m) => ({ default: m.LabPanel })));
const SynthesisPage = lazy(() =>
  import('../features/synthesis/SynthesisPage').then((m) => ({ default: m.SynthesisPage })),
);

// The mechanism page loads with its live stage's client (Play and a joint's drag drawn in a worker).
const MechanismPage = lazy(() =>
  Promise.all([import('../features/mechanism/MechanismPage'), import('../workers/mechStageClient')]).then(([m, c]) => ({
    default: (props: MechanismPageProps) => <m.MechanismPage {...props} createStage={c.createMechStage} />,
  })),
);
const SpatialPage = lazy(() => import('../features/spatial/SpatialPage').then((m) => ({ default: m.SpatialPage })));

/** The address's query as the app was opened (before the URL sync rewrites it): the mechanism page says why a mech= was refused. */
const OPENED_SEARCH = typeof window === 'undefined' ? '' : window.location.search;

/** The synthesis page's pool of solver workers (cores − 1, at least one), made on its first run. */
const createSynthesisPool = () => createSolverPool();

/** What a page's view is drawn from: the simulator's session (state, dispatch, client) and the first frame's flag. */
export interface PageContext {
  session: SimulatorSession;
  /** Whether the parts that follow the first frame are shown yet (the simulator's late panels). */
  lateShown: boolean;
}

/** One page of the app: its tab's name, its view, and how the shell lays it out. */
export interface PageEntry {
  /** The tab's name in each language (a language the app adds and a page forgets is a type error). */
  label: Record<Locale, string>;
  /** The page's view in the tab panel; a lazily loaded page wraps itself in Suspense with its own fallback. */
  view(ctx: PageContext): ReactNode;
  /** Whether the shell shows the simulator's controls column and results column beside the page. */
  sideColumns: boolean;
  /** Classes on the page's panel (`main-<id>`) and on the app (`app-<id>`) for its own layout, if any. */
  layoutClass?: string;
}

/** A lazily loaded view with a fallback naming the page while its chunk loads. */
function loading(label: Record<Locale, string>, locale: Locale, view: ReactNode): ReactNode {
  return <Suspense fallback={<p className="note">{label[locale]}…</p>}>{view}</Suspense>;
}

const LAB_LABEL = { en: 'Solver lab', 'zh-TW': '求解器實驗室' };
const SYNTHESIS_LABEL = { en: 'Synthesis', 'zh-TW': '機構合成' };
const MECHANISM_LABEL = { en: 'Mechanisms', 'zh-TW': '機構' };
const SPATIAL_LABEL = { en: 'Spatial', 'zh-TW': '空間機構' };

/**
 * Every page of the app, registered once, in the tabs' order: the tabs (PageTabs), the page's view and layout
 * (AppLayout) come from here; its id and URL value (page=…) from PAGE_URL_VALUES in the shell slice, which makes
 * a page missing here a type error. docs/ARCHITECTURE.md "To add a page".
 */
export const PAGES: Readonly<Record<Page, PageEntry>> = {
  simulator: {
    label: { en: 'Simulator', 'zh-TW': '模擬器' },
    view: ({ session, lateShown }) => <SimulatorPage session={session} lateShown={lateShown} />,
    sideColumns: true,
  },
  lab: {
    label: LAB_LABEL,
    view: ({ session: s }) =>
      loading(LAB_LABEL, s.state.shell.locale, <LabPanel client={s.client} state={s.state} dispatch={s.dispatch} />),
    sideColumns: true,
    layoutClass: 'lab',
  },
  synthesis: {
    label: SYNTHESIS_LABEL,
    view: ({ session: s }) =>
      loading(
        SYNTHESIS_LABEL,
        s.state.shell.locale,
        <SynthesisPage state={s.state} dispatch={s.dispatch} createPool={createSynthesisPool} />,
      ),
    sideColumns: false,
    layoutClass: 'synthesis',
  },
  mechanism: {
    label: MECHANISM_LABEL,
    view: ({ session: s }) =>
      loading(
        MECHANISM_LABEL,
        s.state.shell.locale,
        <MechanismPage state={s.state} dispatch={s.dispatch} client={s.client} openedSearch={OPENED_SEARCH} />,
      ),
    sideColumns: false,
    layoutClass: 'mechanism',
  },
  spatial: {
    label: SPATIAL_LABEL,
    view: ({ session: s }) =>
      loading(SPATIAL_LABEL, s.state.shell.locale, <SpatialPage state={s.state} dispatch={s.dispatch} />),
    sideColumns: false,
    layoutClass: 'spatial',
  },
};

/** The pages in the tabs' order. */
export const PAGE_ORDER = Object.keys(PAGES) as Page[];
