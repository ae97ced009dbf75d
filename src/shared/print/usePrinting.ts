import { useEffect, useState } from 'react';
import { flushSync } from 'react-dom';

/**
 * True while the page prints: from beforeprint (Ctrl+P, window.print()) to afterprint, and while print media is
 * emulated (the print media query), even across a print made meanwhile. Set synchronously on beforeprint, so the
 * browser prints what it rendered.
 */
export function usePrinting(): boolean {
  const [printing, setPrinting] = useState(() => window.matchMedia?.('print').matches ?? false);
  useEffect(() => {
    const before = () => flushSync(() => setPrinting(true));
    const print = window.matchMedia?.('print');
    // After a print (a PDF made while print media is emulated too), the sheet stays while the media is print.
    const after = () => setPrinting(print?.matches ?? false);
    const onMedia = () => (print?.matches ? before() : after());
    window.addEventListener('beforeprint', before);
    window.addEventListener('afterprint', after);
    print?.addEventListener('change', onMedia);
    return () => {
      window.removeEventListener('beforeprint', before);
      window.removeEventListener('afterprint', after);
      print?.removeEventListener('change', onMedia);
    };
  }, []);
  return printing;
}
