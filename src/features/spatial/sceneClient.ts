import type { SceneLinkage, ScenePose } from './sceneData';
import type { Projection, SpatialScene } from './spatialScene';
import type { PlayAt, PlayRun, ViewMove, ViewReply, ViewRequest } from './viewProtocol';

/** What the page hears from the worker's view: each drawn frame (counts, Play's place) and the look. */
export interface WorkerSceneEvents {
  onFrame(frames: number, layerFrames: number, play: PlayAt | null): void;
  onQuality(name: 'full' | 'lean', antialias: boolean): void;
}

/** The 3D view's worker entry, started from its own file (a chunk of this page only). */
function startSceneWorker(): Worker {
  return new Worker(new URL('../../workers/spatialScene.worker.ts', import.meta.url), { type: 'module' });
}

/**
 * The 3D view drawn by a worker (src/workers/spatialScene.worker.ts) on the canvas handed to it: a SpatialScene whose
 * calls are posted, with play() (Play runs on the worker's clock). Resolves once the worker's view is made; rejects when
 * the worker cannot start or make WebGL (the canvas is then spent: the caller draws on a fresh one on its own thread).
 */
export function createWorkerScene(
  canvas: HTMLCanvasElement,
  rendererName: string | null,
  events: WorkerSceneEvents,
): Promise<SpatialScene> {
  // A worker that cannot start (a file:// page, a module from another origin) or a canvas that cannot be handed over
  // throws here: a rejection, so the caller draws on its own thread.
  try {
    return workerScene(startSceneWorker(), canvas, rendererName, events);
  } catch (e) {
    return Promise.reject(e instanceof Error ? e : new Error(String(e)));
  }
}

function workerScene(
  worker: Worker,
  canvas: HTMLCanvasElement,
  rendererName: string | null,
  events: WorkerSceneEvents,
): Promise<SpatialScene> {
  let frames = 0;
  let nextPng = 1;
  const pngs = new Map<number, { resolve: (b: Uint8Array) => void; reject: (e: Error) => void }>();
  const post = (m: ViewRequest, transfer: Transferable[] = []) => worker.postMessage(m, transfer);
  const move = (m: ViewMove) => post({ type: 'move', move: m });
  const api: SpatialScene = {
    setLinkage: (linkage: SceneLinkage) => post({ type: 'linkage', linkage }),
    setPose: (pose: ScenePose | null) => post({ type: 'pose', pose }),
    setProjection: (projection: Projection) => post({ type: 'projection', projection }),
    resetView: () => move({ op: 'reset' }),
    orbitBy: (dAzimuth, dElevation) => move({ op: 'orbit', dAzimuth, dElevation }),
    zoomBy: (factor) => move({ op: 'zoom', factor }),
    panBy: (dx, dy) => move({ op: 'pan', dx, dy }),
    resize: (widthPx, heightPx, ratio) =>
      post({ type: 'resize', widthPx, heightPx, devicePixelRatio: ratio ?? window.devicePixelRatio ?? 1 }),
    pngBytes: (scale) =>
      new Promise<Uint8Array>((resolve, reject) => {
        const id = nextPng++;
        pngs.set(id, { resolve, reject });
        post({ type: 'png', id, scale });
      }),
    frames: () => frames,
    play: (run: PlayRun | null) => post({ type: 'play', run }),
    hold: (rates) => post({ type: 'hold', rates }),
    dispose() {
      worker.terminate();
      for (const p of pngs.values()) p.reject(new Error('the 3D view closed'));
      pngs.clear();
    },
  };
  return new Promise<SpatialScene>((resolve, reject) => {
    const fail = (message: string) => {
      worker.terminate();
      reject(new Error(message));
    };
    worker.onerror = (e) => fail(e.message || 'the 3D view worker failed');
    worker.onmessage = (e: MessageEvent<ViewReply>) => {
      const m = e.data;
      if (m.type === 'ready') resolve(api);
      else if (m.type === 'failed') fail(m.message);
      else if (m.type === 'frame') {
        frames = m.frames;
        events.onFrame(m.frames, m.layerFrames, m.play);
      } else if (m.type === 'quality') events.onQuality(m.name, m.antialias);
      else {
        const p = pngs.get(m.id);
        pngs.delete(m.id);
        if (m.ok) p?.resolve(m.bytes);
        else p?.reject(new Error(m.message));
      }
    };
    try {
      const offscreen = canvas.transferControlToOffscreen();
      post({ type: 'init', canvas: offscreen, rendererName, devicePixelRatio: window.devicePixelRatio || 1 }, [
        offscreen,
      ]);
    } catch (e) {
      fail(e instanceof Error ? e.message : String(e));
    }
  });
}
