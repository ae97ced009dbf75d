import { useCallback, useRef } from 'react';
import type { ShownFrame } from './shownFrame';

/** The frame the linkage view drew last, for the exports: a getter, and the report to give LinkageStage. */
export function useShownFrame(): { shown: () => ShownFrame | null; onShown: (frame: ShownFrame) => void } {
  // Written by the stage's layout effect, read by export handlers: never during render.
  const last = useRef<ShownFrame | null>(null);
  const onShown = useCallback((frame: ShownFrame) => {
    last.current = frame;
  }, []);
  const shown = useCallback(() => last.current, []);
  return { shown, onShown };
}
