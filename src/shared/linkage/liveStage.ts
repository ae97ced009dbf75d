import type { InputRangeDeg } from '../state/animation';
import type { AppState } from '../state/appState';
import type { PlayFrame } from '../state/playhead';
import type { CycleResponse } from '../solution';

/**
 * The live stage: Play's linkage drawn in a worker, on a canvas laid over the page's (OffscreenCanvas), with the
 * worker's own frame clock. The page's main thread then does not draw the linkage per frame of Play, and a busy main
 * thread (panels, plots, a slow phone) does not hold the linkage's frames up. The page follows the stage's frames
 * (its playhead, the plot markers) as often as it can. Where a worker cannot draw (no OffscreenCanvas, no
 * requestAnimationFrame in workers) there is no stage and the page draws Play itself.
 */
export interface LiveStage {
  /** The stage's canvas, laid over the page's: handed to the worker at the first play() (a canvas goes once). */
  attach(canvas: HTMLCanvasElement): void;
  /** The canvas's size in CSS pixels (the page's canvas's). */
  setSize(width: number, height: number): void;
  /** What the stage draws from besides the frame: the committed state, the latest cycle, whether the ghost shows. */
  setScene(state: AppState, cycle: CycleResponse | null, ghostShown: boolean): void;
  /**
   * Plays from frame as it stands at atMs (a requestAnimationFrame timestamp of this page): the worker advances it
   * as useAnimation does (speed in degrees per nominal 60 FPS frame, rocking within range). A later call re-bases it
   * (an edit while playing).
   */
  play(frame: PlayFrame, atMs: number, speedDegPerFrame: number, range: InputRangeDeg): void;
  /**
   * Draws frame as it is (a θ2 drag: the page's input moves it) until the next show(), play() or stop(). A worker's
   * frame reaches the screen a frame after the input; the page's, in the input's own frame when the page is quick.
   * So a drag goes to the stage only where the page's own drawing is slow (prefersStage).
   */
  show(frame: PlayFrame): void;
  /** Starts the worker without drawing (a drag the page draws itself: the next may need the stage at once). */
  warm(): void;
  /** Notes how long the page took to draw the linkage once (ms): the stage learns how slow the page is. */
  notePageDraw(ms: number): void;
  /**
   * Whether the page draws the linkage too slowly to keep up with a drag: the lower median of its latest draws is, or
   * once was, slow (a slow page stays slow).
   */
  prefersStage(): boolean;
  /** Stops drawing; the stage's canvas hides (showing() turns false). */
  stop(): void;
  /** The newest frame the stage drew since the last play(), or null before its first. */
  latest(): PlayFrame | null;
  /**
   * Whether the stage's canvas shows: from its third frame after play() (the page draws the first) or its first after
   * show(), to stop().
   */
  showing(): boolean;
  /** Adds a listener to changes of showing(); returns its removal. */
  subscribe(listener: () => void): () => void;
}

/**
 * A stage worker's clock, its animation frames and the way back to its page (the worker's globals, passed to its loop
 * so the loop is tested on a hand-run clock): replies of type R.
 */
export interface StageFrameHost<R> {
  /** The worker's clock (ms, performance.now) and its origin (epoch ms), so the page's clock and this one agree. */
  now(): number;
  timeOrigin: number;
  /** The worker's requestAnimationFrame, or null where workers have none. */
  requestFrame: ((callback: (now: number) => void) => number) | null;
  cancelFrame(handle: number): void;
  reply(message: R): void;
}
