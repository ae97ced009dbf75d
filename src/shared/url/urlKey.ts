import type { AppState, Page } from '../state/appState';
import type { EmbedOptions } from './embedOptions';
import type { Codec } from './urlCodec';

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
 * both walk URL_KEYS, so a key a slice adds to its list is read and written. Methods (not function-valued
 * properties) so that keys of different value types share one table type.
 */
export interface UrlKey<T> extends Codec<T>, Lens<T> {
  name: string;
  /** 'state' keys go into every share link; 'embed' keys only into embed URLs. */
  scope: 'state' | 'embed';
  /** Whether serializeState writes the key for this target; absent means always. */
  include?(target: UrlTarget): boolean;
  /**
   * The page whose links alone read and write the key; absent means every page. On its page the key shadows a key of
   * the same name with no page (the spatial page's r2 is its RSSR crank, not the simulator's), elsewhere it is unknown.
   */
  page?: Page;
}

/** A rule between keys checked after every key is parsed; the keys that break it are reverted and reported. */
export interface UrlConstraint {
  keys: readonly string[];
  holds(state: AppState): boolean;
  why: string;
}

/** The slices of the app state (each a plain object of fields). */
type SliceName = keyof AppState;

/** A lens on one field of one slice: sliceLens('motion')('theta2Deg'). */
export function sliceLens<S extends SliceName>(slice: S) {
  return <K extends keyof AppState[S]>(field: K): Lens<AppState[S][K]> => ({
    get: (u) => u.state[slice][field],
    set: (u, value) => ({ ...u, state: { ...u.state, [slice]: { ...u.state[slice], [field]: value } } }),
  });
}

/** A lens on one field of an object-valued field of a slice: the linkage's r1, the view's zoom. */
export function nestedLens<S extends SliceName, K extends keyof AppState[S]>(slice: S, field: K) {
  return <F extends keyof AppState[S][K]>(inner: F): Lens<AppState[S][K][F]> => ({
    get: (u) => u.state[slice][field][inner],
    set: (u, value) => {
      const s = u.state[slice];
      return { ...u, state: { ...u.state, [slice]: { ...s, [field]: { ...s[field], [inner]: value } } } };
    },
  });
}

/** A lens on one embed option. */
export function embedLens<K extends keyof EmbedOptions>(field: K): Lens<EmbedOptions[K]> {
  return {
    get: (u) => u.embed[field],
    set: (u, value) => ({ ...u, embed: { ...u.embed, [field]: value } }),
  };
}

/** A URL parameter from its name, codec and lens; written always unless include says otherwise. */
export function urlKey<T>(
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

/** A key written only when its text differs from the default value's (keeps links short and old links alike). */
export function optionalKey<T>(name: string, codec: Codec<T>, lens: Lens<T>, defaultValue: T): UrlKey<T> {
  const defaultText = codec.format(defaultValue);
  return urlKey(name, codec, lens, 'state', (u) => codec.format(lens.get(u)) !== defaultText);
}

/** An enum codec's pairs where the URL text is the value itself. */
export function sameText<T extends string>(values: readonly T[]): (readonly [string, T])[] {
  return values.map((v) => [v, v] as const);
}

/** The keys, each read and written only on this page (see UrlKey.page). */
export function onPage(page: Page, keys: readonly UrlKey<unknown>[]): UrlKey<unknown>[] {
  return keys.map((k) => ({ ...k, page }));
}
