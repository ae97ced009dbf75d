import type { AppState } from '../shared/state/appState';
import { DEFAULT_STATE } from '../shared/state/appState';
import { detectLocale, parseLocale } from '../shared/i18n/i18n';
import type { ParsedUrl } from '../shared/url/url';
import { parseUrl } from '../shared/url/url';

/**
 * The state to start from: defaults, the language from the stored choice or the browser's preferences,
 * then every valid URL parameter on top; bad ones are ignored, listed in `ignored` (for the UrlNotice) and
 * warned about on the console.
 */
export function initialState(search: string, languages: readonly string[], storedLocale: string | null): ParsedUrl {
  const stored = storedLocale ? parseLocale(storedLocale) : null;
  const base: AppState = {
    ...DEFAULT_STATE,
    shell: { ...DEFAULT_STATE.shell, locale: stored ?? detectLocale(languages) },
  };
  return parseUrl(search, base);
}
