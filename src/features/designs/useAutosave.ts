import { useEffect, useState } from 'react';
import type { AppState } from '../../shared/state/appState';
import { AUTOSAVE_STORAGE_KEY, writeStorage } from '../../shared/storage';
import { AUTOSAVE_DEBOUNCE_MS } from './autosave';
import { writeDesignFile } from './designFile';

/**
 * Keeps the work in localStorage as a design file (AUTOSAVE_STORAGE_KEY), AUTOSAVE_DEBOUNCE_MS after the last
 * change, never while Play runs, and only once the state differs from the one the page started with: opening
 * the app does not overwrite the session a restore offer is about.
 */
export function useAutosave(state: AppState, name: string): void {
  const [start] = useState(state);
  useEffect(() => {
    if (state === start || state.motion.playing) return;
    const id = setTimeout(
      () => writeStorage(AUTOSAVE_STORAGE_KEY, writeDesignFile(state, name, new Date())),
      AUTOSAVE_DEBOUNCE_MS,
    );
    return () => clearTimeout(id);
  }, [state, name, start]);
}
