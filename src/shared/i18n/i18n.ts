import type { Locale } from '../state/appState';
import type { Messages } from './messages';
import { messagesEn } from './messagesEn';
import { messageModule } from './messageModule';

/** Supported UI languages, English first (the default). */
export const LOCALES: readonly Locale[] = ['en', 'zh-TW'];

/** The app's own strings: English in the first load, zh-TW a chunk of its own loaded on demand. */
export const appMessages = messageModule<Messages>(messagesEn, {
  'zh-TW': () => import('./messagesZhTw').then((m) => m.messagesZhTw),
});

/** The app's strings in locale once loaded (loadLanguage), English until then (never undefined). */
export function getMessages(locale: Locale): Messages {
  return appMessages.get(locale);
}

/** Maps a BCP 47 tag to a supported locale: any Chinese tag but simplified ones gives zh-TW; null when unsupported. */
export function matchLocale(tag: string): Locale | null {
  const t = tag.trim().toLowerCase();
  if (t === '') return null;
  if (t.startsWith('en')) return 'en';
  if (t.startsWith('zh')) {
    if (/^zh-(hans|cn|sg)\b/.test(t)) return null;
    return 'zh-TW';
  }
  return null;
}

/** Picks the UI language from the browser's preference list (navigator.languages); English when none matches. */
export function detectLocale(preferred: readonly string[]): Locale {
  for (const tag of preferred) {
    const m = matchLocale(tag);
    if (m) return m;
  }
  return 'en';
}

/** Parses a locale parameter exactly ('en' or 'zh-TW', case-insensitive); null otherwise. */
export function parseLocale(value: string): Locale | null {
  const v = value.trim().toLowerCase();
  if (v === 'en') return 'en';
  if (v === 'zh-tw') return 'zh-TW';
  return null;
}
