import type { Branch } from '../../solver/types';
import type { AppState, Direction } from './appState';

/** What Play moves every frame: the input angle (degrees, [0, 360)), its direction and the branch (a rocking input switches it). */
export interface PlayFrame {
  theta2Deg: number;
  direction: Direction;
  branch: Branch;
}

/** The frame fields of a state. */
export function playFrameOf(state: Pick<AppState, 'motion' | 'design'>): PlayFrame {
  return { theta2Deg: state.motion.theta2Deg, direction: state.motion.direction, branch: state.design.branch };
}

/** Whether two frames are the same pose and direction. */
export function sameFrame(a: PlayFrame, b: PlayFrame): boolean {
  return a.theta2Deg === b.theta2Deg && a.direction === b.direction && a.branch === b.branch;
}

/** The state with a frame's fields, or the state itself when the frame is null or already its own. */
export function withFrame(state: AppState, frame: PlayFrame | null): AppState {
  if (!frame || sameFrame(frame, playFrameOf(state))) return state;
  const { theta2Deg, direction, branch } = frame;
  return { ...state, motion: { ...state.motion, theta2Deg, direction }, design: { ...state.design, branch } };
}

/**
 * The frame Play advances from. Play draws from the playhead every frame and commits to the state only a few
 * times a second, so the state lags the playhead and is no source of truth while playing, except for what
 * someone else changed: a field whose state value moved since the previous frame (seenBefore) to a value
 * that is not one Play committed itself (committed, oldest first) was edited (the θ2 field, the branch or
 * direction control) and is taken from the state; every other field comes from the playhead.
 */
export function playBase(
  state: PlayFrame,
  seenBefore: PlayFrame | null,
  playhead: PlayFrame | null,
  committed: readonly PlayFrame[],
): PlayFrame {
  if (!playhead) return state;
  if (!seenBefore || sameFrame(state, seenBefore) || committed.some((c) => sameFrame(c, state))) return playhead;
  return {
    theta2Deg: state.theta2Deg !== seenBefore.theta2Deg ? state.theta2Deg : playhead.theta2Deg,
    direction: state.direction !== seenBefore.direction ? state.direction : playhead.direction,
    branch: state.branch !== seenBefore.branch ? state.branch : playhead.branch,
  };
}

/**
 * The frame on screen while Play runs, ahead of the state: a tiny external store (get, set, subscribe) for
 * useSyncExternalStore, so only the views that follow every frame (canvas, plot markers) re-render per frame.
 * null when nothing is playing ahead of the state.
 */
export class Playhead {
  private frame: PlayFrame | null = null;
  private readonly listeners = new Set<() => void>();

  /** The current frame, or null (the state's own fields hold). Stable between sets (for useSyncExternalStore). */
  readonly get = (): PlayFrame | null => this.frame;

  /** Moves the playhead (null hands the pose back to the state) and tells the subscribers when it changed. */
  set(frame: PlayFrame | null): void {
    const same = frame === null ? this.frame === null : this.frame !== null && sameFrame(frame, this.frame);
    if (same) return;
    this.frame = frame;
    for (const listener of [...this.listeners]) listener();
  }

  /** Adds a change listener; returns its removal. */
  readonly subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };
}
