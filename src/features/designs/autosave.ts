import type { AppState } from '../../shared/state/appState';
import { SHELL_URL_KEYS } from '../../shared/state/slices/shellSlice';
import type { DesignFileRead } from './designFile';
import { designValues, readDesignFile } from './designFile';

/** Wait after the last change before the work is autosaved, ms. */
export const AUTOSAVE_DEBOUNCE_MS = 1000;

/** A session the app can restore: the autosave's state, name and time. */
export interface RestoreOffer {
  state: AppState;
  name: string;
  savedAt: string | null;
}

const SHELL_KEYS = new Set(SHELL_URL_KEYS.map((k) => k.name));

/** Whether a query string is a share link: it has a parameter other than the language and the page. */
export function isShareLink(search: string): boolean {
  const params = new URLSearchParams(search.startsWith('?') ? search.slice(1) : search);
  for (const key of params.keys()) if (!SHELL_KEYS.has(key)) return true;
  return false;
}

/** Whether two states hold the same work (what a design file holds; language, page, Play aside). */
export function sameWork(a: AppState, b: AppState): boolean {
  return JSON.stringify(designValues(a)) === JSON.stringify(designValues(b));
}

/**
 * The restore offer at start: the autosave (a design file's text) when there is one, it reads, the page was
 * not opened from a share link (search), and its work differs from the state the app starts with; else null.
 */
export function restoreOffer(autosave: string | null, start: AppState, search: string): RestoreOffer | null {
  if (!autosave || isShareLink(search)) return null;
  const r: DesignFileRead = readDesignFile(autosave, start);
  if (!r.ok || sameWork(r.state, start)) return null;
  return { state: r.state, name: r.name, savedAt: r.savedAt };
}
