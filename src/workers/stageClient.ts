import type { LiveStage } from '../shared/linkage/liveStage';
import type { InputRangeDeg } from '../shared/state/animation';
import type { PlayFrame } from '../shared/state/playhead';
import { BENCH_MARKS, benchMark } from '../shared/benchMarks';
import { createPageDraws } from '../features/simulator/stage/pageDraws';
import { createStageInputs } from '../features/simulator/stage/stageInputs';
import type { StageReply, StageRequest } from '../features/simulator/stage/stageProtocol';
import { createStageRun } from '../features/simulator/stage/stageRun';

/** Whether this browser can hand a canvas to a worker (OffscreenCanvas with transferControlToOffscreen). */
export function canTransfer(): boolean {
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

/** A flag whose listeners hear each change (the stage's showing()). */
export function createShownFlag() {
  let shown = false;
  const listeners = new Set<() => void>();
  return {
    get: () => shown,
    set(next: boolean) {
      if (shown === next) return;
      shown = next;
      for (const listener of [...listeners]) listener();
    },
    subscribe(listener: () => void) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
}

/** Marks a drawn frame 'fourbar:stage-frame' (page time, θ2, the worker's cost) for bench:ui. */
function markStageFrame(m: Extract<StageReply, { type: 'drawn' }>): void {
  // Off in normal use: not even the mark's detail is made (a frame of Play's cost on the page's thread).
  if (!BENCH_MARKS) return;
  benchMark('fourbar:stage-frame', {
    theta2Deg: m.frame.theta2Deg,
    t: m.atEpochMs - performance.timeOrigin,
    shown: m.shownEpochMs - performance.timeOrigin,
    drawMs: m.drawMs,
  });
}

/**
 * The page's side of the live stage (shared/linkage/liveStage.ts). Its worker starts at the first play(), show() or
 * warm(), or as soon as the page's first draws show it draws slowly (warmIfSlow), and is then handed the attached
 * canvas: a quick page that never plays or drags never loads it. The canvas's data-stage is "attached" once handed
 * over and "ready" once the worker has started and drawn once (tests wait on it). The canvas element shows the
 * frames the worker draws; the page keeps the newest one for its playhead (stageRun.ts), and the canvas's
 * data-theta2 names the θ2 it shows; its data-page is "quick" or "slow" once the page's first draws judged it (a
 * slow page stays slow: prefersStage). Marks each drawn frame for bench:ui. Null where a worker cannot draw; a worker
 * that fails or says it cannot animate turns the stage off for good (the page draws as before).
 */
export function createLiveStage(): LiveStage | null {
  if (!canTransfer()) return null;
  let worker: Worker | null = null;
  let broken = false;
  /** Whether the worker said it is ready (canvas data-stage="ready"). */
  let ready = false;
  /** The page's canvas for the stage, handed to the worker when it starts (or at once, once it has). */
  let element: HTMLCanvasElement | null = null;
  const run = createStageRun();
  const inputs = createStageInputs();
  const pageDraws = createPageDraws();
  const shown = createShownFlag();
  const post = (message: StageRequest | null, transfer: Transferable[] = []) => {
    if (message && worker && !broken) worker.postMessage(message, transfer);
  };
  const breakDown = () => {
    broken = true;
    run.abandon();
    worker?.terminate();
    worker = null;
    shown.set(false);
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
    if (!run.receive(m.id, m.frame)) return;
    // The pose on screen, for tests and tools (the page's canvas's label names the committed pose meanwhile).
    if (element) element.dataset.theta2 = String(m.frame.theta2Deg);
    markStageFrame(m);
    if (run.ready()) shown.set(true);
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
      for (const message of inputs.replay()) post(message);
      return true;
    } catch {
      breakDown();
      return false;
    }
  };
  /** Whether the page draws the linkage too slowly for a drag (pageDraws: a slow page stays slow). */
  function prefersStage(): boolean {
    return !broken && element !== null && pageDraws.slow();
  }
  /**
   * On a page that draws slowly the worker starts as soon as that is known (its first draws), not at the first Play
   * or drag: its start-up (script, first scene, fonts; seconds at 6x CPU) is then over before the student's first
   * drag, whose route is decided from its first move.
   */
  const warmIfSlow = () => {
    if (!worker && prefersStage()) start();
  };
  /** For tests and tools: the canvas's data-page says how the page was judged (a drag's route), once it is. */
  const markJudged = () => {
    if (!element || !pageDraws.judged()) return;
    const judged = pageDraws.slow() ? 'slow' : 'quick';
    if (element.dataset.page !== judged) element.dataset.page = judged;
  };
  return {
    attach(canvas) {
      if (element === canvas) return;
      element = canvas;
      markJudged();
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
      post(inputs.size(width, height, dpr));
    },
    setScene(state, cycle, ghostShown) {
      for (const message of inputs.scene(state, cycle, ghostShown)) post(message);
    },
    play(frame: PlayFrame, atMs: number, speedDegPerFrame: number, range: InputRangeDeg) {
      if (!start()) return;
      const id = run.begin('play');
      post({ type: 'play', id, frame, atEpochMs: performance.timeOrigin + atMs, speedDegPerFrame, range });
    },
    warm() {
      start();
    },
    show(frame: PlayFrame) {
      if (!start()) return;
      const id = run.mode() === 'show' ? run.id() : run.begin('show');
      post({ type: 'show', id, frame });
    },
    stop() {
      if (run.mode() === null) return;
      run.end();
      post({ type: 'stop' });
      shown.set(false);
    },
    notePageDraw(ms) {
      pageDraws.note(ms);
      markJudged();
      warmIfSlow();
    },
    prefersStage,
    latest: () => run.newest(),
    showing: () => shown.get(),
    subscribe: (listener) => shown.subscribe(listener),
  };
}
