import { Suspense, lazy, useCallback, useEffect, useLayoutEffect, useMemo, useReducer, useRef, useState } from 'react';
import type { Dispatch } from 'react';
// The angles module alone: importing the barrel would pull the whole solver into the main bundle.
import { degToRad, radToDeg, radToDeg360 } from '../solver/angles';
import type { Branch } from '../solver/types';
import type { BranchExtent, SceneText } from '../render/scene';
import { sceneBounds, sceneCurves, scenePose } from '../render/scene';
import type { LinkageScene } from '../render/scene';
import { advanceTheta2, degreesForElapsed, rangeToDeg } from '../state/animation';
import type { Action, AppState, Locale } from '../state/appState';
import { reducer } from '../state/appState';
import type { ExportSubject, PngSize } from '../state/fileNames';
import { csvFileName, pngFileName } from '../state/fileNames';
import { formatDeg, formatIntervalsDeg, formatNumber } from '../state/format';
import { LOCALES, getMessages } from '../state/i18n';
import { LOCALE_STORAGE_KEY, writeStorage } from '../state/storage';
import type { ParsedUrl } from '../state/url';
import { appUrl, serializeState } from '../state/url';
import { AnalysisPanel } from './AnalysisPanel';
import { AnglePlotsPanel } from './AnglePlotsPanel';
import { angleChartInputs, angleMarker, convergenceInputs, cycleDegrees } from './chartInputs';
import { ControlsPanel } from './ControlsPanel';
import { ConvergencePanel } from './ConvergencePanel';
import { ExportPanel } from './ExportPanel';
import { angleChartPng, convergencePng, downloadCsv, downloadPng, linkagePng } from './exporters';
import { Icon } from './Icon';
import { LinkageCanvas } from './LinkageCanvas';
import { MessagesContext } from './MessagesContext';
import { SharePanel } from './SharePanel';
import { useAnimationFrame } from './useAnimationFrame';
import { useCycle, usePoint, useSolverClient } from './useSolver';
import { useElementSize } from './useElementSize';
import { decodeStatuses } from '../worker/statusCodes';

// The solver lab (its charts and tables) loads only when it is opened.
const LabPanel = lazy(() => import('./LabPanel').then((m) => ({ default: m.LabPanel })));

/** The full app or the compact embeddable widget. */
export type AppMode = 'app' | 'embed';

/** Props of App: which layout, and the state and embed options parsed from the URL. */
export interface AppProps {
  mode: AppMode;
  initial: ParsedUrl;
}

/** Logical (CSS pixel) size of exported angle plots and of the exported convergence plot. */
export const ANGLE_EXPORT_SIZE = { width: 640, height: 360 } as const;
export const CONVERGENCE_EXPORT_SIZE = { width: 560, height: 340 } as const;

function LanguageSelect({ locale, dispatch }: { locale: Locale; dispatch: Dispatch<Action> }) {
  const t = getMessages(locale);
  return (
    <label className="lang-select">
      <span className="sr-only">{t.language}</span>
      <span className="lang-icon">
        <Icon name="language" />
      </span>
      <select
        className="select select-small"
        aria-label={t.language}
        value={locale}
        onChange={(e) => {
          const l = e.target.value as Locale;
          writeStorage(LOCALE_STORAGE_KEY, l);
          dispatch({ type: 'setLocale', locale: l });
        }}
      >
        {LOCALES.map((l) => (
          <option key={l} value={l}>
            {t.languageNames[l]}
          </option>
        ))}
      </select>
    </label>
  );
}

/** The simulator: state, solver client, animation, canvas, panels, plots, export and share, in either layout. */
export function App({ mode, initial }: AppProps) {
  const [state, dispatch] = useReducer(reducer, initial.state);
  const embedOptions = initial.embed;
  const t = getMessages(state.locale);
  const { client, mode: solverMode } = useSolverClient();
  const onLab = mode === 'app' && state.page === 'lab';
  // A callback ref kept in state, so the size follows the plots card when it is mounted again (page switch).
  const [plotsEl, setPlotsEl] = useState<HTMLElement | null>(null);
  const plotsSize = useElementSize(useMemo(() => ({ current: plotsEl }), [plotsEl]));
  const showPlots = mode === 'embed' ? initial.embed.panels.includes('plots') : !onLab;
  const dpr = typeof window !== 'undefined' ? window.devicePixelRatio || 1 : 1;
  // Only what the visible views show is computed: plot samples follow the plots' pixel width.
  const plotPixels = showPlots && plotsSize.width > 0 ? Math.round(plotsSize.width * dpr) : 0;
  const solver = useMemo(() => ({ method: state.method, tol: state.tol }), [state.method, state.tol]);
  const cycleNeeds = useMemo(
    () => ({
      solver,
      branch: state.branch,
      otherBranch: state.showGhost,
      curves: state.showTrace && !onLab,
      plotPixels,
    }),
    [solver, state.branch, state.showGhost, state.showTrace, onLab, plotPixels],
  );
  const pointNeeds = useMemo(
    () => ({
      solver,
      ghost: state.showGhost && !onLab,
      newton: mode === 'app' || initial.embed.panels.includes('info'),
    }),
    [solver, state.showGhost, onLab, mode, initial.embed.panels],
  );
  const { cycle, error: cycleError } = useCycle(client, state.linkage, state.samples, state.coupler, cycleNeeds);
  const point = usePoint(
    client,
    state.linkage,
    state.branch,
    state.theta2Deg,
    state.samples,
    state.coupler,
    pointNeeds,
  );
  const deg = useMemo(() => (cycle ? cycleDegrees(cycle) : null), [cycle]);
  const rangeDeg = useMemo(() => (cycle ? rangeToDeg(cycle.classification.inputRange) : null), [cycle]);
  const rocking = cycle
    ? !cycle.classification.inputRange.full && cycle.classification.inputRange.intervals.length > 0
    : false;

  useLayoutEffect(() => {
    // After the children's layout effects: the plots now show this cycle. The UI benchmark listens for it.
    if (cycle && typeof performance.mark === 'function')
      performance.mark('fourbar:cycle-drawn', { detail: { ...cycle.linkage } });
  }, [cycle]);

  const stateRef = useRef<AppState>(state);
  stateRef.current = state;
  const rangeRef = useRef(rangeDeg);
  rangeRef.current = rangeDeg;

  useAnimationFrame(state.playing, (dt) => {
    const s = stateRef.current;
    const r = rangeRef.current;
    if (!r) return;
    const next = advanceTheta2(s.theta2Deg, degreesForElapsed(s.speedDegPerFrame, dt), s.direction, s.branch, r);
    dispatch({ type: 'animate', ...next });
  });

  const onStep = useCallback((sign: 1 | -1) => {
    const s = stateRef.current;
    const r = rangeRef.current ?? { full: true, intervals: [] };
    const next = advanceTheta2(s.theta2Deg, 360 / s.samples, sign, s.branch, r);
    dispatch({ type: 'animate', theta2Deg: next.theta2Deg, branch: next.branch, direction: s.direction });
  }, []);

  useEffect(() => {
    document.documentElement.lang = t.htmlLang;
    document.title = mode === 'embed' ? t.embedTitle : t.appTitle;
  }, [t, mode]);

  useEffect(() => {
    // Keep the address bar in step (debounced; not while animating, which would flood the history API).
    if (state.playing) return;
    const id = setTimeout(() => {
      try {
        const q = serializeState(state, mode === 'embed' ? embedOptions : undefined);
        window.history.replaceState(window.history.state, '', `${window.location.pathname}?${q}`);
      } catch {
        // Some sandboxed frames refuse history changes; the state still lives in the app.
      }
    }, 250);
    return () => clearTimeout(id);
  }, [state, mode, embedOptions]);

  // The scene is built from the point answer's own lengths, so a pose is never drawn with other lengths.
  const sceneLinkage = point ? point.linkage : state.linkage;
  const sceneCoupler = useMemo(
    () => (point ? point.coupler : { distance: state.coupler.distance, angleRad: degToRad(state.coupler.angleDeg) }),
    [point, state.coupler.distance, state.coupler.angleDeg],
  );
  const pose = useMemo(
    () => scenePose(sceneLinkage, point?.pose ?? null, sceneCoupler),
    [sceneLinkage, point, sceneCoupler],
  );
  const ghost = useMemo(
    () => scenePose(sceneLinkage, point?.ghost ?? null, sceneCoupler),
    [sceneLinkage, point, sceneCoupler],
  );
  const theta2Rad = point ? point.theta2Rad : degToRad(state.theta2Deg);
  const drawBranch: Branch = point ? point.branch : state.branch;
  const curves = useMemo(
    () => (cycle ? sceneCurves(cycle.curves, drawBranch, theta2Rad) : []),
    [cycle, drawBranch, theta2Rad],
  );
  const cycleBounds = useMemo(() => {
    if (!cycle) return null;
    const other: Branch = drawBranch === 'open' ? 'crossed' : 'open';
    const ext = (b: Branch): BranchExtent => ({ theta4: cycle[b].theta4, px: cycle[b].px, py: cycle[b].py });
    const both = state.showGhost || rocking;
    return sceneBounds(cycle.linkage, both ? [ext(drawBranch), ext(other)] : [ext(drawBranch)], [], []);
  }, [cycle, drawBranch, state.showGhost, rocking]);
  // Before the first cycle arrives, fit the pose itself.
  const bounds = cycleBounds ?? sceneBounds(sceneLinkage, [], [], [pose, ghost]);

  const classification = cycle?.classification ?? null;
  const theta2Text = formatDeg(radToDeg360(theta2Rad), 2);
  const warning =
    point && !point.pose
      ? classification?.type === 'cannot-assemble'
        ? t.cannotAssembleAny
        : t.cannotAssembleAt(theta2Text)
      : null;
  const warningDetail =
    warning &&
    classification &&
    classification.type !== 'cannot-assemble' &&
    classification.inputRange.intervals.length > 0
      ? t.reachableHint(formatIntervalsDeg(classification.inputRange.intervals, t.rangeInterval))
      : null;
  const text: SceneText = useMemo(
    () => ({
      ...t.jointLabels,
      warning,
      warningDetail,
      gridSpacing: t.gridSpacing,
      formatAngle: (d: number) => `${formatDeg(d, 1)}°`,
      formatLength: (x: number) => formatNumber(x, 4),
    }),
    [t, warning, warningDetail],
  );
  const scene: LinkageScene = useMemo(
    () => ({
      linkage: sceneLinkage,
      theta2: theta2Rad,
      pose,
      ghost,
      curves,
      showGrid: state.showGrid,
      showAngles: state.showAngles,
      showGhost: state.showGhost,
      showTrace: state.showTrace,
      text,
      bounds,
    }),
    [
      sceneLinkage,
      theta2Rad,
      pose,
      ghost,
      curves,
      state.showGrid,
      state.showAngles,
      state.showGhost,
      state.showTrace,
      text,
      bounds,
    ],
  );
  const description = pose
    ? `θ2 ${theta2Text}°, θ3 ${formatDeg(radToDeg(pose.theta3), 2)}°, θ4 ${formatDeg(radToDeg(pose.theta4), 2)}°, μ ${formatDeg(radToDeg(pose.mu), 2)}°`
    : (warning ?? '');

  const canvasSize = useRef({ width: 640, height: 420 });
  const onCanvasSize = useCallback((width: number, height: number) => {
    canvasSize.current = { width, height };
  }, []);
  const onViewChange = useCallback((view: AppState['view']) => dispatch({ type: 'setView', view }), []);

  const live = useRef({ state, point, cycle, deg, scene, t });
  live.current = { state, point, cycle, deg, scene, t };
  const onPng = useCallback(async (subject: ExportSubject, size: PngSize) => {
    const { state: s, point: p, deg: d, scene: sc, t: m } = live.current;
    const name = pngFileName(s.linkage, s.branch, s.theta2Deg, subject, size);
    let bytes: Uint8Array;
    if (subject === 'linkage') {
      bytes = await linkagePng(sc, s.view, canvasSize.current.width, canvasSize.current.height, size);
    } else if (subject === 'convergence') {
      const { width, height } = CONVERGENCE_EXPORT_SIZE;
      bytes = await convergencePng(convergenceInputs(p, s.nrStart, m), width, height, size);
    } else {
      const { width, height } = ANGLE_EXPORT_SIZE;
      bytes = await angleChartPng(
        angleChartInputs(subject, d, s.branch, s.showGhost, m),
        angleMarker(subject, p),
        width,
        height,
        size,
      );
    }
    downloadPng(bytes, name);
  }, []);
  const onCsv = useCallback(async () => {
    const { state: s, cycle: c } = live.current;
    if (!c) throw new Error('the cycle is still being solved');
    const b = c[s.branch];
    downloadCsv(
      {
        theta2Deg: c.theta2Deg,
        theta3Rad: b.theta3,
        theta4Rad: b.theta4,
        status: decodeStatuses(b.statusCodes),
        iterations: b.iterations,
        residual: b.residual,
      },
      csvFileName(c.linkage, s.branch, c.samples),
    );
  }, []);

  const canvas = (
    <LinkageCanvas
      scene={scene}
      view={state.view}
      onViewChange={onViewChange}
      onSize={onCanvasSize}
      description={description}
    />
  );
  const solverNote = solverMode === 'main-thread' ? <p className="note note-muted">{t.solvingOnMainThread}</p> : null;
  const errorNote = cycleError ? (
    <p className="note note-error" role="alert">
      {cycleError}
    </p>
  ) : null;

  if (mode === 'embed') {
    const show = (p: (typeof embedOptions.panels)[number]) => embedOptions.panels.includes(p);
    let fullHref = '';
    try {
      fullHref = appUrl(window.location.href, state);
    } catch {
      fullHref = '';
    }
    return (
      <MessagesContext.Provider value={t}>
        <div className="embed" data-ready={cycle && point ? 'true' : 'false'}>
          <header className="embed-bar">
            <h1 className="embed-title">{t.embedTitle}</h1>
            <div className="embed-bar-right">
              <LanguageSelect locale={state.locale} dispatch={dispatch} />
              {fullHref ? (
                <a className="embed-link" href={fullHref} target="_blank" rel="noopener noreferrer">
                  {t.openFull} ↗
                </a>
              ) : null}
            </div>
          </header>
          <div className={`embed-body${show('controls') ? ' with-controls' : ''}`}>
            <div className="embed-stage">{canvas}</div>
            {show('controls') ? (
              <aside className="embed-controls">
                <ControlsPanel
                  state={state}
                  dispatch={dispatch}
                  locked={embedOptions.locked}
                  compact
                  rocking={rocking}
                  onStep={onStep}
                />
              </aside>
            ) : null}
          </div>
          {show('info') ? (
            <section className="card embed-card">
              <AnalysisPanel cycle={cycle} point={point} branch={state.branch} nrStart={state.nrStart} />
            </section>
          ) : null}
          {show('plots') ? (
            <section className="card embed-card embed-plots" ref={setPlotsEl}>
              <AnglePlotsPanel
                deg={deg}
                point={point}
                branch={state.branch}
                showOther={state.showGhost}
                layout={state.plotLayout}
                dispatch={dispatch}
              />
            </section>
          ) : null}
          {show('export') ? (
            <section className="card embed-card">
              <ExportPanel onPng={onPng} onCsv={onCsv} compact />
            </section>
          ) : null}
          {solverNote}
          {errorNote}
        </div>
      </MessagesContext.Provider>
    );
  }

  return (
    <MessagesContext.Provider value={t}>
      <div className="app" data-ready={cycle && point ? 'true' : 'false'}>
        <header className="topbar">
          <div className="brand">
            <svg className="logo" viewBox="0 0 32 32" aria-hidden="true">
              <path
                d="M5 25 L11 12 L24 9 L27 25"
                fill="none"
                stroke="currentColor"
                strokeWidth="2.4"
                strokeLinejoin="round"
              />
              <circle cx="5" cy="25" r="2.6" fill="#fff" stroke="currentColor" strokeWidth="1.6" />
              <circle cx="27" cy="25" r="2.6" fill="#fff" stroke="currentColor" strokeWidth="1.6" />
              <circle cx="11" cy="12" r="2.2" fill="#fff" stroke="currentColor" strokeWidth="1.6" />
              <circle cx="24" cy="9" r="2.2" fill="#fff" stroke="currentColor" strokeWidth="1.6" />
            </svg>
            <div>
              <h1 className="app-title">{t.appTitle}</h1>
              <p className="app-subtitle">{t.appSubtitle}</p>
            </div>
          </div>
          <div className="page-tabs" role="tablist" aria-label={t.viewSimulator + ' / ' + t.viewLab}>
            {(['simulator', 'lab'] as const).map((p) => (
              <button
                key={p}
                type="button"
                role="tab"
                id={`tab-${p}`}
                aria-selected={state.page === p}
                aria-controls="page-main"
                className={`page-tab${state.page === p ? ' active' : ''}`}
                onClick={() => dispatch({ type: 'setPage', page: p })}
              >
                {p === 'simulator' ? t.viewSimulator : t.viewLab}
              </button>
            ))}
          </div>
          <LanguageSelect locale={state.locale} dispatch={dispatch} />
        </header>
        <aside className="sidebar" aria-label={t.sectionLinks}>
          <ControlsPanel state={state} dispatch={dispatch} rocking={rocking} onStep={onStep} />
        </aside>
        <main
          className={`main${onLab ? ' main-lab' : ''}`}
          id="page-main"
          role="tabpanel"
          aria-labelledby={`tab-${state.page}`}
        >
          {onLab ? (
            <Suspense fallback={<p className="note">{t.labRun}…</p>}>
              <LabPanel client={client} state={state} dispatch={dispatch} />
            </Suspense>
          ) : (
            <>
              <section className="card stage">{canvas}</section>
              <section className="card plots" aria-label={t.sectionPlots} ref={setPlotsEl}>
                <AnglePlotsPanel
                  deg={deg}
                  point={point}
                  branch={state.branch}
                  showOther={state.showGhost}
                  layout={state.plotLayout}
                  dispatch={dispatch}
                />
              </section>
            </>
          )}
        </main>
        <aside className="rightbar">
          <section className="card" aria-labelledby="sec-analysis">
            <h2 id="sec-analysis" className="section-title">
              {t.sectionAnalysis}
            </h2>
            <AnalysisPanel cycle={cycle} point={point} branch={state.branch} nrStart={state.nrStart} />
            {errorNote}
          </section>
          <section className="card convergence-card">
            <ConvergencePanel point={point} nrStart={state.nrStart} dispatch={dispatch} />
          </section>
          <section className="card" aria-labelledby="sec-export">
            <h2 id="sec-export" className="section-title">
              {t.sectionExport}
            </h2>
            <ExportPanel onPng={onPng} onCsv={onCsv} />
          </section>
          <section className="card" aria-labelledby="sec-share">
            <h2 id="sec-share" className="section-title">
              {t.sectionShare}
            </h2>
            <SharePanel state={state} pageHref={window.location.href} />
          </section>
          {solverNote}
        </aside>
      </div>
    </MessagesContext.Provider>
  );
}
