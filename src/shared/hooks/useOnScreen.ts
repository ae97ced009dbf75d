import { useEffect, useState } from 'react';
import type { RefObject } from 'react';

/** How far outside the view (CSS pixels) an element still counts as on screen: it is brought up to date before it shows. */
export const ON_SCREEN_MARGIN_PX = 160;

/**
 * Whether ref's element is on screen (within ON_SCREEN_MARGIN_PX of the viewport, clipped by the scrolling boxes it
 * sits in), tracked with an IntersectionObserver while watching is true. While not watching, and where there is no
 * IntersectionObserver, the element counts as on screen.
 */
export function useOnScreen(ref: RefObject<Element | null>, watching: boolean): boolean {
  const [onScreen, setOnScreen] = useState(true);
  useEffect(() => {
    const el = ref.current;
    if (!watching || !el || typeof IntersectionObserver === 'undefined') return;
    const margin = `${ON_SCREEN_MARGIN_PX}px`;
    // scrollMargin grows the scrolling boxes' clips too (a sidebar scrolled by the student); older browsers ignore it.
    const init: IntersectionObserverInit & { scrollMargin?: string } = { rootMargin: margin, scrollMargin: margin };
    const io = new IntersectionObserver((entries) => {
      const last = entries[entries.length - 1];
      if (last) setOnScreen(last.isIntersecting);
    }, init);
    io.observe(el);
    return () => {
      io.disconnect();
      setOnScreen(true);
    };
  }, [ref, watching]);
  return watching ? onScreen : true;
}
