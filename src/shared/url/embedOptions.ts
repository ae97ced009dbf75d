import type { Page } from '../state/appState';

/** Panels an embed can show besides the canvas ('forces': the Forces toggle, force arrows and the numbers). */
export type EmbedPanel = 'controls' | 'info' | 'plots' | 'export' | 'forces';

/**
 * Parameters an embed can lock (shown, not editable): the simulator's lengths, θ2, branch, coupler point and Play;
 * the mechanism page's template and editing (dragging joints, the linkage in mech=); the spatial page's parameters
 * (kind, arcs or lengths, coupler point) beside its θ2, branch and Play.
 */
export type LockableParam =
  'r1' | 'r2' | 'r3' | 'r4' | 'theta2' | 'branch' | 'coupler' | 'play' | 'template' | 'edit' | 'params';

/** Embed-only options: which panels show and which parameters are locked. */
export interface EmbedOptions {
  panels: EmbedPanel[];
  locked: LockableParam[];
}

/** All embed panels in display order. */
export const EMBED_PANELS: readonly EmbedPanel[] = ['controls', 'info', 'plots', 'export', 'forces'];

/** All lockable parameters. */
export const LOCKABLE_PARAMS: readonly LockableParam[] = [
  'r1',
  'r2',
  'r3',
  'r4',
  'theta2',
  'branch',
  'coupler',
  'play',
  'template',
  'edit',
  'params',
];

/** An embed shows the controls and the plots, with nothing locked, unless the URL says otherwise. */
export const DEFAULT_EMBED: EmbedOptions = { panels: ['controls', 'plots'], locked: [] };

/** How a page embeds: the panels and locks it offers (in the generator's order) and the lock guarding each URL key. */
export interface PageEmbedOptions {
  panels: readonly EmbedPanel[];
  locks: readonly LockableParam[];
  /** The lock that guards each URL key a host could set (postMessage, the element's attributes): locked, refused. */
  keyLocks: Readonly<Record<string, LockableParam>>;
  /** Keys an embed URL of the page writes even at their default (tpl): an embed keeps its linkage if a default changes. */
  pinnedKeys: readonly string[];
}

/** The spatial page's linkage keys (sk, arcs, coupler point, RSSR lengths and tilt, the input's ω2 and α2): the 'params' lock. */
const SPATIAL_PARAM_KEYS = [
  'sk',
  'a1',
  'a2',
  'a3',
  'a4',
  'pd',
  'pa',
  'r2',
  'r3',
  'r4',
  'a',
  'beta',
  'h2',
  'h4',
  'w2',
  'al2',
];

/**
 * Which pages embed (embed.html?page=…, <fourbar-lab page="…">) and with what options; null: the page has no embed
 * (its link opens the simulator's). The generator's page list, the URL's check of panels and lock, and the host's
 * set-state locks come from here; src/app/embedPages.tsx gives each page here its view (a page missing there is a
 * type error). A page missing here is one too.
 */
export const PAGE_EMBEDS = {
  simulator: {
    panels: EMBED_PANELS,
    locks: ['r1', 'r2', 'r3', 'r4', 'theta2', 'branch', 'coupler', 'play'],
    keyLocks: {
      r1: 'r1',
      r2: 'r2',
      r3: 'r3',
      r4: 'r4',
      t2: 'theta2',
      br: 'branch',
      pd: 'coupler',
      pa: 'coupler',
      play: 'play',
    },
    pinnedKeys: [],
  },
  lab: null,
  synthesis: null,
  mechanism: {
    panels: ['controls', 'info', 'plots'],
    locks: ['template', 'edit'],
    keyLocks: { tpl: 'template', mech: 'edit' },
    pinnedKeys: ['tpl'],
  },
  spatial: {
    panels: ['controls', 'info', 'plots'],
    locks: ['params', 'theta2', 'branch', 'play'],
    keyLocks: {
      ...Object.fromEntries(SPATIAL_PARAM_KEYS.map((k) => [k, 'params' as const])),
      t2: 'theta2',
      br: 'branch',
    },
    pinnedKeys: [],
  },
} satisfies Readonly<Record<Page, PageEmbedOptions | null>>;

/** A page that embeds (its PAGE_EMBEDS entry is not null). */
export type EmbedPage = { [P in Page]: (typeof PAGE_EMBEDS)[P] extends null ? never : P }[Page];

/** The pages that embed, in the registry's order. */
export const EMBED_PAGES = (Object.keys(PAGE_EMBEDS) as Page[]).filter((p): p is EmbedPage => PAGE_EMBEDS[p] !== null);

/** Whether the page embeds. */
export function isEmbedPage(page: Page): page is EmbedPage {
  return PAGE_EMBEDS[page] !== null;
}

/** The options an embed of this page uses: the page's own, or the simulator's for a page without an embed. */
export function pageEmbedOptions(page: Page): PageEmbedOptions {
  return isEmbedPage(page) ? PAGE_EMBEDS[page] : PAGE_EMBEDS.simulator;
}
