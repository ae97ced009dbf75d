import { RECENT_DESIGNS_STORAGE_KEY, readStorage, writeStorage } from '../../shared/storage';

/** A design opened or saved lately: its name, when (ISO 8601), and the file's text (read again when reopened). */
export interface RecentDesign {
  name: string;
  at: string;
  file: string;
}

/** Most recent designs kept. */
export const RECENT_MAX = 5;

/** The list with entry first: an older entry of the same name is dropped, and at most RECENT_MAX are kept. */
export function withRecent(list: readonly RecentDesign[], entry: RecentDesign): RecentDesign[] {
  return [entry, ...list.filter((d) => d.name !== entry.name)].slice(0, RECENT_MAX);
}

function isRecent(x: unknown): x is RecentDesign {
  if (typeof x !== 'object' || x === null) return false;
  const d = x as Record<string, unknown>;
  return typeof d.name === 'string' && typeof d.at === 'string' && typeof d.file === 'string';
}

/** The stored list's text read leniently: anything but a list of well-formed entries gives or drops to []. */
export function parseRecent(text: string | null): RecentDesign[] {
  if (!text) return [];
  try {
    const list: unknown = JSON.parse(text);
    return Array.isArray(list) ? list.filter(isRecent).slice(0, RECENT_MAX) : [];
  } catch {
    return [];
  }
}

/** The recent designs in storage, newest first ([] when storage is unavailable). */
export function readRecent(): RecentDesign[] {
  return parseRecent(readStorage(RECENT_DESIGNS_STORAGE_KEY));
}

/** Puts a design first in the stored list and returns the new list (kept in memory when storage refuses). */
export function rememberRecent(entry: RecentDesign): RecentDesign[] {
  const list = withRecent(readRecent(), entry);
  writeStorage(RECENT_DESIGNS_STORAGE_KEY, JSON.stringify(list));
  return list;
}
