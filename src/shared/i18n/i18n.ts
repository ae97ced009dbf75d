import type { Locale } from '../state/appState';
import type { Messages } from './messages';
import { messagesEn } from './messagesEn';

/** Supported UI languages, English first (the default). */
export const LOCALES: readonly Locale[] = ['en', 'zh-TW'];

/** Message tables loaded so far: English is in the first load, other languages load on demand. */
const loaded: Partial<Record<Locale, Messages>> = { en: messagesEn };

/** How each language's table loads: one entry per Locale (a new language without one is a type error). */
const LOADERS: Record<Locale, () => Promise<Messages>> = {
  en: async () => messagesEn,
  'zh-TW': () => import('./messagesZhTw').then((m) => m.messagesZhTw),
};

/** The strings of one language, if loadMessages has loaded them; English until then (never undefined). */
export function getMessages(locale: Locale): Messages {
  return loaded[locale] ?? messagesEn;
}

/** Loads a language's strings (zh-TW is a separate chunk, so English users never download it); resolves to them. */
export async function loadMessages(locale: Locale): Promise<Messages> {
  const have = loaded[locale];
  if (have) return have;
  const messages = await LOADERS[locale]();
  loaded[locale] = messages;
  return messages;
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
