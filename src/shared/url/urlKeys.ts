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

/** Rules between keys: the transmission band needs mulo < muhi. */
export const URL_CONSTRAINTS: readonly UrlConstraint[] = [
  {
    keys: ['mulo', 'muhi'],
    holds: (s) => s.display.muBandLoDeg < s.display.muBandHiDeg,
    why: 'the transmission band needs mulo < muhi',
  },
];
