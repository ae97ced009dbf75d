import type { InputRangeDeg } from '../../../shared/state/animation';
import { advanceTheta2, degreesForElapsed } from '../../../shared/state/animation';
import type { AppState } from '../../../shared/state/appState';
import type { PlayFrame } from '../../../shared/state/playhead';
import { playFrameOf } from '../../../shared/state/playhead';
import type { CycleResponse } from '../../../shared/solution';
import type { StageInputs } from '../scene/stageScene';
import type { StageReply, StageRequest } from './stageProtocol';

/** Longest frame step, seconds, as useAnimationFrame caps it on the page: a backgrounded tab does not jump on return. */
export const MAX_DT_SECONDS = 0.1;

/** What draws the live stage's frames: the canvas, its size, the language's tables (stagePainter.ts in the worker). */
export interface StagePainter {
  setCanvas(canvas: OffscreenCanvas): void;
  setSize(width: number, height: number, dpr: number): void;
  /** Starts loading the state's language where it has not loaded yet; settles once it has (at once for English). */
  prepare(state: AppState): Promise<void>;
  /** Draws frame of the inputs; how long it took (ms), or null when there is nothing to draw on yet or its language is loading. */
  draw(frame: PlayFrame, inputs: StageInputs): number | null;
}

/** The worker's clock and its animation frames, and the way back to the page. */
export interface StageHost {
  /** The worker's clock (ms, performance.now) and its origin (epoch ms), so the page's clock and this one agree. */
  now(): number;
  timeOrigin: number;
  /** The worker's requestAnimationFrame, or null where workers have none. */
  requestFrame: ((callback: (now: number) => void) => number) | null;
  cancelFrame(handle: number): void;
  reply(message: StageReply): void;
}

/** What Play is doing: the frame drawn last, when, and how it moves. */
interface Playing {
  id: number;
  frame: PlayFrame;
  atEpochMs: number;
  speedDegPerFrame: number;
  range: InputRangeDeg;
  /** The first step from the page's frame is not capped: the worker catches up with the page's clock. */
  first: boolean;
}

/**
 * The live stage's message loop (the worker's whole behaviour, without its globals): the page's requests
 * (stageProtocol.ts) set the canvas, size, state and cycle, start Play from a frame and time, show one frame (a θ2
 * drag) or stop. Play advances θ2 itself every animation frame (advanceTheta2 from the frame and time it started at)
 * and tells the page each frame it drew: the frame it drew, never the one before, so Pause keeps what is on screen.
 * Returns the handler of one request.
 */
export function createStageLoop(host: StageHost, painter: StagePainter): (request: StageRequest) => void {
  let inputs: StageInputs | null = null;
  let cycle: CycleResponse | null = null;
  let playing: Playing | null = null;
  let handle = 0;
  let hasCanvas = false;
  /** Whether 'ready' went to the page (once per worker). */
  let readySent = false;
  const epochNow = (now: number) => host.timeOrigin + now;

  const stopFrames = () => {
    if (handle) host.cancelFrame(handle);
    handle = 0;
  };

  const draw = (frame: PlayFrame): number | null => (inputs ? painter.draw(frame, inputs) : null);

  function tick(now: number) {
    handle = 0;
    const p = playing;
    if (!p || !host.requestFrame) return;
    const at = epochNow(now);
    const elapsed = Math.max(0, (at - p.atEpochMs) / 1000);
    const dt = p.first ? elapsed : Math.min(MAX_DT_SECONDS, elapsed);
    const next = advanceTheta2(
      p.frame.theta2Deg,
      degreesForElapsed(p.speedDegPerFrame, dt),
      p.frame.direction,
      p.frame.branch,
      p.range,
    );
    const drawMs = draw(next);
    if (drawMs !== null) {
      playing = { ...p, frame: next, atEpochMs: at, first: false };
      host.reply({ type: 'drawn', id: p.id, frame: next, atEpochMs: at, shownEpochMs: at, drawMs });
    }
    handle = host.requestFrame(tick);
  }

  function show(id: number, frame: PlayFrame) {
    // A θ2 drag: drawn at once (its input came with a page frame), nothing moves it on.
    playing = null;
    stopFrames();
    const drawMs = draw(frame);
    if (drawMs === null || !host.requestFrame) return;
    // Told once the frame it went out with has begun (as the page's own measure of a rendered frame).
    const at = epochNow(host.now());
    host.requestFrame(() =>
      host.reply({ type: 'drawn', id, frame, atEpochMs: at, shownEpochMs: epochNow(host.now()), drawMs }),
    );
  }

  /**
   * Once it has a canvas and a state whose language has loaded, the stage draws the state's pose once, unseen (its
   * canvas is hidden until a run's frames come: this compiles the scene's code and lays out its text), and tells the
   * page it is ready: a Play or drag from then on draws from its first frame without the worker's start-up.
   */
  const warmUp = () => {
    if (readySent || !hasCanvas || !inputs || !host.requestFrame) return;
    if (!playing) draw(playFrameOf(inputs.state));
    readySent = true;
    host.reply({ type: 'ready' });
  };

  return (m) => {
    switch (m.type) {
      case 'canvas':
        painter.setCanvas(m.canvas);
        hasCanvas = true;
        if (!host.requestFrame) host.reply({ type: 'unsupported' });
        warmUp();
        break;
      case 'size':
        painter.setSize(m.width, m.height, m.dpr);
        break;
      case 'state':
        inputs = { state: m.state, cycle, ghostShown: m.ghostShown };
        void painter.prepare(m.state).then(warmUp);
        break;
      case 'cycle':
        cycle = m.cycle;
        if (inputs) inputs = { ...inputs, cycle };
        break;
      case 'play':
        playing = { ...m, first: true };
        if (!handle && host.requestFrame) handle = host.requestFrame(tick);
        break;
      case 'show':
        show(m.id, m.frame);
        break;
      case 'stop':
        playing = null;
        stopFrames();
        break;
    }
  };
}
