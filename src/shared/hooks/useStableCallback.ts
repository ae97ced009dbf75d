import { useCallback, useInsertionEffect, useRef } from 'react';

/**
 * A function with a stable identity that always calls the latest fn, for handlers passed to memoised panels
 * (export, share, step): the panels do not re-render when the state behind the handler changes. The latest fn
 * is stored in an insertion effect, never during render; the result is for events, not for calling in render.
 */
export function useStableCallback<A extends unknown[], R>(fn: (...args: A) => R): (...args: A) => R {
  const latest = useRef(fn);
  useInsertionEffect(() => {
    latest.current = fn;
  });
  return useCallback((...args: A) => latest.current(...args), []);
}
