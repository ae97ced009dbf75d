/** Reads a localStorage item; null when storage is unavailable (sandboxed iframes, privacy modes) or the key is absent. */
export function readStorage(key: string): string | null {
  try {
    return globalThis.localStorage?.getItem(key) ?? null;
  } catch {
    return null;
  }
}

/** Writes a localStorage item; returns false instead of throwing when storage is unavailable or full. */
export function writeStorage(key: string, value: string): boolean {
  try {
    globalThis.localStorage?.setItem(key, value);
    return true;
  } catch {
    return false;
  }
}

/** Storage key of the chosen UI language. */
export const LOCALE_STORAGE_KEY = 'fourbar-lab.locale';

/** Storage key set once the phone layout's first-use hint (joints can be dragged) was dismissed: '1'. */
export const DRAG_HINT_STORAGE_KEY = 'fourbar-lab.drag-hint-dismissed';

/** Storage key of the autosaved work: the design file text of the last state (features/designs). */
export const AUTOSAVE_STORAGE_KEY = 'fourbar-lab.autosave';

/** Storage key of the recently opened or saved designs: a JSON list, newest first (features/designs). */
export const RECENT_DESIGNS_STORAGE_KEY = 'fourbar-lab.recent-designs';
