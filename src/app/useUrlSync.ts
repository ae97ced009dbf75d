import { useEffect } from 'react';
import type { AppState } from '../shared/state/appState';
import type { EmbedOptions } from '../shared/url/url';
import { serializeState } from '../shared/url/url';

/** Wait after the last change before the address bar is rewritten (ms). */
const URL_DEBOUNCE_MS = 250;

/**
 * Keeps the address bar's query in step with the state (and the embed options, in the embed), debounced and
 * not while animating, which would flood the history API. Sandboxed frames that refuse it are left alone.
 * Not when enabled is false (a widget inside someone else's page leaves its address bar alone).
 */
export function useUrlSync(state: AppState, embed?: EmbedOptions, enabled = true): void {
  useEffect(() => {
    if (state.motion.playing || !enabled) return;
    const id = setTimeout(() => {
      try {
        const q = serializeState(state, embed);
        window.history.replaceState(window.history.state, '', `${window.location.pathname}?${q}`);
      } catch {
        // Some sandboxed frames refuse history changes; the state still lives in the app.
      }
    }, URL_DEBOUNCE_MS);
    return () => clearTimeout(id);
  }, [state, embed, enabled]);
}
