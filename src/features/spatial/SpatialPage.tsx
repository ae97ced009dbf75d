import './SpatialPage.css';
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
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
import { playStep } from './spatialPlay';
import type { SpatialFrame } from './spatialPlayhead';
import { SpatialPlayhead } from './spatialPlayhead';
import type { SpatialScene } from './spatialScene';
import type { ViewStatus } from './SpatialView';
import { SpatialView } from './SpatialView';
import { muAt, poseAt, useSpatialAnalysis } from './useSpatialAnalysis';
import type { PlayAt } from './viewProtocol';

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

/**
 * The Spatial page (page=3d, issue 32): a spherical four-bar or an RSSR linkage in a three.js view, its controls and
 * presets, the numbers at θ2, θ4 ω4 α4 μ against θ2, and the PNG, CSV and link exports.
 */
export function SpatialPage({ state, dispatch, embed }: SpatialPageProps) {
  const s = state.spatial;
  const sm = spatialMessagesFor(state.shell.locale);
  const { analysis, error } = useSpatialAnalysis(s);
  const model = analysis?.model ?? null;
  const input = analysis?.input ?? null;
  const pose = useMemo(
    () => (model && input ? poseAt(model, s.theta2Deg, s.branch, input) : null),
    [model, input, s.theta2Deg, s.branch],
  );
  const muRad = useMemo(() => (model ? muAt(model, s.theta2Deg, s.branch) : null), [model, s.theta2Deg, s.branch]);
  const linkage = analysis?.scene ?? null;
  const shownPose = useMemo(() => (linkage && pose ? scenePose(linkage, pose) : null), [linkage, pose]);
  const sceneRef = useRef<SpatialScene | null>(null);
  const [playing, setPlaying] = useState(false);
  const direction = useRef<1 | -1>(1);
  const [playhead] = useState(() => new SpatialPlayhead());
  const base = useMemo<SpatialFrame>(
    () => ({ theta2Deg: s.theta2Deg, branch: s.branch, pose, muRad }),
    [s.theta2Deg, s.branch, pose, muRad],
  );
  const [notice, setNotice] = useState<string | null>(null);
  const [viewStatus, setViewStatus] = useState<ViewStatus>('loading');
  /** The view runs Play itself (drawn in its worker): the page follows its frames instead of running Play. */
  const [viewPlays, setViewPlays] = useState(false);
  const onViewStatus = useCallback((status: ViewStatus, playsItself: boolean) => {
    setViewStatus(status);
    setViewPlays(status === 'ready' && playsItself);
  }, []);
  const pngOff = viewStatus === 'ready' ? null : viewStatus === 'no-webgl' ? sm.pngNeedsWebgl : sm.pngLoading;

  // A change of the state (an edit, a commit) or of the linkage hands the view back to the state.
  useEffect(() => playhead.set(null), [playhead, base]);

  // Play moves the playhead and the 3D view every frame without touching the app state (no page or app render per
  // frame); the state gets θ2 and the branch when Play stops or turns back at a limit (spatialPlay.ts). Where the view
  // draws in its worker, the worker runs Play on its own clock and the page's panels follow its frames.
  useAnimationFrame(playing && !viewPlays && model !== null && input !== null, (dt) => {
    if (!model || !input) return;
    const from = playhead.current() ?? base;
    const step = playStep(model, input, { ...from, direction: direction.current }, dt);
    direction.current = step.direction;
    if (step.turned) {
      dispatch({ type: 'setSpatial', patch: { theta2Deg: step.theta2Deg, branch: step.branch } });
      return;
    }
    const frame = {
      theta2Deg: step.theta2Deg,
      branch: step.branch,
      pose: step.pose,
      muRad: muAt(model, step.theta2Deg, step.branch),
    };
    playhead.advance(frame, performance.now());
    if (linkage && step.pose) sceneRef.current?.setPose(scenePose(linkage, step.pose));
  });
  // The worker's Play starts from the state, and again from it after each change of the state or linkage (as the
  // page's Play does: the playhead goes back to the state), or stops.
  useEffect(() => {
    if (!viewPlays) return;
    const run = playing && model && input ? { model, input, theta2Deg: base.theta2Deg, branch: base.branch } : null;
    sceneRef.current?.play?.(run);
  }, [viewPlays, playing, model, input, base]);
  /** A frame of the worker's Play: the panels follow it (at most every PANEL_INTERVAL_MS), a turn goes to the state. */
  const onPlayFrame = (at: PlayAt) => {
    if (!playing || !model || !input) return;
    if (at.turned) {
      dispatch({ type: 'setSpatial', patch: { theta2Deg: at.theta2Deg, branch: at.branch } });
      return;
    }
    const framePose = poseAt(model, at.theta2Deg, at.branch, input);
    const muRadAt = muAt(model, at.theta2Deg, at.branch);
    playhead.advance(
      { theta2Deg: at.theta2Deg, branch: at.branch, pose: framePose, muRad: muRadAt },
      performance.now(),
    );
  };

  /** Play on or off; off commits the frame on screen to the state (the link, the fields). */
  const onPlay = (on: boolean) => {
    const f = playhead.current();
    if (!on && f) {
      dispatch({ type: 'setSpatial', patch: { theta2Deg: f.theta2Deg, branch: f.branch } });
      playhead.set(null);
    }
    setPlaying(on);
  };
  const shows = (part: 'controlsShown' | 'numbersShown' | 'plotsShown') => !embed || embed[part];
  const onStep = (d: number) => {
    const f = playhead.current() ?? base;
    setPlaying(false);
    dispatch({ type: 'setSpatial', patch: { theta2Deg: normalizeTheta2Deg(f.theta2Deg + d), branch: f.branch } });
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
    if (!model || !input) return;
    try {
      downloadText(spatialCsvText(model, s.branch, input), `${spatialFileStem(s)}.csv`, 'text/csv;charset=utf-8');
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
            onStatus={onViewStatus}
            onPlayFrame={onPlayFrame}
          />
        </section>
        <div className="spatial-side" hidden={!shows('controlsShown')}>
          <PanelSection id="spatial-controls-title" title={sm.kindLegend}>
            <SpatialControls
              s={s}
              dispatch={dispatch}
              playing={playing}
              onPlay={onPlay}
              onStep={onStep}
              sm={sm}
              playhead={playhead}
              locked={embed?.locks}
            />
          </PanelSection>
        </div>
        <div className="spatial-results" hidden={!shows('numbersShown')}>
          <PanelSection id="spatial-numbers-title" title={sm.numbersSection}>
            {analysis ? (
              <SpatialNumbers analysis={analysis} playhead={playhead} base={base} sm={sm} />
            ) : (
              <p className="spatial-warning" role="alert">
                {error}
              </p>
            )}
          </PanelSection>
          {embed ? null : (
            <PanelSection id="spatial-exports-title" title={sm.exportsTitle}>
              <div className="spatial-exports">
                <button
                  type="button"
                  className="btn"
                  onClick={onPng}
                  disabled={pngOff !== null}
                  title={pngOff ?? undefined}
                  aria-describedby={viewStatus === 'no-webgl' ? 'spatial-png-off' : undefined}
                >
                  {sm.exportPng}
                </button>
                <button type="button" className="btn" onClick={onCsv} disabled={!model}>
                  {sm.exportCsv}
                </button>
                <button type="button" className="btn" onClick={onCopyLink}>
                  {sm.copyLink}
                </button>
              </div>
              {viewStatus === 'no-webgl' ? (
                <p id="spatial-png-off" className="note spatial-png-off">
                  {pngOff}
                </p>
              ) : null}
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
          <SpatialPlots analysis={analysis} playhead={playhead} base={base} sm={sm} />
        </PanelSection>
      ) : null}
    </div>
  );
}
