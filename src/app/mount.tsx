import { StrictMode } from 'react';
import type { ComponentType } from 'react';
import { createRoot } from 'react-dom/client';
import { ErrorBoundary } from './ErrorBoundary';
import { getMessages } from '../shared/i18n/i18n';
import { loadLanguage } from '../shared/i18n/messageModule';
import { initialState } from './initialState';
import { LOCALE_STORAGE_KEY, readStorage } from '../shared/storage';
import type { ParsedUrl } from '../shared/url/url';

/** Props every top-level layout takes: the state and embed options parsed from the URL. */
export interface LayoutProps {
  initial: ParsedUrl;
}

/**
 * Mounts a layout (the app or the embed widget) into #root with the state from the URL, inside an error boundary,
 * once the language's strings are loaded (English is in the first load; zh-TW is fetched first when chosen).
 */
export async function mount(Layout: ComponentType<LayoutProps>): Promise<void> {
  const root = document.getElementById('root');
  if (!root) throw new Error('index.html must have an element with id "root"');
  const languages = typeof navigator !== 'undefined' ? (navigator.languages ?? [navigator.language]) : [];
  const initial = initialState(window.location.search, languages, readStorage(LOCALE_STORAGE_KEY));
  try {
    await loadLanguage(initial.state.shell.locale);
  } catch {
    // The language chunk could not load (offline): the English strings are there.
  }
  const reset = () => {
    try {
      window.location.assign(window.location.pathname);
    } catch {
      window.location.reload();
    }
  };
  createRoot(root).render(
    <StrictMode>
      <ErrorBoundary messages={getMessages(initial.state.shell.locale)} onReset={reset}>
        <Layout initial={initial} />
      </ErrorBoundary>
    </StrictMode>,
  );
}
