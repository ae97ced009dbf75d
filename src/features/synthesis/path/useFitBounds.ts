import { useState } from 'react';
import type { Bounds } from '../../../shared/canvas/view';

function contains(outer: Bounds, inner: Bounds): boolean {
  return inner.minX >= outer.minX && inner.maxX <= outer.maxX && inner.minY >= outer.minY && inner.maxY <= outer.maxY;
}

/** A quarter more room on every side, so a few more clicks near the edge do not refit. */
function widen(b: Bounds): Bounds {
  const dx = Math.max(b.maxX - b.minX, b.maxY - b.minY, 1e-9) * 0.25;
  return { minX: b.minX - dx, minY: b.minY - dx, maxX: b.maxX + dx, maxY: b.maxY + dx };
}

/**
 * The bounds a canvas fits: held while the content stays inside them (so adding or dragging a target does not
 * rescale the view under the pointer), grown when it leaves them, and fitted afresh to the content when resetKey
 * changes (new targets pasted, new results, another design chosen).
 */
export function useFitBounds(content: Bounds, resetKey: string): Bounds {
  const [held, setHeld] = useState<{ bounds: Bounds; key: string } | null>(null);
  if (held !== null && held.key === resetKey && contains(held.bounds, content)) return held.bounds;
  const same = held !== null && held.key === resetKey;
  const bounds = same
    ? widen({
        minX: Math.min(held.bounds.minX, content.minX),
        minY: Math.min(held.bounds.minY, content.minY),
        maxX: Math.max(held.bounds.maxX, content.maxX),
        maxY: Math.max(held.bounds.maxY, content.maxY),
      })
    : content;
  // Derived state kept from the previous render (React's "adjusting state while rendering").
  setHeld({ bounds, key: resetKey });
  return bounds;
}
