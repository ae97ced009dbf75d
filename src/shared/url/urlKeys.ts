import { LAB_STEPS_DEG, LAB_TOLERANCES } from '../../study/options';
import { wrapDeg180 } from '../../solver/angles';
import { SWEEP_METHODS } from '../../solver/methods';
import type { Linkage } from '../../solver/types';
import type { AppState, CouplerPoint, ViewOffset } from '../state/appState';
import { DEFAULT_STATE, SAMPLES_MAX, SAMPLES_MIN, normalizeTheta2Deg } from '../state/appState';
import type { EmbedOptions } from './embedOptions';
import { DEFAULT_EMBED, EMBED_PANELS, LOCKABLE_PARAMS } from './embedOptions';
import { LOCALES } from '../i18n/i18n';
import type { Codec } from './urlCodec';
import { boolCodec, choiceCodec, enumCodec, integerCodec, listCodec, nullableCodec, numberCodec } from './urlCodec';

/** What the URL describes: the app state and the embed options. */
export interface UrlTarget {
  state: AppState;
  embed: EmbedOptions;
}

/** Where one parameter's value lives in a UrlTarget: get reads it, set returns a new target with it replaced. */
export interface Lens<T> {
  get(target: UrlTarget): T;
  set(target: UrlTarget, value: T): UrlTarget;
}

/**
 * One URL parameter: its name, its codec (parse, format) and its lens (get, set). parseUrl and serializeState
 * both walk URL_KEYS, so a key added here is read and written. Methods (not function-valued properties) so
 * that keys of different value types share one table type.
 */
export interface UrlKey<T> extends Codec<T>, Lens<T> {
  name: string;
  /** 'state' keys go into every share link; 'embed' keys only into embed URLs. */
  scope: 'state' | 'embed';
  /** Whether serializeState writes the key for this target; absent means always. */
  include?(target: UrlTarget): boolean;
}

/** A rule between keys checked after every key is parsed; the keys that break it are reverted and reported. */
export interface UrlConstraint {
  keys: readonly string[];
  holds(state: AppState): boolean;
  why: string;
}

/** Decimals of angles in degrees in the URL: 1e-9 deg keeps any typed value and drops float noise from Play. */
export const URL_ANGLE_DECIMALS = 9;
/** Significant digits of the view's zoom and pan in the URL (sub-pixel at any canvas size). */
export const URL_VIEW_DIGITS = 6;

/** Zoom factors accepted from the URL (1 = fitted). */
export const ZOOM_RANGE = { min: 1e-3, max: 1e3 } as const;
/** Pan accepted from the URL, in fractions of the view's width or height. */
export const PAN_RANGE = { min: -100, max: 100 } as const;

/** The default target: the default state and embed options. */
export const DEFAULT_TARGET: UrlTarget = { state: DEFAULT_STATE, embed: DEFAULT_EMBED };

function stateLens<K extends keyof AppState>(field: K): Lens<AppState[K]> {
  return {
    get: (u) => u.state[field],
    set: (u, value) => ({ ...u, state: { ...u.state, [field]: value } }),
  };
}

function linkageLens(field: keyof Linkage): Lens<number> {
  return {
    get: (u) => u.state.linkage[field],
    set: (u, value) => ({ ...u, state: { ...u.state, linkage: { ...u.state.linkage, [field]: value } } }),
  };
}

function couplerLens(field: keyof CouplerPoint): Lens<number> {
  return {
    get: (u) => u.state.coupler[field],
    set: (u, value) => ({ ...u, state: { ...u.state, coupler: { ...u.state.coupler, [field]: value } } }),
  };
}

function viewLens(field: keyof ViewOffset): Lens<number> {
  return {
    get: (u) => u.state.view[field],
    set: (u, value) => ({ ...u, state: { ...u.state, view: { ...u.state.view, [field]: value } } }),
  };
}

function embedLens<K extends keyof EmbedOptions>(field: K): Lens<EmbedOptions[K]> {
  return {
    get: (u) => u.embed[field],
    set: (u, value) => ({ ...u, embed: { ...u.embed, [field]: value } }),
  };
}

function key<T>(
  name: string,
  codec: Codec<T>,
  lens: Lens<T>,
  scope: UrlKey<T>['scope'] = 'state',
  include?: (target: UrlTarget) => boolean,
): UrlKey<T> {
  return {
    name,
    scope,
    parse: codec.parse,
    format: codec.format,
    get: lens.get,
    set: lens.set,
    ...(include ? { include } : {}),
  };
}

/** A key that is written only when its text differs from the default's (keeps links short and old links alike). */
function optional<T>(name: string, codec: Codec<T>, lens: Lens<T>): UrlKey<T> {
  return key(name, codec, lens, 'state', (u) => codec.format(lens.get(u)) !== codec.format(lens.get(DEFAULT_TARGET)));
}

const viewMoved = (u: UrlTarget): boolean =>
  u.state.view.zoom !== 1 || u.state.view.panX !== 0 || u.state.view.panY !== 0;
const length = numberCodec('r1');
const angle360 = numberCodec('theta2', { decimals: URL_ANGLE_DECIMALS, normalize: normalizeTheta2Deg });
const angle180 = numberCodec('couplerAngle', { decimals: URL_ANGLE_DECIMALS, normalize: wrapDeg180 });

/**
 * Every URL parameter, in the order serializeState writes them. README "Share and embed" lists them;
 * z, px, py (view) are written together when the view was zoomed or panned; panels and lock only for embeds.
 */
export const URL_KEYS: readonly UrlKey<unknown>[] = [
  key('r1', length, linkageLens('r1')),
  key('r2', numberCodec('r2'), linkageLens('r2')),
  key('r3', numberCodec('r3'), linkageLens('r3')),
  key('r4', numberCodec('r4'), linkageLens('r4')),
  key('t2', angle360, stateLens('theta2Deg')),
  key(
    'br',
    enumCodec([
      ['open', 'open'],
      ['crossed', 'crossed'],
    ] as const),
    stateLens('branch'),
  ),
  key('pd', numberCodec('couplerDistance'), couplerLens('distance')),
  key('pa', angle180, couplerLens('angleDeg')),
  key('play', boolCodec, stateLens('playing')),
  key('spd', numberCodec('speed'), stateLens('speedDegPerFrame')),
  key(
    'dir',
    enumCodec([
      ['ccw', 1],
      ['cw', -1],
    ] as const),
    stateLens('direction'),
  ),
  key('grid', boolCodec, stateLens('showGrid')),
  key('ang', boolCodec, stateLens('showAngles')),
  key('ghost', boolCodec, stateLens('showGhost')),
  key('trace', boolCodec, stateLens('showTrace')),
  key(
    'nr',
    enumCodec([
      ['cont', 'continuation'],
      ['cold', 'cold'],
    ] as const),
    stateLens('nrStart'),
  ),
  key(
    'plots',
    enumCodec([
      ['separate', 'separate'],
      ['together', 'together'],
    ] as const),
    stateLens('plotLayout'),
  ),
  key('n', integerCodec(SAMPLES_MIN, SAMPLES_MAX), stateLens('samples')),
  key(
    'lang',
    enumCodec(
      LOCALES.map((l) => [l, l] as const),
      true,
    ),
    stateLens('locale'),
  ),
  key('m', enumCodec(SWEEP_METHODS.map((m) => [m, m] as const)), stateLens('method')),
  key('tol', nullableCodec(choiceCodec(LAB_TOLERANCES), 'default'), stateLens('tol')),
  optional(
    'page',
    enumCodec([
      ['sim', 'simulator'],
      ['lab', 'lab'],
    ] as const),
    stateLens('page'),
  ),
  optional('lstep', choiceCodec(LAB_STEPS_DEG), stateLens('labStepDeg')),
  optional('w2', numberCodec('omega2'), stateLens('omega2RadPerS')),
  optional('a2', numberCodec('alpha2'), stateLens('alpha2RadPerS2')),
  optional('vel', boolCodec, stateLens('showVelocity')),
  optional('acc', boolCodec, stateLens('showAcceleration')),
  optional(
    'plot',
    enumCodec([
      ['ang', 'angles'],
      ['vel', 'velocities'],
      ['acc', 'accelerations'],
    ] as const),
    stateLens('plotKind'),
  ),
  optional('mulo', numberCodec('muBandLo'), stateLens('muBandLoDeg')),
  optional('muhi', numberCodec('muBandHi'), stateLens('muBandHiDeg')),
  optional('dc', boolCodec, stateLens('showDeadCentres')),
  optional('ic', boolCodec, stateLens('showInstantCentres')),
  key('z', numberCodec(ZOOM_RANGE, { significant: URL_VIEW_DIGITS }), viewLens('zoom'), 'state', viewMoved),
  key('px', numberCodec(PAN_RANGE, { significant: URL_VIEW_DIGITS }), viewLens('panX'), 'state', viewMoved),
  key('py', numberCodec(PAN_RANGE, { significant: URL_VIEW_DIGITS }), viewLens('panY'), 'state', viewMoved),
  key('panels', listCodec(EMBED_PANELS), embedLens('panels'), 'embed'),
  key('lock', listCodec(LOCKABLE_PARAMS), embedLens('locked'), 'embed', (u) => u.embed.locked.length > 0),
];

/** Rules between keys: the transmission band needs mulo < muhi. */
export const URL_CONSTRAINTS: readonly UrlConstraint[] = [
  {
    keys: ['mulo', 'muhi'],
    holds: (s) => s.muBandLoDeg < s.muBandHiDeg,
    why: 'the transmission band needs mulo < muhi',
  },
];
