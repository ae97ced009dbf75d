import { useEffect, useEffectEvent, useRef, useState } from 'react';
import type { KeyboardEvent, PointerEvent, RefObject } from 'react';
import { Segmented } from '../../shared/ui/Segmented';
import { HOLD_TIMEOUT_MS, KeyHold, ZOOM_STEP, applyMove } from './keyHold';
import { createWorkerScene } from './sceneClient';
import type { SceneLinkage, ScenePose } from './sceneData';
import type { SpatialMessages } from './spatialMessages';
import type { Projection, SpatialScene } from './spatialScene';
import { ViewGestures, wheelZoom } from './viewGestures';
import type { PlayAt, ViewMove } from './viewProtocol';
import { chooseViewRoute } from './viewRoute';
import { canTransferCanvas, probeWebgl } from './webglProbe';

/** Props of SpatialView: the fixed parts, the pose, the strings, and a ref the page's PNG export reads the scene from. */
export interface SpatialViewProps {
  linkage: SceneLinkage | null;
  pose: ScenePose | null;
  sm: SpatialMessages;
  sceneRef: RefObject<SpatialScene | null>;
  /** Shown over the view when the loop cannot close at θ2. */
  warning: string;
  /**
   * Told each time the view's status changes (the page turns its PNG export on only when ready), and whether the view
   * runs Play itself (drawn in its worker: the page then sets scene.play and follows onPlayFrame).
   */
  onStatus?: (status: ViewStatus, playsItself: boolean) => void;
  /** Each frame the view's worker drew during Play: where Play is. */
  onPlayFrame?: (at: PlayAt) => void;
}

/** Where the view is: its code loading, drawing, or without WebGL (the fallback message). */
export type ViewStatus = 'loading' | 'ready' | 'no-webgl';

/** The scene on the page's thread: three.js's chunk loads here, on this page only. */
async function mainThreadScene(canvas: HTMLCanvasElement, rendererName: string | null): Promise<SpatialScene> {
  const { createSpatialScene } = await import('./spatialScene');
  return createSpatialScene(canvas, {
    rendererName,
    devicePixelRatio: window.devicePixelRatio || 1,
    // Frames drawn so far, for bench:ui and the e2e (one attribute write per drawn frame).
    onFrame: (frames, layerFrames) => {
      canvas.dataset.frames = String(frames);
      canvas.dataset.layerFrames = String(layerFrames);
    },
    onQuality: (q, antialias) => {
      canvas.dataset.quality = q.name;
      canvas.dataset.antialias = String(antialias);
    },
  });
}

/**
 * The 3D view: three.js on a canvas sized to its box, drawn by a worker on an OffscreenCanvas where the browser can
 * (the page keeps its thread for the panels), else on the page's thread (its chunk loads here, on this page only);
 * orbit, zoom and pan by mouse, touch and keys; reset and projection tools. The canvas's data-route names where it
 * draws, data-frames counts its frames and data-layer-frames those drawn on the fixed parts' layer. Without WebGL a
 * message says so and the rest of the page works.
 */
export function SpatialView({ linkage, pose, sm, sceneRef, warning, onStatus, onPlayFrame }: SpatialViewProps) {
  const hostRef = useRef<HTMLDivElement>(null);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const [status, setStatus] = useState<ViewStatus>('loading');
  const [playsItself, setPlaysItself] = useState(false);
  const [projection, setProjection] = useState<Projection>('perspective');
  /** The worker failed on this page: the view draws on a fresh canvas on the page's thread. */
  const [workerFailed, setWorkerFailed] = useState(false);
  const playFrame = useEffectEvent((at: PlayAt) => onPlayFrame?.(at));

  useEffect(() => {
    let live = true;
    let made: SpatialScene | null = null;
    let observer: ResizeObserver | null = null;
    const canvas = canvasRef.current;
    const host = hostRef.current;
    if (!canvas || !host) return;
    const webgl = probeWebgl();
    const route = chooseViewRoute({ webgl: webgl !== null, canTransfer: canTransferCanvas(), workerFailed });
    canvas.dataset.route = route;
    const making =
      route === 'none' || !webgl
        ? Promise.reject(new Error('no WebGL'))
        : route === 'worker'
          ? createWorkerScene(canvas, webgl.rendererName, {
              onFrame: (frames, layerFrames, play) => {
                canvas.dataset.frames = String(frames);
                canvas.dataset.layerFrames = String(layerFrames);
                if (play) playFrame(play);
              },
              onQuality: (name, antialias) => {
                canvas.dataset.quality = name;
                canvas.dataset.antialias = String(antialias);
              },
            })
          : mainThreadScene(canvas, webgl.rendererName);
    making
      .then((scene) => {
        if (!live) {
          scene.dispose();
          return;
        }
        made = scene;
        sceneRef.current = scene;
        const fit = () => scene.resize(host.clientWidth, host.clientHeight, window.devicePixelRatio || 1);
        observer = new ResizeObserver(fit);
        observer.observe(host);
        fit();
        setPlaysItself(scene.play !== undefined);
        setStatus('ready');
      })
      .catch(() => {
        if (!live) return;
        if (route === 'worker') setWorkerFailed(true);
        else setStatus('no-webgl');
      });
    return () => {
      live = false;
      observer?.disconnect();
      made?.dispose();
      sceneRef.current = null;
    };
  }, [sceneRef, workerFailed]);

  useEffect(() => {
    onStatus?.(status, playsItself);
  }, [status, playsItself, onStatus]);

  // Mouse and touch: pointer gestures (viewGestures.ts) posted as moves; the wheel zooms (a listener that is not
  // passive, so the page does not scroll under the view).
  const [gestures] = useState(() => new ViewGestures());
  const apply = (moves: readonly ViewMove[]) => {
    const scene = sceneRef.current;
    if (!scene) return;
    for (const m of moves) applyMove(scene, m);
  };
  const applyMoves = useEffectEvent(apply);
  useEffect(() => {
    const host = hostRef.current;
    if (!host || status !== 'ready') return;
    const onWheel = (e: WheelEvent) => {
      e.preventDefault();
      applyMoves([wheelZoom(e.deltaMode === 1 ? e.deltaY * 33 : e.deltaY)]);
    };
    host.addEventListener('wheel', onWheel, { passive: false });
    return () => host.removeEventListener('wheel', onWheel);
  }, [status]);
  const onPointerDown = (e: PointerEvent<HTMLDivElement>) => {
    if ((e.target as HTMLElement).closest('button')) return;
    e.currentTarget.setPointerCapture(e.pointerId);
    const r = e.currentTarget.getBoundingClientRect();
    const pans = e.button === 2 || e.shiftKey || e.ctrlKey || e.metaKey;
    gestures.down({ id: e.pointerId, x: e.clientX - r.left, y: e.clientY - r.top, pans });
  };
  const onPointerMove = (e: PointerEvent<HTMLDivElement>) => {
    if (gestures.count === 0) return;
    const r = e.currentTarget.getBoundingClientRect();
    apply(gestures.move(e.pointerId, e.clientX - r.left, e.clientY - r.top, r.height));
  };
  const onPointerUp = (e: PointerEvent<HTMLDivElement>) => gestures.up(e.pointerId);
  useEffect(() => {
    if (status === 'ready' && linkage) sceneRef.current?.setLinkage(linkage);
  }, [status, linkage, sceneRef]);
  useEffect(() => {
    if (status === 'ready') sceneRef.current?.setPose(pose);
  }, [status, pose, linkage, sceneRef]);
  useEffect(() => {
    if (status === 'ready') sceneRef.current?.setProjection(projection);
  }, [status, projection, sceneRef]);

  // Keys (keyHold.ts): a press steps the view; a held key, from its first repeat, moves it at a steady speed on the
  // view's own frames where it has them (its worker), else by a step per repeat as the keys come.
  const [keys] = useState(() => new KeyHold());
  const holdTimer = useRef<ReturnType<typeof setTimeout> | undefined>(undefined);
  const letGo = () => {
    clearTimeout(holdTimer.current);
    if (keys.clear()) sceneRef.current?.hold?.(null);
  };
  useEffect(() => () => clearTimeout(holdTimer.current), []);
  const onKeyDown = (e: KeyboardEvent<HTMLDivElement>) => {
    const scene = sceneRef.current;
    if (!scene) return;
    const k = keys.down(e.code || e.key, e.key, e.shiftKey, e.repeat && scene.hold !== undefined);
    if (!k.handled) return;
    e.preventDefault();
    if (k.step) applyMove(scene, k.step);
    if (k.changed) scene.hold?.(keys.rates());
    if (keys.size > 0) {
      clearTimeout(holdTimer.current);
      holdTimer.current = setTimeout(letGo, HOLD_TIMEOUT_MS);
    }
  };
  const onKeyUp = (e: KeyboardEvent<HTMLDivElement>) => {
    if (!keys.up(e.code || e.key)) return;
    sceneRef.current?.hold?.(keys.rates());
    if (keys.size === 0) clearTimeout(holdTimer.current);
  };

  return (
    <div className="spatial-view" data-state={status}>
      {status === 'no-webgl' ? (
        <div className="spatial-no-webgl" role="status" data-testid="spatial-no-webgl">
          <p className="spatial-no-webgl-title">{sm.noWebgl}</p>
          <p>{sm.noWebglDetail}</p>
        </div>
      ) : (
        <div
          ref={hostRef}
          className="spatial-canvas-host"
          tabIndex={0}
          role="application"
          aria-label={sm.viewLabel}
          aria-describedby="spatial-view-hint"
          onKeyDown={onKeyDown}
          onKeyUp={onKeyUp}
          onBlur={letGo}
          onPointerDown={onPointerDown}
          onPointerMove={onPointerMove}
          onPointerUp={onPointerUp}
          onPointerCancel={onPointerUp}
          onContextMenu={(e) => e.preventDefault()}
        >
          <canvas
            key={workerFailed ? 'main' : 'first'}
            ref={canvasRef}
            className="spatial-canvas"
            data-testid="spatial-canvas"
          />
          {status === 'loading' ? <p className="spatial-view-loading">{sm.viewLoading}</p> : null}
          {status === 'ready' && pose === null && linkage ? (
            <p className="spatial-view-warning" role="status">
              {warning}
            </p>
          ) : null}
          <div className="spatial-view-tools">
            <button type="button" className="btn btn-small" onClick={() => sceneRef.current?.zoomBy(ZOOM_STEP)}>
              <span aria-hidden="true">+</span>
              <span className="sr-only">{sm.zoomIn}</span>
            </button>
            <button type="button" className="btn btn-small" onClick={() => sceneRef.current?.zoomBy(1 / ZOOM_STEP)}>
              <span aria-hidden="true">−</span>
              <span className="sr-only">{sm.zoomOut}</span>
            </button>
            <button type="button" className="btn btn-small" onClick={() => sceneRef.current?.resetView()}>
              {sm.resetView}
            </button>
          </div>
        </div>
      )}
      <div className="spatial-view-foot">
        {status !== 'no-webgl' ? (
          <p id="spatial-view-hint" className="note spatial-view-hint">
            {sm.viewHint}
          </p>
        ) : null}
        {status !== 'no-webgl' ? (
          <Segmented
            legend={sm.projectionLegend}
            value={projection}
            options={[
              { value: 'perspective', label: sm.perspective },
              { value: 'orthographic', label: sm.orthographic },
            ]}
            onChange={setProjection}
          />
        ) : null}
      </div>
    </div>
  );
}
