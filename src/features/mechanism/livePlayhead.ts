import { useCallback, useSyncExternalStore } from 'react';
import { ExternalValue } from '../../shared/state/externalValue';

/** Where Play is while it runs: the input (rad for a pin, length for a slider), its direction, the last limit met. */
export interface Playhead {
  input: number;
  direction: 1 | -1;
  /** The input at which Play last reversed at a limit, or null. */
  limitAt: number | null;
}

/**
 * A value that changes often (every frame of Play, every move of a drag) and where it is read: its latest value and a
 * subscription to its changes. The page holds the source, which stays the same object, so a change re-renders only the
 * views that read it (useSyncExternalStore), not the page.
 */
export interface LiveSource<T> {
  get(): T;
  set(next: T): void;
  subscribe(listener: () => void): () => void;
}

/** Play's playhead: null while Play is off; the canvas, the plots' markers and the readouts read it. */
export type PlayheadSource = LiveSource<Playhead | null>;

/** A playhead source, off (null) at first. */
export function createPlayheadSource(): PlayheadSource {
  return createLiveSource<Playhead | null>(null);
}

/** A live source holding first at first; setting the same value again tells no one (the app's ExternalValue). */
export function createLiveSource<T>(first: T): LiveSource<T> {
  return new ExternalValue(first);
}

/**
 * subscribe, with the listener called at most once per everyMs (ms) and once more after the last change of a burst, so
 * a reader that shows text (a readout, a slider's thumb) follows Play a few times a second instead of every frame.
 * Throws for an everyMs that is not a positive finite number.
 */
export function throttledSubscribe(
  subscribe: (listener: () => void) => () => void,
  everyMs: number,
): (listener: () => void) => () => void {
  if (!(everyMs > 0 && Number.isFinite(everyMs)))
    throw new Error(`everyMs must be a positive finite number, got ${everyMs}`);
  return (listener) => {
    let last = -Infinity;
    let timer: ReturnType<typeof setTimeout> | null = null;
    const fire = () => {
      timer = null;
      last = Date.now();
      listener();
    };
    const unsubscribe = subscribe(() => {
      if (timer !== null) return;
      const wait = last + everyMs - Date.now();
      if (wait <= 0) fire();
      else timer = setTimeout(fire, wait);
    });
    return () => {
      if (timer !== null) clearTimeout(timer);
      unsubscribe();
    };
  };
}

/**
 * The input shown: Play's playhead while it runs, else rest (the committed input). everyMs, when given, makes the
 * reader follow Play at most once per everyMs ms (throttledSubscribe); default every move.
 */
export function usePlayheadInput(source: PlayheadSource, rest: number, everyMs?: number): number {
  const subscribe = useCallback(
    (listener: () => void) =>
      everyMs === undefined ? source.subscribe(listener) : throttledSubscribe(source.subscribe, everyMs)(listener),
    [source, everyMs],
  );
  // While a throttled reader waits, it keeps what it read last: get() is read again only when it is told.
  const input = useSyncExternalStore(subscribe, () => source.get()?.input ?? null);
  return input ?? rest;
}
