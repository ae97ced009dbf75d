import type { InputRangeDeg } from '../../../shared/state/animation';
import { advanceTheta2, degreesForElapsed } from '../../../shared/state/animation';
import type { AppState } from '../../../shared/state/appState';
import type { PlayFrame } from '../../../shared/state/playhead';
import { playFrameOf } from '../../../shared/state/playhead';
import type { CycleResponse } from '../../../shared/solution';
import type { StageInputs } from '../scene/stageScene';
import type { StageReply, StageRequest } from './stageProtocol';
import type { StageFrameHost } from '../../../shared/linkage/liveStage';
import { createStageClock } from '../../../shared/linkage/stageClock';

export { MAX_DT_SECONDS } from '../../../shared/linkage/stageClock';

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
export type StageHost = StageFrameHost<StageReply>;

/** What Play is doing: the frame drawn last and how it moves (its time is the clock's). */
interface Playing {
  id: number;
  frame: PlayFrame;
  speedDegPerFrame: number;
  range: InputRangeDeg;
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
  let hasCanvas = false;

  const draw = (frame: PlayFrame): number | null => (inputs ? painter.draw(frame, inputs) : null);

  const clock = createStageClock(host, (dt, at) => {
    const p = playing;
    if (!p) return false;
    const next = advanceTheta2(
      p.frame.theta2Deg,
      degreesForElapsed(p.speedDegPerFrame, dt),
      p.frame.direction,
      p.frame.branch,
      p.range,
    );
    const drawMs = draw(next);
    if (drawMs === null) return false;
    playing = { ...p, frame: next };
    host.reply({ type: 'drawn', id: p.id, frame: next, atEpochMs: at, shownEpochMs: at, drawMs });
    return true;
  });

  function show(id: number, frame: PlayFrame) {
    // A θ2 drag: drawn at once (its input came with a page frame), nothing moves it on.
    playing = null;
    clock.stop();
    const drawMs = draw(frame);
    if (drawMs === null) return;
    // Told once the frame it went out with has begun (as the page's own measure of a rendered frame).
    const at = clock.epochNow();
    clock.atNextFrame(() =>
      host.reply({ type: 'drawn', id, frame, atEpochMs: at, shownEpochMs: clock.epochNow(), drawMs }),
    );
  }

  /**
   * Once it has a canvas and a state whose language has loaded, the stage draws the state's pose once, unseen (its
   * canvas is hidden until a run's frames come: this compiles the scene's code and lays out its text), and tells the
   * page it is ready: a Play or drag from then on draws from its first frame without the worker's start-up.
   */
  const warmUp = () => {
    if (clock.readySaid() || !hasCanvas || !inputs || !host.requestFrame) return;
    if (!playing) draw(playFrameOf(inputs.state));
    clock.sayReady();
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
        playing = { id: m.id, frame: m.frame, speedDegPerFrame: m.speedDegPerFrame, range: m.range };
        clock.play(m.atEpochMs);
        break;
      case 'show':
        show(m.id, m.frame);
        break;
      case 'stop':
        playing = null;
        clock.stop();
        break;
    }
  };
}
