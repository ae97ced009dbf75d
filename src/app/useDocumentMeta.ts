import { useEffect } from 'react';

/** Keeps the document's language (a BCP 47 tag) and title in step with the UI language; not when enabled is false. */
export function useDocumentMeta(lang: string, title: string, enabled = true): void {
  useEffect(() => {
    if (!enabled) return;
    document.documentElement.lang = lang;
    document.title = title;
  }, [lang, title, enabled]);
}
