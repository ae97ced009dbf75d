import { startTransition, useEffect, useState } from 'react';

/**
 * False for the first commit, then true once the browser has had a task to paint it (a transition, so input is
 * never held up by it): for parts of a page that can follow the first frame.
 */
export function useAfterFirstFrame(): boolean {
  const [after, setAfter] = useState(false);
  useEffect(() => {
    const id = setTimeout(() => startTransition(() => setAfter(true)), 0);
    return () => clearTimeout(id);
  }, []);
  return after;
}
