import { useCallback, useSyncExternalStore } from 'react';

/** Where Play is while it runs: the input (rad for a pin, length for a slider), its direction, the last limit met. */
export interface Playhead {
  input: number;
  direction: 1 | -1;
  /** The input at which Play last reversed at a limit, or null. */
  limitAt: number | null;
}

/**
 * Where Play's playhead is read: its latest value (null while Play is off) and a subscription to its moves. The
 * workspace holds this source, which stays the same object, so a frame of Play re-renders only the views that read
 * it (the canvas, the plots' markers, the readouts), not the page.
 */
export interface PlayheadSource {
  get(): Playhead | null;
  set(next: Playhead | null): void;
  subscribe(listener: () => void): () => void;
}

/** A playhead source, off (null) at first. */
export function createPlayheadSource(): PlayheadSource {
  let at: Playhead | null = null;
  const listeners = new Set<() => void>();
  return {
    get: () => at,
    set(next) {
      if (next === at) return;
      at = next;
      for (const listener of listeners) listener();
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
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
