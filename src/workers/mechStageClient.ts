import type { MechLiveStage } from '../features/mechanism/stage/mechLiveStage';
import type { MechStageReply, MechStageRequest, MechStageView } from '../features/mechanism/stage/mechStageProtocol';
import type { MechScene } from '../features/mechanism/mechScene';
import type { Playhead } from '../features/mechanism/livePlayhead';
import { benchMark } from '../shared/benchMarks';
import { canTransfer, createShownFlag } from './stageClient';

/** Starts the Mechanisms stage's module worker (matched by scripts/viteInlineWorker.ts: keep it as is). */
function startMechStageWorker(): Worker {
  return new Worker(new URL('./mechStage.worker.ts', import.meta.url), { type: 'module' });
}

type Drawn = Extract<MechStageReply, { type: 'drawn' }>;

/** Marks a drawn frame 'fourbar:mech-stage-frame' (page times drawn and shown, the input, the worker's draw ms) for bench:ui. */
function markFrame(m: Drawn, mode: 'play' | 'show'): void {
  benchMark('fourbar:mech-stage-frame', {
    mode,
    input: m.playhead.input,
    pose: m.pose,
    t: m.atEpochMs - performance.timeOrigin,
    shown: m.shownEpochMs - performance.timeOrigin,
    drawMs: m.drawMs,
  });
}

/**
 * The page's side of the Mechanisms page's live stage (features/mechanism/stage/mechLiveStage.ts). Its worker starts
 * when the stage's canvas is attached and is handed that canvas at once, with the view and scene as they come (a
 * worker that starts warm draws a Play's or a drag's first frame without its start-up). The canvas carries, for tests
 * and tools: data-stage ("attached" once handed over, "ready" once the worker has drawn once), data-frames (the frames
 * it drew in all), data-mode ("play", "show" or ""), and of the newest frame data-input, data-pose (poseDigest) and
 * data-selected-at. Null where a worker cannot draw on a canvas; a worker that fails or cannot animate turns the stage
 * off for good (usable() false: the page draws as before).
 */
export function createMechStage(): MechLiveStage | null {
  if (!canTransfer()) return null;
  let worker: Worker | null = null;
  let broken = false;
  let element: HTMLCanvasElement | null = null;
  /** The current run (a play, or a drag's shows): its id, mode, frames drawn and newest playhead. */
  let run: { id: number; mode: 'play' | 'show' | null; newest: Playhead | null } = { id: 0, mode: null, newest: null };
  let framesDrawn = 0;
  let view: Extract<MechStageRequest, { type: 'view' }> | null = null;
  let scene: MechScene | null = null;
  const shown = createShownFlag();
  const post = (message: MechStageRequest, transfer: Transferable[] = []) => {
    if (worker && !broken) worker.postMessage(message, transfer);
  };
  const begin = (mode: 'play' | 'show') => {
    run = { id: run.id + 1, mode, newest: null };
    return run.id;
  };
  const breakDown = () => {
    if (broken) return;
    broken = true;
    run = { ...run, mode: null };
    worker?.terminate();
    worker = null;
    if (element) element.dataset.stage = 'off';
    shown.set(false);
  };
  const onReply = (e: MessageEvent<MechStageReply>) => {
    const m = e.data;
    if (m.type === 'unsupported') return breakDown();
    if (m.type === 'ready') {
      if (element) element.dataset.stage = 'ready';
      return;
    }
    if (m.id !== run.id || run.mode === null) return;
    run.newest = m.playhead;
    framesDrawn += 1;
    if (element) {
      element.dataset.frames = String(framesDrawn);
      element.dataset.input = String(m.playhead.input);
      element.dataset.pose = m.pose;
      element.dataset.selectedAt = m.selectedAt;
    }
    markFrame(m, run.mode);
    shown.set(true);
  };
  /** Starts the worker and hands it the canvas, the view and the scene; false where it cannot. */
  const start = (): boolean => {
    if (worker) return true;
    if (broken || !element || element.dataset.stage) return false;
    try {
      worker = startMechStageWorker();
      worker.addEventListener('message', onReply);
      worker.addEventListener('error', breakDown);
      const offscreen = element.transferControlToOffscreen();
      element.dataset.stage = 'attached';
      post({ type: 'canvas', canvas: offscreen }, [offscreen]);
      if (view) post(view);
      if (scene) post({ type: 'scene', scene });
      return true;
    } catch {
      breakDown();
      return false;
    }
  };
  const setMode = (mode: string) => {
    if (element) element.dataset.mode = mode;
  };
  return {
    attach(canvas) {
      if (element === canvas) return;
      element = canvas;
      start();
    },
    setView(next) {
      const dpr = Math.max(1, Math.min(4, window.devicePixelRatio || 1));
      const v: MechStageView = { ...next, dpr };
      const old = view?.view;
      const same =
        old &&
        old.width === v.width &&
        old.height === v.height &&
        old.dpr === v.dpr &&
        old.bounds === v.bounds &&
        old.offset === v.offset;
      if (same) return;
      view = { type: 'view', view: v };
      post(view);
    },
    setScene(next) {
      if (next === scene) return;
      scene = next;
      post({ type: 'scene', scene });
    },
    play(from, atMs, drive) {
      if (!start()) return;
      setMode('play');
      post({ type: 'play', id: begin('play'), from, atEpochMs: performance.timeOrigin + atMs, drive });
    },
    show(input, dragged) {
      if (!start()) return;
      const id = run.mode === 'show' ? run.id : begin('show');
      setMode('show');
      post({ type: 'show', id, input, dragged });
    },
    stop() {
      if (run.mode === null) return;
      // A frame of the run that comes later is stale.
      run = { id: run.id + 1, mode: null, newest: null };
      setMode('');
      post({ type: 'stop' });
      shown.set(false);
    },
    usable: () => !broken,
    latest: () => run.newest,
    showing: () => shown.get(),
    subscribe: (listener) => shown.subscribe(listener),
    dispose() {
      breakDown();
    },
  };
}
