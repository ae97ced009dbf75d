import { useLayoutEffect, useRef } from 'react';
import type { RefObject } from 'react';

/**
 * A ref that holds the latest committed `value`, for event handlers with a stable identity that must read the
 * current state (an export button, a copy-link button). The ref is written in a layout effect, after the render
 * commits, never during render; read it only from event handlers and effects.
 */
export function useLatest<T>(value: T): RefObject<T> {
  const latest = useRef(value);
  useLayoutEffect(() => {
    latest.current = value;
  });
  return latest;
}
