import './SpatialPage.css';
import { useMemo, useRef, useState } from 'react';
import type { Dispatch } from 'react';
import { downloadPng, downloadText } from '../../shared/canvas/download';
import { formatDeg } from '../../shared/format';
import { useAnimationFrame } from '../../shared/hooks/useAnimationFrame';
import type { Action, AppState } from '../../shared/state/appState';
import { normalizeTheta2Deg } from '../../shared/state/appState';
import { copyText } from '../../shared/ui/clipboard';
import { PanelSection } from '../../shared/ui/PanelSection';
import { serializeState } from '../../shared/url/url';
import { scenePose } from './sceneData';
import type { SpatialLocks } from './SpatialControls';
import { SpatialControls } from './SpatialControls';
import { spatialCsvText, spatialFileStem } from './spatialExports';
import { spatialMessagesFor } from './spatialMessages';
import { SpatialNumbers } from './SpatialNumbers';
import { SpatialPlots } from './SpatialPlots';
import type { SpatialScene } from './spatialScene';
import { SpatialView } from './SpatialView';
import { muAt, poseAt, useSpatialAnalysis } from './useSpatialAnalysis';

/** Props of SpatialPage: the app state and dispatch. */
export interface SpatialPageProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  /** In the embed (page=3d in embed.html or <fourbar-lab>): its panels and locks; absent: the full page. */
  embed?: SpatialEmbedOptions;
}

/** What an embed of the page shows (the controls, the numbers, the plots; the 3D view always) and locks. */
export interface SpatialEmbedOptions {
  controlsShown: boolean;
  numbersShown: boolean;
  plotsShown: boolean;
  locks: SpatialLocks;
}

/** Play's speed, degrees of θ2 per second. */
export const PLAY_DEG_PER_S = 90;

/**
 * The Spatial page (page=3d, issue 32): a spherical four-bar or an RSSR linkage in a three.js view, its controls and
 * presets, the numbers at θ2, θ4 ω4 α4 μ against θ2, and the PNG, CSV and link exports.
 */
export function SpatialPage({ state, dispatch, embed }: SpatialPageProps) {
  const s = state.spatial;
  const sm = spatialMessagesFor(state.shell.locale);
  const { analysis, error } = useSpatialAnalysis(s);
  const model = analysis?.model ?? null;
  const pose = useMemo(() => (model ? poseAt(model, s.theta2Deg, s.branch) : null), [model, s.theta2Deg, s.branch]);
  const muRad = useMemo(() => (model ? muAt(model, s.theta2Deg, s.branch) : null), [model, s.theta2Deg, s.branch]);
  const linkage = analysis?.scene ?? null;
  const shownPose = useMemo(() => (linkage && pose ? scenePose(linkage, pose) : null), [linkage, pose]);
  const sceneRef = useRef<SpatialScene | null>(null);
  const [playing, setPlaying] = useState(false);
  const [direction, setDirection] = useState<1 | -1>(1);
  const [notice, setNotice] = useState<string | null>(null);

  useAnimationFrame(playing && model !== null, (dt) => {
    if (!model) return;
    const next = normalizeTheta2Deg(s.theta2Deg + direction * PLAY_DEG_PER_S * dt);
    if (poseAt(model, next, s.branch) === null) {
      // The input's limit: a real linkage goes back on the other branch (the two meet there).
      setDirection(direction === 1 ? -1 : 1);
      dispatch({ type: 'setSpatial', patch: { branch: s.branch === 'open' ? 'crossed' : 'open' } });
      return;
    }
    dispatch({ type: 'setSpatialField', field: 'theta2Deg', value: next });
  });

  const shows = (part: 'controlsShown' | 'numbersShown' | 'plotsShown') => !embed || embed[part];
  const onStep = (d: number) => {
    setPlaying(false);
    dispatch({ type: 'setSpatialField', field: 'theta2Deg', value: normalizeTheta2Deg(s.theta2Deg + d) });
  };
  const fail = (e: unknown) => setNotice(sm.exportFailed(e instanceof Error ? e.message : String(e)));
  const onPng = () => {
    const scene = sceneRef.current;
    if (!scene) return;
    scene
      .pngBytes(2)
      .then((bytes) => downloadPng(bytes, `${spatialFileStem(s)}_theta2-${Math.round(s.theta2Deg)}_3d.png`))
      .catch(fail);
  };
  const onCsv = () => {
    if (!model) return;
    try {
      downloadText(spatialCsvText(model, s.branch), `${spatialFileStem(s)}.csv`, 'text/csv;charset=utf-8');
    } catch (e) {
      fail(e);
    }
  };
  const onCopyLink = () => {
    const u = new URL(window.location.href);
    u.search = `?${serializeState(state)}`;
    void copyText(u.toString()).then((ok) => setNotice(ok ? sm.linkCopied : null));
  };

  return (
    <div className={`spatial-page${embed ? ' spatial-embedded' : ''}`} data-testid="spatial-page">
      {embed ? null : (
        <header className="spatial-head">
          <h1 className="spatial-title">{sm.pageTitle}</h1>
          <p className="note spatial-intro">{sm.pageIntro}</p>
        </header>
      )}
      <div className="spatial-main">
        <section className="spatial-view-area" aria-label={sm.viewLabel}>
          <SpatialView
            linkage={linkage}
            pose={shownPose}
            sm={sm}
            sceneRef={sceneRef}
            warning={sm.cannotClose(`${formatDeg(s.theta2Deg)}°`)}
          />
        </section>
        <div className="spatial-side" hidden={!shows('controlsShown')}>
          <PanelSection id="spatial-controls-title" title={sm.kindLegend}>
            <SpatialControls
              s={s}
              dispatch={dispatch}
              playing={playing}
              onPlay={setPlaying}
              onStep={onStep}
              sm={sm}
              locked={embed?.locks}
            />
          </PanelSection>
        </div>
        <div className="spatial-results" hidden={!shows('numbersShown')}>
          <PanelSection id="spatial-numbers-title" title={sm.numbersSection}>
            {analysis ? (
              <SpatialNumbers analysis={analysis} pose={pose} muRad={muRad} theta2Deg={s.theta2Deg} sm={sm} />
            ) : (
              <p className="spatial-warning" role="alert">
                {error}
              </p>
            )}
          </PanelSection>
          {embed ? null : (
            <PanelSection id="spatial-exports-title" title={sm.exportsTitle}>
              <div className="spatial-exports">
                <button type="button" className="btn" onClick={onPng}>
                  {sm.exportPng}
                </button>
                <button type="button" className="btn" onClick={onCsv} disabled={!model}>
                  {sm.exportCsv}
                </button>
                <button type="button" className="btn" onClick={onCopyLink}>
                  {sm.copyLink}
                </button>
              </div>
              {notice ? (
                <p className="note" role="status">
                  {notice}
                </p>
              ) : null}
            </PanelSection>
          )}
        </div>
      </div>
      {analysis && shows('plotsShown') ? (
        <PanelSection id="spatial-plots-title" title={sm.plotsTitle} className="panel-section spatial-plots-section">
          <SpatialPlots analysis={analysis} theta2Deg={s.theta2Deg} pose={pose} muRad={muRad} sm={sm} />
        </PanelSection>
      ) : null}
    </div>
  );
}
