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
