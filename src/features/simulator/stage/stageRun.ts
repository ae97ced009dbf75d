import type { PlayFrame } from '../../../shared/state/playhead';

/**
 * Play's canvas shows from the worker's third frame of a run: a worker's first frames come slowly (its script
 * compiling, its first scene, fonts; at 6x CPU a quarter second between the first two), and the page draws Play
 * meanwhile. A drag's shows from its first (each of its frames is one input, and a drag can be a single move).
 */
export const PLAY_SHOWS_AFTER = 3;

/** What the live stage is doing: playing, showing a drag's frames, or nothing. */
export type StageMode = 'play' | 'show' | null;

/**
 * The page's record of the live stage's current run (a play, or a drag's shows): its id (a reply of another run is
 * stale), its frames, the newest of them.
 */
export interface StageRun {
  mode(): StageMode;
  /** The current run's id (the worker's replies carry it). */
  id(): number;
  /** Starts a new run in mode; returns its id. */
  begin(mode: 'play' | 'show'): number;
  /** Ends the run (the stage stops drawing); a reply of it that comes later is stale. */
  end(): void;
  /** Leaves the run without a new one (the worker is gone): latest() keeps its newest frame. */
  abandon(): void;
  /** Takes a drawn frame of run id: false for a stale one; true for the current run's. */
  receive(id: number, frame: PlayFrame): boolean;
  /** Whether the run has drawn enough frames to show (PLAY_SHOWS_AFTER for play, one for show). */
  ready(): boolean;
  /** The newest frame of the current run, or null before its first. */
  newest(): PlayFrame | null;
}

/** The live stage's run bookkeeping (no worker, no DOM: the client posts what it decides). */
export function createStageRun(): StageRun {
  let mode: StageMode = null;
  let id = 0;
  let frames = 0;
  let newest: PlayFrame | null = null;
  const restart = () => {
    id += 1;
    frames = 0;
    newest = null;
  };
  return {
    mode: () => mode,
    id: () => id,
    begin(next) {
      mode = next;
      restart();
      return id;
    },
    end() {
      mode = null;
      restart();
    },
    abandon() {
      mode = null;
    },
    receive(replyId, frame) {
      if (replyId !== id) return false;
      newest = frame;
      frames += 1;
      return true;
    },
    ready: () => frames >= (mode === 'play' ? PLAY_SHOWS_AFTER : 1),
    newest: () => newest,
  };
}
