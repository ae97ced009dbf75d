import { useEffect, useRef, useState } from 'react';

/**
 * value, following it at most once per intervalMs: a change after a quiet interval passes at once, changes
 * that come faster are held and the latest passes when the interval is up (nothing is lost, the last value
 * always arrives). Drags of a length use it for the worker's pose request: the numbers and the NR plot
 * follow a few times a second while the plots, which need the cycle, get the worker to themselves.
 */
export function useThrottledValue<T>(value: T, intervalMs: number): T {
  const [shown, setShown] = useState(value);
  // When shown last changed (ms, performance.now()); written in effects only.
  const lastMs = useRef(-Infinity);
  useEffect(() => {
    if (Object.is(value, shown)) return;
    const wait = lastMs.current + intervalMs - performance.now();
    const pass = () => {
      lastMs.current = performance.now();
      setShown(value);
    };
    if (wait <= 0) {
      pass();
      return;
    }
    const id = setTimeout(pass, wait);
    return () => clearTimeout(id);
  }, [value, shown, intervalMs]);
  return shown;
}
