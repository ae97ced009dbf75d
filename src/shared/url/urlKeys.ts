import { DESIGN_URL_KEYS } from '../state/slices/designSlice';
import { DISPLAY_URL_KEYS } from '../state/slices/displaySlice';
import { FORCES_URL_KEYS } from '../state/slices/forcesSlice';
import { LAB_URL_KEYS } from '../state/slices/labSlice';
import { MOTION_URL_KEYS } from '../state/slices/motionSlice';
import { SHELL_URL_KEYS } from '../state/slices/shellSlice';
import { SOLVER_URL_KEYS } from '../state/slices/solverSlice';
import { SYN_FUNCTION_URL_KEYS } from '../state/slices/synFunctionSlice';
import { SYN_MOTION_URL_KEYS } from '../state/slices/synMotionSlice';
import { SYN_PATH_URL_KEYS } from '../state/slices/synthesisSlice';
import { DEFAULT_STATE } from '../state/appState';
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
 * The one URL table: every slice's keys, in the order serializeState writes them. docs/instructors.md "URL keys"
 * lists them; panels and lock go only into embed URLs.
 */
export const URL_KEYS: readonly UrlKey<unknown>[] = [
  ...DESIGN_URL_KEYS,
  ...MOTION_URL_KEYS,
  ...DISPLAY_URL_KEYS,
  ...SOLVER_URL_KEYS,
  ...SHELL_URL_KEYS,
  ...LAB_URL_KEYS,
  ...SYN_PATH_URL_KEYS,
  ...FORCES_URL_KEYS,
  ...SYN_MOTION_URL_KEYS,
  ...SYN_FUNCTION_URL_KEYS,
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
