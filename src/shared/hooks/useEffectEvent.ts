import { useCallback, useInsertionEffect, useRef } from 'react';

/**
 * A stable function that always calls the latest render's `fn`: React 19.2's `useEffectEvent` for React 18, which
 * the app uses because its react-dom is 20 KB gzip lighter (the first-load budget, issue 11). Call the result from
 * effects and event listeners, never during render: the latest `fn` is stored before layout effects run.
 */
export function useEffectEvent<A extends unknown[], R>(fn: (...args: A) => R): (...args: A) => R {
  const latest = useRef(fn);
  useInsertionEffect(() => {
    latest.current = fn;
  });
  return useCallback((...args: A) => latest.current(...args), []);
}
