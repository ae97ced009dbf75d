import type { Locale } from '../state/appState';

/** One language's table of a module: the table itself (bundled with the module) or a loader of its chunk. */
export type TableSource<M> = M | (() => Promise<M>);

/** A feature's strings in every supported language, behind the one loader (loadLanguage). */
export interface MessageModule<M> {
  /** The table of locale when loaded, else English (never undefined: a view never waits for its words). */
  get(locale: Locale): M;
  /** Loads locale's table (a no-op when it is bundled or already loaded); resolves to it. */
  load(locale: Locale): Promise<M>;
}

/** Every module made so far: loadLanguage loads a language for all of them. */
const modules: MessageModule<unknown>[] = [];

/**
 * A feature's message module: English bundled (the fallback), and one source per other language, so a language
 * the app supports but a module forgets is a type error. Registered with loadLanguage.
 */
export function messageModule<M>(en: M, others: Record<Exclude<Locale, 'en'>, TableSource<M>>): MessageModule<M> {
  const loaded: Partial<Record<Locale, M>> = { en };
  const sources: Record<Locale, TableSource<M>> = { en, ...others };
  for (const [locale, source] of Object.entries(sources) as [Locale, TableSource<M>][]) {
    if (typeof source !== 'function') loaded[locale] = source;
  }
  const module: MessageModule<M> = {
    get: (locale) => loaded[locale] ?? en,
    async load(locale) {
      const have = loaded[locale];
      if (have) return have;
      const table = await (sources[locale] as () => Promise<M>)();
      loaded[locale] = table;
      return table;
    },
  };
  modules.push(module as MessageModule<unknown>);
  return module;
}

/**
 * Loads a language for every message module made so far (the app's, the shell's and each loaded feature's); a
 * feature loaded later (the lab) makes its module with its chunk, and it bundles its tables, so nothing is missed.
 */
export async function loadLanguage(locale: Locale): Promise<void> {
  await Promise.all(modules.map((m) => m.load(locale)));
}
