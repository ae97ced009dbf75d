import { useLayoutEffect, useState } from 'react';
import type { RefObject } from 'react';

/** Size of an element's content box in CSS pixels (whole pixels), tracked with a ResizeObserver. */
export interface ElementSize {
  width: number;
  height: number;
}

/** Tracks the content-box size of ref's element in CSS pixels; { 0, 0 } until it is laid out. */
export function useElementSize(ref: RefObject<HTMLElement | null>): ElementSize {
  const [size, setSize] = useState<ElementSize>({ width: 0, height: 0 });
  useLayoutEffect(() => {
    const el = ref.current;
    if (!el) return;
    const update = (w: number, h: number) => {
      const width = Math.floor(w);
      const height = Math.floor(h);
      setSize((s) => (s.width === width && s.height === height ? s : { width, height }));
    };
    const r = el.getBoundingClientRect();
    update(el.clientWidth || r.width, el.clientHeight || r.height);
    if (typeof ResizeObserver === 'undefined') return;
    const ro = new ResizeObserver((entries) => {
      const e = entries[entries.length - 1];
      update(e.contentRect.width, e.contentRect.height);
    });
    ro.observe(el);
    return () => ro.disconnect();
  }, [ref]);
  return size;
}
