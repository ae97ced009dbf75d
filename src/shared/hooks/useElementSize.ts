import { useLayoutEffect, useState } from 'react';
import type { RefObject } from 'react';

/** Size of an element's content box in CSS pixels (whole pixels), tracked with a ResizeObserver. */
export interface ElementSize {
  width: number;
  height: number;
}

/**
 * The content-box size of an element in CSS pixels, as a ResizeObserver's contentRect gives it: measured the same
 * way at mount and on resize, so the observer's first callback changes nothing and costs no render.
 */
export function contentBox(el: HTMLElement): ElementSize {
  const cs = getComputedStyle(el);
  const px = (v: string) => Number.parseFloat(v) || 0;
  return {
    width: Math.max(0, el.clientWidth - px(cs.paddingLeft) - px(cs.paddingRight)),
    height: Math.max(0, el.clientHeight - px(cs.paddingTop) - px(cs.paddingBottom)),
  };
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
    const box = contentBox(el);
    update(box.width, box.height);
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
