import { useCallback, useSyncExternalStore } from 'react';

/** A query's MediaQueryList and whether it matches, kept current by the list's own 'change' events. */
interface KeptQuery {
  list: MediaQueryList;
  matches: boolean;
}

/**
 * One MediaQueryList per query, kept with its answer: window.matchMedia parses and evaluates its query again at
 * each call, and reading a list's `matches` evaluates it again too (React reads a store's value at every render
 * of a reader and again after each commit: Play commits a few times a second).
 */
const kept = new Map<string, KeptQuery>();

/** The page's kept query; null where there is no window (server rendering, tests in Node). */
function keptQuery(query: string): KeptQuery | null {
  if (typeof window === 'undefined' || !window.matchMedia) return null;
  let entry = kept.get(query);
  if (!entry) {
    const list = window.matchMedia(query);
    const made: KeptQuery = { list, matches: list.matches };
    list.addEventListener('change', (e) => {
      made.matches = e.matches;
    });
    kept.set(query, made);
    entry = made;
  }
  return entry;
}

/**
 * Whether a CSS media query matches now, following its changes (window.matchMedia); false where there is no
 * window (server rendering, tests in Node).
 */
export function useMediaQuery(query: string): boolean {
  const subscribe = useCallback(
    (onChange: () => void) => {
      const list = keptQuery(query)?.list;
      if (!list) return () => undefined;
      list.addEventListener('change', onChange);
      return () => list.removeEventListener('change', onChange);
    },
    [query],
  );
  // The kept answer: the list's first 'change' listener (keptQuery's) updates it before any reader hears.
  const matches = () => keptQuery(query)?.matches ?? false;
  return useSyncExternalStore(subscribe, matches, () => false);
}
