import { enumCodec } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { optionalKey, sameText, sliceLens, urlKey } from '../../url/urlKey';
import type { Action } from '../appState';
import type { Slice } from '../slice';
import { LOCALES } from '../../i18n/i18n';

/** UI languages: English (default) and Traditional Chinese. */
export type Locale = 'en' | 'zh-TW';

/**
 * Every page of the app and its value in the URL (page=…): the simulator, the solver lab (work-precision study of
 * the current linkage), synthesis. src/app/pages.tsx gives each its tab and view (a page missing there is a type
 * error); docs/ARCHITECTURE.md "To add a page".
 */
export const PAGE_URL_VALUES = { simulator: 'sim', lab: 'lab', synthesis: 'syn', mechanism: 'mech' } as const;

/** Which page the app shows. */
export type Page = keyof typeof PAGE_URL_VALUES;

/** The shell slice: the language and the page shown. */
export interface ShellState {
  locale: Locale;
  page: Page;
}

/** Actions only the shell slice handles. */
export type ShellAction = { type: 'setLocale'; locale: Locale } | { type: 'setPage'; page: Page };

/** English, on the simulator page. */
export const DEFAULT_SHELL: ShellState = { locale: 'en', page: 'simulator' };

/** The shell slice's reducer: pure, returns the same object when nothing changes. */
export function shellReducer(s: ShellState, action: Action): ShellState {
  switch (action.type) {
    case 'setLocale':
      return action.locale === s.locale ? s : { ...s, locale: action.locale };
    case 'setPage':
      return action.page === s.page ? s : { ...s, page: action.page };
    default:
      return s;
  }
}

const field = sliceLens('shell');

/** The shell's URL keys: lang (any letter case), and page when it is not the simulator. */
export const SHELL_URL_KEYS: readonly UrlKey<unknown>[] = [
  urlKey('lang', enumCodec(sameText(LOCALES), true), field('locale')),
  optionalKey(
    'page',
    enumCodec((Object.keys(PAGE_URL_VALUES) as Page[]).map((page) => [PAGE_URL_VALUES[page], page] as const)),
    field('page'),
    DEFAULT_SHELL.page,
  ),
];

/** The shell slice's registration in SLICES (appState.ts). */
export const SHELL_SLICE: Slice<ShellState, ShellAction> = {
  summary: 'the language and the page',
  defaults: DEFAULT_SHELL,
  reducer: shellReducer,
  urlKeys: SHELL_URL_KEYS,
};
