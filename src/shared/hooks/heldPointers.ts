/** The pointers (mouse buttons, fingers, pens) held down anywhere on the page, followed from window. */
export interface HeldPointers {
  /** Whether any pointer is down. */
  held(): boolean;
  /** Stops following. */
  dispose(): void;
}

/**
 * Follows the page's pointers from window in the capture phase (a handler that stops propagation does not hide them):
 * press runs when the first pointer goes down, release when the last one comes up or is cancelled.
 */
export function followPointers(on: { press?: () => void; release?: () => void } = {}): HeldPointers {
  const down = new Set<number>();
  const press = (e: PointerEvent) => {
    if (down.size === 0) on.press?.();
    down.add(e.pointerId);
  };
  const release = (e: PointerEvent) => {
    if (!down.delete(e.pointerId) || down.size > 0) return;
    on.release?.();
  };
  const options = { capture: true, passive: true };
  window.addEventListener('pointerdown', press, options);
  window.addEventListener('pointerup', release, options);
  window.addEventListener('pointercancel', release, options);
  return {
    held: () => down.size > 0,
    dispose() {
      window.removeEventListener('pointerdown', press, options);
      window.removeEventListener('pointerup', release, options);
      window.removeEventListener('pointercancel', release, options);
    },
  };
}
