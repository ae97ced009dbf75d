import { useEffect, useState } from 'react';
import { flushSync } from 'react-dom';

/**
 * Calls before() when the page starts printing (beforeprint: Ctrl+P, window.print(); or print media coming on, as
 * when emulated) and after() when it ends (afterprint while print media is off, or print media going off);
 * returns the function that stops listening.
 */
export function onPrinting(before: () => void, after: () => void): () => void {
  const print = window.matchMedia?.('print');
  const onMedia = () => (print?.matches ? before() : after());
  // After a print made while print media is on (a PDF made under emulated print media), the page still prints.
  const afterPrint = () => {
    if (!print?.matches) after();
  };
  window.addEventListener('beforeprint', before);
  window.addEventListener('afterprint', afterPrint);
  print?.addEventListener('change', onMedia);
  return () => {
    window.removeEventListener('beforeprint', before);
    window.removeEventListener('afterprint', afterPrint);
    print?.removeEventListener('change', onMedia);
  };
}

/**
 * True while the page prints: from beforeprint (Ctrl+P, window.print()) to afterprint, and while print media is
 * emulated (the print media query), even across a print made meanwhile. Set synchronously on beforeprint, so the
 * browser prints what it rendered.
 */
export function usePrinting(): boolean {
  const [printing, setPrinting] = useState(() => window.matchMedia?.('print').matches ?? false);
  useEffect(
    () =>
      onPrinting(
        () => flushSync(() => setPrinting(true)),
        () => setPrinting(false),
      ),
    [],
  );
  return printing;
}
