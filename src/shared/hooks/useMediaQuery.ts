import { useCallback, useSyncExternalStore } from 'react';

/** One MediaQueryList per query, kept: window.matchMedia parses and evaluates its query again at each call. */
const lists = new Map<string, MediaQueryList>();

/** The page's MediaQueryList for a query; null where there is no window (server rendering, tests in Node). */
function mediaList(query: string): MediaQueryList | null {
  if (typeof window === 'undefined' || !window.matchMedia) return null;
  let list = lists.get(query);
  if (!list) {
    list = window.matchMedia(query);
    lists.set(query, list);
  }
  return list;
}

/**
 * Whether a CSS media query matches now, following its changes (window.matchMedia); false where there is no
 * window (server rendering, tests in Node).
 */
export function useMediaQuery(query: string): boolean {
  const subscribe = useCallback(
    (onChange: () => void) => {
      const list = mediaList(query);
      if (!list) return () => undefined;
      list.addEventListener('change', onChange);
      return () => list.removeEventListener('change', onChange);
    },
    [query],
  );
  // A kept list's `matches` follows the page as it changes (its 'change' events are what subscribe hears).
  const matches = () => mediaList(query)?.matches ?? false;
  return useSyncExternalStore(subscribe, matches, () => false);
}
