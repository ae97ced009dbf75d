import { useEffect } from 'react';

/** Keeps the document's language (a BCP 47 tag) and title in step with the UI language. */
export function useDocumentMeta(lang: string, title: string): void {
  useEffect(() => {
    document.documentElement.lang = lang;
    document.title = title;
  }, [lang, title]);
}
