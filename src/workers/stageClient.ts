import type { LiveStage } from '../shared/linkage/liveStage';
import type { InputRangeDeg } from '../shared/state/animation';
import type { AppState } from '../shared/state/appState';
import type { PlayFrame } from '../shared/state/playhead';
import type { CycleResponse } from '../shared/solution';
import { benchMark } from '../shared/benchMarks';
import type { StageReply, StageRequest } from '../features/simulator/stage/stageProtocol';

/**
 * A page whose recent draws of the linkage take this long (ms, their lower median) hands a θ2 drag to the stage: past
 * it, the page's frame (its React render, the drawing, its paint) no longer fits in the one frame the worker's route
 * adds.
 */
const SLOW_PAGE_DRAW_MS = 5;
/** How many of the page's latest draws the median is taken over (a slow one, say the first, does not decide alone). */
const DRAWS_KEPT = 5;

/**
 * Play's canvas shows from the worker's third frame of a run: a worker's first frames come slowly (its script
 * compiling, its first scene, fonts; at 6x CPU a quarter second between the first two), and the page draws Play
 * meanwhile. A drag's shows from its first (each of its frames is one input, and a drag can be a single move).
 */
const PLAY_SHOWS_AFTER = 3;

/** Whether this browser can hand a canvas to a worker (OffscreenCanvas with transferControlToOffscreen). */
function canTransfer(): boolean {
  return (
    typeof Worker !== 'undefined' &&
    typeof OffscreenCanvas !== 'undefined' &&
    typeof HTMLCanvasElement !== 'undefined' &&
    'transferControlToOffscreen' in HTMLCanvasElement.prototype
  );
}

/** Starts the live stage's module worker (matched by scripts/viteInlineWorker.ts: keep it as is). */
function startStageWorker(): Worker {
  return new Worker(new URL('./stage.worker.ts', import.meta.url), { type: 'module' });
}

/**
 * The page's side of the live stage (shared/linkage/liveStage.ts). Its worker starts at the first play(), show() or
 * warm(), or as soon as the page's first draws show it draws slowly (warmIfSlow), and is then handed the attached
 * canvas: a quick page that never plays or drags never loads it. The canvas's data-stage is "attached" once handed
 * over and "ready" once the worker has started and drawn once (tests wait on it). The canvas element
 * shows the frames the worker draws; the page keeps the newest one for its playhead, and the canvas's data-theta2
 * names the θ2 it shows. Marks each drawn frame 'fourbar:stage-frame' (page time, θ2, the worker's cost) for
 * bench:ui. Null where a worker cannot draw; a worker that fails or says it cannot animate turns the stage off for
 * good (the page draws as before).
 */
export function createLiveStage(): LiveStage | null {
  if (!canTransfer()) return null;
  let worker: Worker | null = null;
  let broken = false;
  /** Whether the worker said it is ready (canvas data-stage="ready"). */
  let ready = false;
  /** The page's canvas for the stage, handed to the worker when it starts (or at once, once it has). */
  let element: HTMLCanvasElement | null = null;
  /** What the stage is doing: playing, showing a drag's frames, or nothing. */
  let mode: 'play' | 'show' | null = null;
  let playId = 0;
  /** Frames drawn in the current run (play or show). */
  let runFrames = 0;
  let newest: PlayFrame | null = null;
  let shown = false;
  let lastState: { state: AppState; ghostShown: boolean } | null = null;
  let lastCycle: CycleResponse | null | undefined;
  let lastSize: { width: number; height: number; dpr: number } | null = null;
  const listeners = new Set<() => void>();
  const pageDraws: number[] = [];
  const setShown = (next: boolean) => {
    if (shown === next) return;
    shown = next;
    for (const listener of [...listeners]) listener();
  };
  const post = (message: StageRequest, transfer: Transferable[] = []) => {
    if (worker && !broken) worker.postMessage(message, transfer);
  };
  const breakDown = () => {
    broken = true;
    mode = null;
    worker?.terminate();
    worker = null;
    setShown(false);
  };
  const onReply = (e: MessageEvent<StageReply>) => {
    const m = e.data;
    if (m.type === 'unsupported') {
      breakDown();
      return;
    }
    if (m.type === 'ready') {
      // For tests and tools: the worker has started and drawn once, so a run's frames come without its start-up.
      ready = true;
      if (element) element.dataset.stage = 'ready';
      return;
    }
    if (m.id !== playId) return;
    newest = m.frame;
    runFrames += 1;
    // The pose on screen, for tests and tools (the page's canvas's label names the committed pose meanwhile).
    if (element) element.dataset.theta2 = String(m.frame.theta2Deg);
    benchMark('fourbar:stage-frame', {
      theta2Deg: m.frame.theta2Deg,
      t: m.atEpochMs - performance.timeOrigin,
      shown: m.shownEpochMs - performance.timeOrigin,
      drawMs: m.drawMs,
    });
    if (runFrames >= (mode === 'play' ? PLAY_SHOWS_AFTER : 1)) setShown(true);
  };
  /** Hands the worker the canvas element (once per element: a remounted canvas view is a new one). */
  const handOver = (canvas: HTMLCanvasElement) => {
    if (canvas.dataset.stage) return;
    const offscreen = canvas.transferControlToOffscreen();
    canvas.dataset.stage = ready ? 'ready' : 'attached';
    post({ type: 'canvas', canvas: offscreen }, [offscreen]);
  };
  /** Starts the worker and hands it the canvas and what it draws from; false where it cannot. */
  const start = (): boolean => {
    if (worker) return true;
    if (broken || !element) return false;
    try {
      worker = startStageWorker();
      worker.addEventListener('message', onReply);
      worker.addEventListener('error', breakDown);
      handOver(element);
      if (lastSize) post({ type: 'size', ...lastSize });
      if (lastState) post({ type: 'state', ...lastState });
      if (lastCycle !== undefined) post({ type: 'cycle', cycle: lastCycle });
      return true;
    } catch {
      breakDown();
      return false;
    }
  };
  /** Whether the page draws the linkage too slowly for a drag: the lower median of its latest draws. */
  function prefersStage(): boolean {
    if (broken || element === null || pageDraws.length < 2) return false;
    const sorted = [...pageDraws].sort((a, b) => a - b);
    return sorted[Math.floor((sorted.length - 1) / 2)] >= SLOW_PAGE_DRAW_MS;
  }
  /**
   * On a page that draws slowly the worker starts as soon as that is known (its first draws), not at the first Play
   * or drag: its start-up (script, first scene, fonts; seconds at 6x CPU) is then over before the student's first
   * drag, whose route is decided from its first move.
   */
  const warmIfSlow = () => {
    if (!worker && prefersStage()) start();
  };
  return {
    attach(canvas) {
      if (element === canvas) return;
      element = canvas;
      warmIfSlow();
      if (!worker || broken) return;
      try {
        handOver(canvas);
      } catch {
        breakDown();
      }
    },
    setSize(width, height) {
      const dpr = Math.max(1, Math.min(4, window.devicePixelRatio || 1));
      if (lastSize && lastSize.width === width && lastSize.height === height && lastSize.dpr === dpr) return;
      lastSize = { width, height, dpr };
      post({ type: 'size', ...lastSize });
    },
    setScene(state, cycle, ghostShown) {
      if (!lastState || lastState.state !== state || lastState.ghostShown !== ghostShown) {
        lastState = { state, ghostShown };
        post({ type: 'state', ...lastState });
      }
      if (lastCycle !== cycle) {
        lastCycle = cycle;
        post({ type: 'cycle', cycle });
      }
    },
    play(frame: PlayFrame, atMs: number, speedDegPerFrame: number, range: InputRangeDeg) {
      if (!start()) return;
      mode = 'play';
      playId += 1;
      newest = null;
      runFrames = 0;
      post({ type: 'play', id: playId, frame, atEpochMs: performance.timeOrigin + atMs, speedDegPerFrame, range });
    },
    warm() {
      start();
    },
    show(frame: PlayFrame) {
      if (!start()) return;
      if (mode !== 'show') {
        mode = 'show';
        playId += 1;
        newest = null;
        runFrames = 0;
      }
      post({ type: 'show', id: playId, frame });
    },
    stop() {
      if (mode === null) return;
      mode = null;
      playId += 1;
      newest = null;
      runFrames = 0;
      post({ type: 'stop' });
      setShown(false);
    },
    notePageDraw(ms) {
      if (!Number.isFinite(ms) || ms < 0) return;
      pageDraws.push(ms);
      if (pageDraws.length > DRAWS_KEPT) pageDraws.shift();
      warmIfSlow();
    },
    prefersStage,
    latest: () => newest,
    showing: () => shown,
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
}
