import type { Page } from '../state/appState';
import { DEFAULT_STATE, SLICES, SLICE_NAMES } from '../state/appState';
import { DEFAULT_EMBED, EMBED_PANELS, LOCKABLE_PARAMS } from './embedOptions';
import { listCodec } from './urlCodec';
import type { UrlConstraint, UrlKey, UrlTarget } from './urlKey';
import { embedLens, urlKey } from './urlKey';

export type { UrlConstraint, UrlKey, UrlTarget } from './urlKey';

/** The default target: the default state and embed options. */
export const DEFAULT_TARGET: UrlTarget = { state: DEFAULT_STATE, embed: DEFAULT_EMBED };

/** The embed-only keys: panels, and lock when something is locked. */
const EMBED_URL_KEYS: readonly UrlKey<unknown>[] = [
  urlKey('panels', listCodec(EMBED_PANELS), embedLens('panels'), 'embed'),
  urlKey('lock', listCodec(LOCKABLE_PARAMS), embedLens('locked'), 'embed', (u) => u.embed.locked.length > 0),
];

/**
 * The one URL table: every slice's keys in SLICES's order, the order serializeState writes them, then the embed-only
 * keys (panels and lock go only into embed URLs). docs/instructors.md "URL keys" lists them (tests check the list).
 */
export const URL_KEYS: readonly UrlKey<unknown>[] = [
  ...SLICE_NAMES.flatMap((name) => SLICES[name].urlKeys),
  ...EMBED_URL_KEYS,
];

const keysByPage = new Map<Page, readonly UrlKey<unknown>[]>();

/**
 * The URL table as a link of this page reads and writes it: the keys of every page but those a key of this page
 * shadows (same name), and this page's own keys, in URL_KEYS's order. Names are unique within it.
 */
export function urlKeysOn(page: Page): readonly UrlKey<unknown>[] {
  let keys = keysByPage.get(page);
  if (!keys) {
    const own = new Set(URL_KEYS.filter((k) => k.page === page).map((k) => k.name));
    keys = URL_KEYS.filter((k) => (k.page === undefined ? !own.has(k.name) : k.page === page));
    keysByPage.set(page, keys);
  }
  return keys;
}

const linkKeysByPage = new Map<Page, readonly UrlKey<unknown>[]>();

/**
 * The keys a link of this page writes: on a page with keys of its own (the spatial page) the shell's keys (language,
 * page), its own and the embed's, so its links read as that page's; on the others every key without a page.
 */
export function linkKeysOf(page: Page): readonly UrlKey<unknown>[] {
  let keys = linkKeysByPage.get(page);
  if (!keys) {
    const own = URL_KEYS.filter((k) => k.page === page);
    keys = own.length
      ? [...SLICES.shell.urlKeys, ...own, ...EMBED_URL_KEYS]
      : URL_KEYS.filter((k) => k.page === undefined);
    linkKeysByPage.set(page, keys);
  }
  return keys;
}

/** Rules between keys: the transmission band needs mulo < muhi. */
export const URL_CONSTRAINTS: readonly UrlConstraint[] = [
  {
    keys: ['mulo', 'muhi'],
    holds: (s) => s.display.muBandLoDeg < s.display.muBandHiDeg,
    why: 'the transmission band needs mulo < muhi',
  },
];
