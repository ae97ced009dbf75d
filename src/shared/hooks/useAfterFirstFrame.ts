import { startTransition, useEffect, useState } from 'react';

/**
 * False for the first commit, then true once the browser has had a task to paint it (a transition, so input is
 * never held up by it): for parts of a page that can follow the first frame. With `after` false it waits: it turns
 * true a task after the first commit where `after` is true (a part that should also wait for the first answers).
 * Once true it stays true.
 */
export function useAfterFirstFrame(after = true): boolean {
  const [shown, setShown] = useState(false);
  useEffect(() => {
    if (!after || shown) return;
    const id = setTimeout(() => startTransition(() => setShown(true)), 0);
    return () => clearTimeout(id);
  }, [after, shown]);
  return shown;
}
