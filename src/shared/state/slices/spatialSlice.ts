import { wrapDeg180 } from '../../../solver/angles';
import { parseDecimal } from '../../decimal';
import type { Codec } from '../../url/urlCodec';
import { enumCodec, exactText, fixedText } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { onPage, optionalKey, sameText, sliceLens, urlKey } from '../../url/urlKey';
import { URL_ANGLE_DECIMALS } from '../../url/urlPrecision';
import type { Action } from '../appState';
import type { Slice } from '../slice';
import { normalizeTheta2Deg } from './motionSlice';

/** Which spatial linkage the page shows: the spherical four-bar or the RSSR (URL sk). */
export type SpatialKind = 'sph' | 'rssr';

/** The spatial page's branch, as the spatial numerics name it. */
export type SpatialBranchName = 'open' | 'crossed';

/**
 * The spatial page (issue 32): the linkage kind, the spherical arcs and coupler point (degrees), the RSSR's lengths
 * (any one unit) and tilt (degrees), the input angle and the branch. Both kinds' values are kept, so switching back
 * finds them.
 */
export interface SpatialState {
  kind: SpatialKind;
  /** Spherical arcs of the ground, crank, coupler and rocker, degrees in (0, 180). */
  a1Deg: number;
  a2Deg: number;
  a3Deg: number;
  a4Deg: number;
  /** The coupler point's arc from A, degrees in [0, 180); 0 means no coupler point. */
  pDistDeg: number;
  /** The coupler point's turn about A from the arc A→B, degrees in (−180, 180]. */
  pAngleDeg: number;
  /** RSSR crank, coupler and rocker (positive), the axes' common normal a (≥ 0), pin offsets h2, h4 (any sign). */
  r2: number;
  r3: number;
  r4: number;
  a: number;
  h2: number;
  h4: number;
  /** RSSR output axis tilt about x, degrees in (−180, 180]. */
  betaDeg: number;
  /** Input angle, degrees in [0, 360). */
  theta2Deg: number;
  branch: SpatialBranchName;
  /** The input's speed ω2 (rad/s, |ω2| ≤ 1e6) and acceleration α2 (rad/s², |α2| ≤ 1e9) the rates are for. */
  omega2RadPerS: number;
  alpha2RadPerS2: number;
}

/** The numeric fields of the spatial state. */
export type SpatialField = Exclude<keyof SpatialState, 'kind' | 'branch'>;

/** What a spatial field accepts: [min, max], each end open or closed, whether it is an angle (degrees), its rate unit. */
export interface SpatialFieldSpec {
  /** The field's URL key (and its name in messages). */
  key: string;
  min: number;
  max: number;
  minOpen: boolean;
  maxOpen: boolean;
  angle: boolean;
  /** The unit of a rate field, shown beside it (ω2, α2). */
  unit?: 'rad/s' | 'rad/s²';
}

/** Largest length the RSSR fields take (the numerics rescale, so 1e±300 solves like 1). */
export const SPATIAL_LENGTH_MAX = 1e300;

const arc = (key: string): SpatialFieldSpec => ({ key, min: 0, max: 180, minOpen: true, maxOpen: true, angle: true });
const turn = (key: string): SpatialFieldSpec => ({
  key,
  min: -180,
  max: 180,
  minOpen: true,
  maxOpen: false,
  angle: true,
});
const positive = (key: string): SpatialFieldSpec => ({
  key,
  min: 0,
  max: SPATIAL_LENGTH_MAX,
  minOpen: true,
  maxOpen: false,
  angle: false,
});
const offset = (key: string): SpatialFieldSpec => ({
  key,
  min: -SPATIAL_LENGTH_MAX,
  max: SPATIAL_LENGTH_MAX,
  minOpen: false,
  maxOpen: false,
  angle: false,
});

/** Every numeric field's URL key and range (issue 32's key names). */
export const SPATIAL_FIELDS: Readonly<Record<SpatialField, SpatialFieldSpec>> = {
  a1Deg: arc('a1'),
  a2Deg: arc('a2'),
  a3Deg: arc('a3'),
  a4Deg: arc('a4'),
  pDistDeg: { key: 'pd', min: 0, max: 180, minOpen: false, maxOpen: true, angle: true },
  pAngleDeg: turn('pa'),
  r2: positive('r2'),
  r3: positive('r3'),
  r4: positive('r4'),
  a: { ...positive('a'), minOpen: false },
  h2: offset('h2'),
  h4: offset('h4'),
  betaDeg: turn('beta'),
  theta2Deg: { key: 't2', min: 0, max: 360, minOpen: false, maxOpen: true, angle: true },
  // The simulator's bounds of w2 and a2; α2's key is al2, as a2 is the crank arc here.
  omega2RadPerS: { key: 'w2', min: -1e6, max: 1e6, minOpen: false, maxOpen: false, angle: false, unit: 'rad/s' },
  alpha2RadPerS2: { key: 'al2', min: -1e9, max: 1e9, minOpen: false, maxOpen: false, angle: false, unit: 'rad/s²' },
};

/** The spherical crank-rocker preset (sph-crank-rocker) at θ2 = 30°, with the RSSR fields at the skew drive's. */
export const DEFAULT_SPATIAL: SpatialState = {
  kind: 'sph',
  a1Deg: 60,
  a2Deg: 20,
  a3Deg: 55,
  a4Deg: 45,
  pDistDeg: 25,
  pAngleDeg: 40,
  r2: 1,
  r3: 4,
  r4: 2,
  a: 3,
  h2: 0.5,
  h4: 1,
  betaDeg: 60,
  theta2Deg: 30,
  branch: 'open',
  omega2RadPerS: 1,
  alpha2RadPerS2: 0,
};

/**
 * Why value cannot be the field, in English naming the key and the value (`a1 must be in (0, 180) degrees, got
 * 200`), or null. Angles that wrap (pa, beta, t2) are checked after wrapping by the caller.
 */
export function spatialFieldProblem(field: SpatialField, value: number): string | null {
  const f = SPATIAL_FIELDS[field];
  const inside =
    Number.isFinite(value) &&
    (f.minOpen ? value > f.min : value >= f.min) &&
    (f.maxOpen ? value < f.max : value <= f.max);
  if (inside) return null;
  const span = `${f.minOpen ? '(' : '['}${f.min}, ${f.max}${f.maxOpen ? ')' : ']'}`;
  return `${f.key} must be in ${span}${f.angle ? ' degrees' : ''}, got ${String(value)}`;
}

/** Maps a typed value into the field's canonical range where the field is an angle that wraps (pa, beta, t2). */
export function normalizeSpatial(field: SpatialField, value: number): number {
  if (field === 'theta2Deg') return normalizeTheta2Deg(value);
  if (field === 'pAngleDeg' || field === 'betaDeg') return wrapDeg180(value);
  return value;
}

/** Actions only the spatial slice handles (values checked by the caller, as the codecs check them). */
export type SpatialAction =
  | { type: 'setSpatial'; patch: Partial<SpatialState> }
  | { type: 'setSpatialField'; field: SpatialField; value: number };

/** The spatial slice's reducer: pure, returns the same object when nothing changes. */
export function spatialReducer(s: SpatialState, action: Action): SpatialState {
  if (action.type === 'setSpatialField') {
    return s[action.field] === action.value ? s : { ...s, [action.field]: action.value };
  }
  if (action.type !== 'setSpatial') return s;
  const keys = Object.keys(action.patch) as (keyof SpatialState)[];
  if (keys.every((k) => action.patch[k] === s[k])) return s;
  return { ...s, ...action.patch };
}

/** A field's codec: degrees to 1e-9 (wrapped where the field wraps), lengths exactly; refused as spatialFieldProblem says. */
function fieldCodec(field: SpatialField): Codec<number> {
  const spec = SPATIAL_FIELDS[field];
  const text = (x: number) => (spec.angle ? fixedText(x, URL_ANGLE_DECIMALS) : exactText(x));
  return {
    parse(raw) {
      const x = parseDecimal(raw);
      if (Number.isNaN(x)) return { ok: false, why: 'not a number' };
      const v = normalizeSpatial(field, x);
      const problem = spatialFieldProblem(field, v);
      return problem ? { ok: false, why: problem } : { ok: true, value: v };
    },
    format: (x) => text(normalizeSpatial(field, Number(text(x)))),
  };
}

const field = sliceLens('spatial');

/** The fields of each kind: a link writes the shown kind's always and the other kind's when not the default. */
const KIND_FIELDS: Readonly<Record<SpatialKind, readonly SpatialField[]>> = {
  sph: ['a1Deg', 'a2Deg', 'a3Deg', 'a4Deg', 'pDistDeg', 'pAngleDeg'],
  rssr: ['r2', 'r3', 'r4', 'a', 'betaDeg', 'h2', 'h4'],
};

/** A field's key: written when its kind is shown or it differs from the default. */
function kindKey(kind: SpatialKind, f: SpatialField): UrlKey<unknown> {
  const codec = fieldCodec(f);
  const lens = field(f);
  const other = optionalKey(SPATIAL_FIELDS[f].key, codec, lens, DEFAULT_SPATIAL[f]);
  return urlKey(
    SPATIAL_FIELDS[f].key,
    codec,
    lens,
    'state',
    (u) => u.state.spatial.kind === kind || (other.include?.(u) ?? true),
  );
}

/**
 * The spatial page's URL keys (issue 32's names, angles in degrees), read and written only on page=3d, where r2, r3,
 * r4, t2, br, pd, pa and a2 are the spatial linkage's, not the simulator's: sk, a1..a4, pd, pa, r2 r3 r4 a beta h2 h4,
 * t2, br, and w2 (ω2, rad/s) and al2 (α2, rad/s²) when not the defaults 1 and 0.
 */
export const SPATIAL_URL_KEYS: readonly UrlKey<unknown>[] = onPage('spatial', [
  urlKey('sk', enumCodec(sameText(['sph', 'rssr'] as const)), field('kind')),
  ...KIND_FIELDS.sph.map((f) => kindKey('sph', f)),
  ...KIND_FIELDS.rssr.map((f) => kindKey('rssr', f)),
  urlKey('t2', fieldCodec('theta2Deg'), field('theta2Deg')),
  urlKey('br', enumCodec(sameText(['open', 'crossed'] as const)), field('branch')),
  optionalKey('w2', fieldCodec('omega2RadPerS'), field('omega2RadPerS'), DEFAULT_SPATIAL.omega2RadPerS),
  optionalKey('al2', fieldCodec('alpha2RadPerS2'), field('alpha2RadPerS2'), DEFAULT_SPATIAL.alpha2RadPerS2),
]);

/** The spatial slice's registration in SLICES (appState.ts). */
export const SPATIAL_SLICE: Slice<SpatialState, SpatialAction> = {
  summary: 'the Spatial page (page=3d): spherical or RSSR linkage, its arcs or lengths, θ2 and branch',
  defaults: DEFAULT_SPATIAL,
  reducer: spatialReducer,
  urlKeys: SPATIAL_URL_KEYS,
};
