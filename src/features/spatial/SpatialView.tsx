import { useEffect, useRef, useState } from 'react';
import type { KeyboardEvent, RefObject } from 'react';
import { Segmented } from '../../shared/ui/Segmented';
import { degToRad } from '../../solver';
import type { SceneLinkage, ScenePose } from './sceneData';
import type { SpatialMessages } from './spatialMessages';
import type { Projection, SpatialScene } from './spatialScene';

/** Props of SpatialView: the fixed parts, the pose, the strings, and a ref the page's PNG export reads the scene from. */
export interface SpatialViewProps {
  linkage: SceneLinkage | null;
  pose: ScenePose | null;
  sm: SpatialMessages;
  sceneRef: RefObject<SpatialScene | null>;
  /** Shown over the view when the loop cannot close at θ2. */
  warning: string;
  /** Told each time the view's status changes (the page turns its PNG export on only when ready). */
  onStatus?: (status: ViewStatus) => void;
}

/** Where the view is: its code loading, drawing, or without WebGL (the fallback message). */
export type ViewStatus = 'loading' | 'ready' | 'no-webgl';

/** Key step of the view: 5° of orbit, 10 % of the height of pan, 1.2× zoom. */
const ORBIT_STEP = degToRad(5);
const PAN_STEP = 0.1;
const ZOOM_STEP = 1.2;

/**
 * The 3D view: three.js (its chunk loads here, on this page only) on a canvas sized to its box; orbit, zoom and pan by
 * mouse, touch and keys; reset and projection tools. Without WebGL a message says so and the rest of the page works.
 */
export function SpatialView({ linkage, pose, sm, sceneRef, warning, onStatus }: SpatialViewProps) {
  const hostRef = useRef<HTMLDivElement>(null);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const [status, setStatus] = useState<ViewStatus>('loading');
  const [projection, setProjection] = useState<Projection>('perspective');

  useEffect(() => {
    let live = true;
    let made: SpatialScene | null = null;
    let observer: ResizeObserver | null = null;
    import('./spatialScene')
      .then(({ createSpatialScene }) => {
        if (!live || !canvasRef.current || !hostRef.current) return;
        try {
          made = createSpatialScene(canvasRef.current);
        } catch {
          setStatus('no-webgl');
          return;
        }
        sceneRef.current = made;
        const host = hostRef.current;
        const fit = () => made?.resize(host.clientWidth, host.clientHeight);
        observer = new ResizeObserver(fit);
        observer.observe(host);
        fit();
        setStatus('ready');
      })
      .catch(() => live && setStatus('no-webgl'));
    return () => {
      live = false;
      observer?.disconnect();
      made?.dispose();
      sceneRef.current = null;
    };
  }, [sceneRef]);

  useEffect(() => {
    onStatus?.(status);
  }, [status, onStatus]);
  useEffect(() => {
    if (status === 'ready' && linkage) sceneRef.current?.setLinkage(linkage);
  }, [status, linkage, sceneRef]);
  useEffect(() => {
    if (status === 'ready') sceneRef.current?.setPose(pose);
  }, [status, pose, linkage, sceneRef]);
  useEffect(() => {
    if (status === 'ready') sceneRef.current?.setProjection(projection);
  }, [status, projection, sceneRef]);

  const onKeyDown = (e: KeyboardEvent<HTMLDivElement>) => {
    const scene = sceneRef.current;
    if (!scene) return;
    const pan = e.shiftKey;
    const keys: Record<string, () => void> = {
      ArrowLeft: () => (pan ? scene.panBy(-PAN_STEP, 0) : scene.orbitBy(-ORBIT_STEP, 0)),
      ArrowRight: () => (pan ? scene.panBy(PAN_STEP, 0) : scene.orbitBy(ORBIT_STEP, 0)),
      ArrowUp: () => (pan ? scene.panBy(0, PAN_STEP) : scene.orbitBy(0, ORBIT_STEP)),
      ArrowDown: () => (pan ? scene.panBy(0, -PAN_STEP) : scene.orbitBy(0, -ORBIT_STEP)),
      '+': () => scene.zoomBy(ZOOM_STEP),
      '=': () => scene.zoomBy(ZOOM_STEP),
      '-': () => scene.zoomBy(1 / ZOOM_STEP),
      '0': () => scene.resetView(),
    };
    const act = keys[e.key];
    if (!act) return;
    e.preventDefault();
    act();
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
        >
          <canvas ref={canvasRef} className="spatial-canvas" data-testid="spatial-canvas" />
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
