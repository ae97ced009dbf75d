import type { Point } from '../../../solver/kinematics';
import type { Codec, Decoded } from '../../url/urlCodec';
import { enumCodec, exactText, integerCodec, nullableCodec } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { optionalKey, sameText, sliceLens } from '../../url/urlKey';
import type { Action } from '../appState';
import { plainDecimal } from '../../decimal';
import type { Slice } from '../slice';

/** The synthesis page's modes: path, motion or function generation, or every linkage through nine points. */
export type SynthesisMode = 'path' | 'motion' | 'function' | 'nine';

/** How the targets are timed: free input angles (in order), equal steps of θ2, or a given θ2 per target. */
export type PathTiming = 'free' | 'step' | 'given';

/** What the input must do: turn fully (a crank), or anything that passes the targets without a limit position. */
export type PathInput = 'crank' | 'any';

/** A box for the crank pivot O2 (length unit). */
export interface PivotBox {
  min: Point;
  max: Point;
}

/**
 * The synthesis page's slice: its mode and the Path mode's task (targets in the length unit, angles in degrees).
 * A null bound means "from the targets' size" (pathBounds in features/synthesis).
 */
export interface SynPathState {
  mode: SynthesisMode;
  targets: Point[];
  timing: PathTiming;
  /** θ2 advance per target for equal steps, degrees (nonzero, −180 … 180). */
  timingStepDeg: number;
  /** θ2 of each target for given timing, degrees; NaN or past the end: not given (the page refuses to run). */
  givenTheta2Deg: number[];
  /** Longest link, length unit; null: from the targets' size. */
  boundLength: number | null;
  /** Largest coupler offset |AP|, length unit; null: from the targets' size. */
  boundCoupler: number | null;
  /** Box of O2; null: from the targets' size. */
  pivotBox: PivotBox | null;
  input: PathInput;
  /** Seed of the search (a whole number ≥ 1). */
  seed: number;
  /**
   * Index of the candidate shown (0 = best; URL cd, 0-based like the Motion mode's mc). A task edit sets it back to
   * 0; Synthesize keeps it, so a link or a design file reopens its chosen candidate when the same seed is run again.
   */
  chosen: number;
}

/** Largest index of a chosen candidate the URL takes (the search lists at most 64 candidates). */
export const MAX_PATH_CHOICE = 63;

/** Most targets a task may have (the URL and the paste keep at most this many). */
export const MAX_TARGETS = 40;

/** Actions only the synthesis slice handles. */
export type SynPathAction =
  | { type: 'setSynthesisMode'; mode: SynthesisMode }
  | { type: 'setTargets'; targets: Point[] }
  /** Removes a target and its given θ2 in one step (one undo step). */
  | { type: 'removeTarget'; index: number }
  | { type: 'setTiming'; timing: PathTiming }
  | { type: 'setTimingStep'; stepDeg: number }
  | { type: 'setGivenTheta2'; theta2Deg: number[] }
  | {
      type: 'setPathBounds';
      bounds: Partial<Pick<SynPathState, 'boundLength' | 'boundCoupler' | 'pivotBox'>>;
    }
  | { type: 'setPathInput'; input: PathInput }
  | { type: 'setPathSeed'; seed: number }
  | { type: 'chooseCandidate'; index: number };

/** Path mode, no targets, free timing, 30° steps, bounds from the targets, a crank input, seed 1. */
export const DEFAULT_SYN_PATH: SynPathState = {
  mode: 'path',
  targets: [],
  timing: 'free',
  timingStepDeg: 30,
  givenTheta2Deg: [],
  boundLength: null,
  boundCoupler: null,
  pivotBox: null,
  input: 'crank',
  seed: 1,
  chosen: 0,
};

function setField<K extends keyof SynPathState>(s: SynPathState, key: K, value: SynPathState[K]): SynPathState {
  return Object.is(s[key], value) ? s : { ...s, [key]: value };
}

/** A field of the task set: the candidate shown goes back to the best when it changes. */
function taskField<K extends keyof SynPathState>(s: SynPathState, key: K, value: SynPathState[K]): SynPathState {
  return Object.is(s[key], value) ? s : { ...s, [key]: value, chosen: 0 };
}

/** The synthesis slice's reducer: pure, returns the same object when nothing changes. */
export function synPathReducer(s: SynPathState, action: Action): SynPathState {
  switch (action.type) {
    case 'setSynthesisMode':
      return setField(s, 'mode', action.mode);
    case 'setTargets':
      return { ...s, targets: action.targets.slice(0, MAX_TARGETS).map((p) => ({ x: p.x, y: p.y })), chosen: 0 };
    case 'removeTarget':
      if (!(action.index >= 0 && action.index < s.targets.length)) return s;
      return {
        ...s,
        targets: s.targets.filter((_, k) => k !== action.index),
        givenTheta2Deg: s.givenTheta2Deg.filter((_, k) => k !== action.index),
        chosen: 0,
      };
    // A new task (or seed) makes new candidates: the best is shown first.
    case 'setTiming':
      return taskField(s, 'timing', action.timing);
    case 'setTimingStep':
      return taskField(s, 'timingStepDeg', action.stepDeg);
    case 'setGivenTheta2':
      return { ...s, givenTheta2Deg: action.theta2Deg.slice(0, MAX_TARGETS), chosen: 0 };
    case 'setPathBounds':
      return { ...s, ...action.bounds, chosen: 0 };
    case 'setPathInput':
      return taskField(s, 'input', action.input);
    case 'setPathSeed':
      return taskField(s, 'seed', action.seed);
    case 'chooseCandidate':
      return setField(s, 'chosen', action.index);
    default:
      return s;
  }
}

function ok<T>(value: T): Decoded<T> {
  return { ok: true, value };
}

function fail<T>(why: string): Decoded<T> {
  return { ok: false, why };
}

/** Numbers separated by commas (exact text), count from min to max; names the bad item. */
export function numberListCodec(what: string, min: number, max: number): Codec<number[]> {
  return {
    parse(raw) {
      const items = raw.trim() === '' ? [] : raw.split(',');
      if (items.length < min || items.length > max)
        return fail(`expected ${min} to ${max} ${what} separated by commas`);
      const out = items.map(plainDecimal);
      const bad = out.findIndex((x) => !Number.isFinite(x));
      return bad < 0 ? ok(out) : fail(`${what} ${bad + 1} (${JSON.stringify(items[bad])}) is not a number`);
    },
    format: (xs) => xs.map(exactText).join(','),
  };
}

/** Given θ2 per target as `a,b,…` in degrees (exact text); an empty item is a θ2 not given (NaN). */
const givenAnglesCodec: Codec<number[]> = {
  parse(raw) {
    const items = raw.trim() === '' ? [] : raw.split(',');
    if (items.length > MAX_TARGETS) return fail(`expected at most ${MAX_TARGETS} angles separated by commas`);
    const out = items.map((t) => (t.trim() === '' ? NaN : plainDecimal(t)));
    const bad = out.findIndex((x, i) => !Number.isFinite(x) && items[i].trim() !== '');
    return bad < 0 ? ok(out) : fail(`angle ${bad + 1} (${JSON.stringify(items[bad])}) is not a number`);
  },
  format: (xs) => xs.map((x) => (Number.isFinite(x) ? exactText(x) : '')).join(','),
};

/** Targets as `x,y;x,y;…` (exact text, at most MAX_TARGETS); names the bad point. */
export const targetsCodec: Codec<Point[]> = {
  parse(raw) {
    if (raw.trim() === '') return ok([]);
    const items = raw.split(';');
    if (items.length > MAX_TARGETS) return fail(`expected at most ${MAX_TARGETS} points x,y separated by ;`);
    const out: Point[] = [];
    for (let i = 0; i < items.length; i++) {
      const xy = items[i].split(',').map(plainDecimal);
      if (xy.length !== 2 || !xy.every(Number.isFinite)) {
        return fail(`point ${i + 1} (${JSON.stringify(items[i])}) is not x,y`);
      }
      out.push({ x: xy[0], y: xy[1] });
    }
    return ok(out);
  },
  format: (ps) => ps.map((p) => `${exactText(p.x)},${exactText(p.y)}`).join(';'),
};

/** A positive length (exact text). */
const lengthCodec: Codec<number> = {
  parse(raw) {
    const x = plainDecimal(raw);
    return x > 0 && Number.isFinite(x) ? ok(x) : fail('expected a positive length');
  },
  format: exactText,
};

/** The θ2 step of equal-step timing: degrees, nonzero, −180 … 180 (exact text). */
const stepCodec: Codec<number> = {
  parse(raw) {
    const x = plainDecimal(raw);
    return x !== 0 && Math.abs(x) <= 180 ? ok(x) : fail('expected a nonzero step in degrees from -180 to 180');
  },
  format: exactText,
};

/** The pivot box as `x0,y0,x1,y1` with x0 < x1 and y0 < y1. */
const pivotBoxCodec: Codec<PivotBox> = {
  parse(raw) {
    const r = numberListCodec('coordinate', 4, 4).parse(raw);
    if (!r.ok) return r;
    const [x0, y0, x1, y1] = r.value;
    return x0 < x1 && y0 < y1
      ? ok({ min: { x: x0, y: y0 }, max: { x: x1, y: y1 } })
      : fail('expected x0,y0,x1,y1 with x0 < x1 and y0 < y1');
  },
  format: (b) => [b.min.x, b.min.y, b.max.x, b.max.y].map(exactText).join(','),
};

const field = sliceLens('synPath');

/**
 * The synthesis slice's URL keys, each written only when it differs from the default: syn (path | motion | fn |
 * nine; function is read as fn),
 * tg (targets x,y;x,y;…), tm (free | step | given), ts (step, degrees), tt (given θ2 per target, degrees; empty: not
 * given),
 * bl (longest link), bc (coupler offset), bp (pivot box x0,y0,x1,y1), in (crank | any), sd (seed), cd (the chosen
 * candidate, 0-based).
 */
export const SYN_PATH_URL_KEYS: readonly UrlKey<unknown>[] = [
  optionalKey(
    'syn',
    enumCodec([
      ['path', 'path'],
      ['motion', 'motion'],
      ['fn', 'function'],
      // Read as fn, the mode's own name; enumCodec writes the first text for a value, so links keep syn=fn.
      ['function', 'function'],
      ['nine', 'nine'],
    ] as const),
    field('mode'),
    DEFAULT_SYN_PATH.mode,
  ),
  optionalKey('tg', targetsCodec, field('targets'), DEFAULT_SYN_PATH.targets),
  optionalKey('tm', enumCodec(sameText(['free', 'step', 'given'] as const)), field('timing'), DEFAULT_SYN_PATH.timing),
  optionalKey('ts', stepCodec, field('timingStepDeg'), DEFAULT_SYN_PATH.timingStepDeg),
  optionalKey('tt', givenAnglesCodec, field('givenTheta2Deg'), DEFAULT_SYN_PATH.givenTheta2Deg),
  optionalKey('bl', nullableCodec(lengthCodec, 'auto'), field('boundLength'), DEFAULT_SYN_PATH.boundLength),
  optionalKey('bc', nullableCodec(lengthCodec, 'auto'), field('boundCoupler'), DEFAULT_SYN_PATH.boundCoupler),
  optionalKey('bp', nullableCodec(pivotBoxCodec, 'auto'), field('pivotBox'), DEFAULT_SYN_PATH.pivotBox),
  optionalKey('in', enumCodec(sameText(['crank', 'any'] as const)), field('input'), DEFAULT_SYN_PATH.input),
  optionalKey('sd', integerCodec(1, 2 ** 31 - 1), field('seed'), DEFAULT_SYN_PATH.seed),
  optionalKey('cd', integerCodec(0, MAX_PATH_CHOICE), field('chosen'), DEFAULT_SYN_PATH.chosen),
];

/** The synPath slice's registration in SLICES (appState.ts). */
export const SYN_PATH_SLICE: Slice<SynPathState, SynPathAction> = {
  summary: "the synthesis page's mode and its Path mode's task: targets, timing, bounds, seed",
  defaults: DEFAULT_SYN_PATH,
  reducer: synPathReducer,
  urlKeys: SYN_PATH_URL_KEYS,
};
