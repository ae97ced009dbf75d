import { useEffect, useLayoutEffect, useState } from 'react';
import type { RefObject } from 'react';

/** How far outside the view (CSS pixels) an element still counts as on screen: it is brought up to date before it shows. */
export const ON_SCREEN_MARGIN_PX = 160;

/** A watched element: where it reports, the scrolling box that clips it (null: only the viewport), its margin. */
interface Watched {
  report: (onScreen: boolean) => void;
  clip: Element | null;
  margin: number;
}

/**
 * The elements watched now. They are checked when the page or any box scrolls, when the window resizes, and after
 * each render of a watcher (a commit can move them), in one animation frame: an IntersectionObserver would check
 * them in every frame of Play instead.
 */
const watched = new Map<Element, Watched>();
let frame = 0;

/** The nearest ancestor that scrolls its content (and so clips it), or null. */
function scrollingBox(el: Element): Element | null {
  for (let p = el.parentElement; p && p !== document.documentElement; p = p.parentElement) {
    const { overflowY } = getComputedStyle(p);
    if (overflowY === 'auto' || overflowY === 'scroll' || overflowY === 'hidden') return p;
  }
  return null;
}

/** Whether el's box is within m CSS pixels of the viewport and of its scrolling box. */
function isOnScreen(el: Element, clip: Element | null, m = ON_SCREEN_MARGIN_PX): boolean {
  const r = el.getBoundingClientRect();
  let top = -m;
  let bottom = window.innerHeight + m;
  let left = -m;
  let right = window.innerWidth + m;
  if (clip) {
    const c = clip.getBoundingClientRect();
    top = Math.max(top, c.top - m);
    bottom = Math.min(bottom, c.bottom + m);
    left = Math.max(left, c.left - m);
    right = Math.min(right, c.right + m);
  }
  return r.bottom >= top && r.top <= bottom && r.right >= left && r.left <= right && r.width + r.height > 0;
}

function checkAll(): void {
  frame = 0;
  for (const [el, w] of watched) w.report(isOnScreen(el, w.clip, w.margin));
}

function scheduleCheck(): void {
  if (!frame) frame = requestAnimationFrame(checkAll);
}

/**
 * Reports whether el is on screen (within margin CSS pixels of the viewport and of the box that scrolls it) in the
 * next animation frame, then whenever a check finds it (see `watched`); returns the stop.
 */
export function watchOnScreen(
  el: Element,
  report: (onScreen: boolean) => void,
  margin = ON_SCREEN_MARGIN_PX,
): () => void {
  if (watched.size === 0) {
    document.addEventListener('scroll', scheduleCheck, { capture: true, passive: true });
    window.addEventListener('resize', scheduleCheck);
  }
  watched.set(el, { report, clip: scrollingBox(el), margin });
  scheduleCheck();
  return () => {
    watched.delete(el);
    if (watched.size > 0) return;
    document.removeEventListener('scroll', scheduleCheck, { capture: true });
    window.removeEventListener('resize', scheduleCheck);
    cancelAnimationFrame(frame);
    frame = 0;
  };
}

/**
 * Whether ref's element is on screen (within ON_SCREEN_MARGIN_PX of the viewport and of the box that scrolls it),
 * followed while watching is true; while not watching, and where there is no window, it counts as on screen.
 */
export function useOnScreen(ref: RefObject<Element | null>, watching: boolean): boolean {
  const [onScreen, setOnScreen] = useState(true);
  useEffect(() => {
    const el = ref.current;
    if (!watching || !el || typeof window === 'undefined') return;
    const stop = watchOnScreen(el, setOnScreen);
    return () => {
      stop();
      setOnScreen(true);
    };
  }, [ref, watching]);
  // Each render here (a state's commit) may have moved what is watched (this element or another's): check again in the
  // next frame.
  useLayoutEffect(() => {
    if (watched.size > 0) scheduleCheck();
  });
  return watching ? onScreen : true;
}
