import type { AppState } from './appState';
import { DEFAULT_STATE } from './appState';
import { detectLocale, parseLocale } from './i18n';
import type { ParsedUrl } from './url';
import { parseUrl } from './url';

/**
 * The state to start from: defaults, the language from the stored choice or the browser's preferences,
 * then every valid URL parameter on top; bad ones are ignored, listed in `ignored` (for the UrlNotice) and
 * warned about on the console.
 */
export function initialState(search: string, languages: readonly string[], storedLocale: string | null): ParsedUrl {
  const stored = storedLocale ? parseLocale(storedLocale) : null;
  const base: AppState = { ...DEFAULT_STATE, locale: stored ?? detectLocale(languages) };
  return parseUrl(search, base);
}
