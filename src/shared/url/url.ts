import type { AppState, Page } from '../state/appState';
import { DEFAULT_STATE } from '../state/appState';
import type { EmbedOptions, PageEmbedOptions } from './embedOptions';
import { DEFAULT_EMBED, PAGE_EMBEDS, isEmbedPage, pageEmbedOptions } from './embedOptions';
import { truncateText } from '../format';
import { PAGE_URL_VALUES } from '../state/slices/shellSlice';
import type { UrlTarget } from './urlKeys';
import { URL_CONSTRAINTS, URL_KEYS, linkKeysOf, urlKeysOn } from './urlKeys';

export type { EmbedOptions, EmbedPanel, LockableParam } from './embedOptions';
export type { EmbedPage, PageEmbedOptions } from './embedOptions';
export {
  DEFAULT_EMBED,
  EMBED_PAGES,
  EMBED_PANELS,
  LOCKABLE_PARAMS,
  PAGE_EMBEDS,
  isEmbedPage,
  pageEmbedOptions,
} from './embedOptions';

/** Longest key or value, in characters, that a message about an ignored parameter echoes. */
export const IGNORED_ECHO_CHARS = 24;

/** A URL parameter that was ignored: raw key and value, the same shortened for display, and why (English). */
export interface IgnoredParam {
  key: string;
  value: string;
  /** key and value cut to IGNORED_ECHO_CHARS characters with an ellipsis, for notices and the console. */
  shownKey: string;
  shownValue: string;
  why: string;
}

/** Result of parsing a query string: the state, the embed options, and every parameter that was ignored. */
export interface ParsedUrl {
  state: AppState;
  embed: EmbedOptions;
  /** One English console line per ignored parameter (kept for logs; the UI reads `ignored`). */
  warnings: string[];
  ignored: IgnoredParam[];
}

/** The page a query string opens: its page parameter when that reads, else base's page. */
function pageOf(params: URLSearchParams, base: AppState): Page {
  const raw = params.get('page');
  const r = raw === null ? null : URL_KEYS.find((x) => x.name === 'page')?.parse(raw);
  return r?.ok ? (r.value as Page) : base.shell.page;
}

/**
 * Parses a query string (with or without '?') into the app state on top of base, walking the URL table of the page
 * it opens (urlKeysOn: a page's own keys shadow the others' of the same name). A bad
 * or unknown parameter is ignored and base's value kept; each is listed in `ignored` and passed to warn
 * (console.warn by default). Rules between keys (URL_CONSTRAINTS) revert the keys that break them. Never throws.
 */
export function parseUrl(
  search: string,
  base: AppState = DEFAULT_STATE,
  warn: (message: string) => void = (m) => console.warn(m),
): ParsedUrl {
  const params = new URLSearchParams(search.startsWith('?') ? search.slice(1) : search);
  const start: UrlTarget = { state: base, embed: DEFAULT_EMBED };
  let target = start;
  const ignored: IgnoredParam[] = [];
  const warnings: string[] = [];
  const bad = (key: string, value: string, why: string): void => {
    const p: IgnoredParam = {
      key,
      value,
      shownKey: truncateText(key, IGNORED_ECHO_CHARS),
      shownValue: truncateText(value, IGNORED_ECHO_CHARS),
      why,
    };
    const message = `Ignoring URL parameter ${p.shownKey}=${JSON.stringify(p.shownValue)}: ${why}; using the default.`;
    ignored.push(p);
    warnings.push(message);
    warn(message);
  };
  const given = new Map<string, string>();
  const keys = urlKeysOn(pageOf(params, base));
  for (const [name, value] of params) {
    const k = keys.find((x) => x.name === name);
    if (!k) {
      const other = URL_KEYS.find((x) => x.name === name)?.page;
      bad(name, value, other ? `read only on page=${PAGE_URL_VALUES[other]}` : 'unknown parameter');
      continue;
    }
    const r = k.parse(value);
    if (r.ok) {
      target = k.set(target, r.value);
      given.set(name, value);
    } else bad(name, value, r.why);
  }
  for (const c of URL_CONSTRAINTS) {
    if (c.holds(target.state)) continue;
    for (const name of c.keys) {
      const k = keys.find((x) => x.name === name);
      const value = given.get(name);
      if (!k || value === undefined) continue;
      target = k.set(target, k.get(start));
      bad(name, value, c.why);
    }
  }
  target = pageEmbedChecked(target, given, bad);
  return { state: target.state, embed: target.embed, warnings, ignored };
}

/**
 * The panels and locks a page's embed offers (PAGE_EMBEDS): a given one the page does not offer (lock=r1 on
 * page=mech) is dropped and the key reported, naming what the page offers. A page without an embed keeps them.
 */
function pageEmbedChecked(
  target: UrlTarget,
  given: ReadonlyMap<string, string>,
  bad: (key: string, value: string, why: string) => void,
): UrlTarget {
  const page = target.state.shell.page;
  if (!isEmbedPage(page)) return target;
  const offered: PageEmbedOptions = PAGE_EMBEDS[page];
  const where = `page=${PAGE_URL_VALUES[page]}`;
  const panels = target.embed.panels.filter((p) => offered.panels.includes(p));
  const locked = target.embed.locked.filter((l) => offered.locks.includes(l));
  const off = (list: readonly string[], kept: readonly string[]) => list.filter((x) => !kept.includes(x)).join(', ');
  if (panels.length < target.embed.panels.length)
    bad(
      'panels',
      given.get('panels') ?? '',
      `${off(target.embed.panels, panels)} not on ${where} (it shows ${offered.panels.join(', ')})`,
    );
  if (locked.length < target.embed.locked.length)
    bad(
      'lock',
      given.get('lock') ?? '',
      `${off(target.embed.locked, locked)} not on ${where} (it locks ${offered.locks.join(', ')})`,
    );
  return { ...target, embed: { panels, locked } };
}

/**
 * Serialises the state (and the embed options when given) to a query string without '?', walking the keys a link of
 * keysOf writes (default the state's page; linkKeysOf: a page=3d link holds the language, the page and the spatial
 * keys); parseUrl gives the state back (angles to 1e-9 degree, view to 6 digits, everything else exactly).
 */
export function serializeState(state: AppState, embed?: EmbedOptions, keysOf: Page = state.shell.page): string {
  const target: UrlTarget = { state, embed: embed ?? DEFAULT_EMBED };
  const p = new URLSearchParams();
  for (const k of linkKeysOf(keysOf)) {
    if (k.scope === 'embed' && !embed) continue;
    if (k.include && !k.include(target)) continue;
    p.set(k.name, k.format(k.get(target)));
  }
  return p.toString();
}

/**
 * The URL of the embed page beside the app page: same directory, embed.html, with the state and embed options, and
 * the page's pinned keys (PAGE_EMBEDS: page=mech's tpl) written even at their default.
 */
export function embedUrl(appHref: string, state: AppState, embed: EmbedOptions): string {
  const u = new URL(appHref);
  u.search = '';
  u.hash = '';
  u.pathname = u.pathname.replace(/[^/]*$/, 'embed.html');
  const page = state.shell.page;
  const query = new URLSearchParams(serializeState(state, embed));
  for (const name of pageEmbedOptions(page).pinnedKeys) {
    const k = urlKeysOn(page).find((x) => x.name === name);
    if (k && !query.has(name)) query.set(name, k.format(k.get({ state, embed })));
  }
  return `${u.toString()}?${query.toString()}`;
}

/** The URL of the full app beside the embed page, carrying the state. */
export function appUrl(embedHref: string, state: AppState): string {
  const u = new URL(embedHref);
  u.search = '';
  u.hash = '';
  u.pathname = u.pathname.replace(/[^/]*$/, '');
  return `${u.toString()}?${serializeState(state)}`;
}
