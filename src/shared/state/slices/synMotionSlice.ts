import { wrapDeg180 } from '../../../solver/angles';
import type { Point } from '../../../solver/kinematics';
import type { Codec, Decoded } from '../../url/urlCodec';
import { enumCodec, fixedText, significantText } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { optionalKey, sameText, sliceLens } from '../../url/urlKey';
import { URL_ANGLE_DECIMALS } from '../../url/urlPrecision';
import { parseDecimal } from '../../decimal';
import type { Action } from '../appState';
import type { Slice } from '../slice';

/** A coupler pose as the page holds it: its point (length unit) and the direction of its frame (degrees, CCW from +x). */
export interface PoseDeg {
  x: number;
  y: number;
  angleDeg: number;
}

/** Which pivots the designer places for three poses: the moving pivots A, B (coupler frame) or the fixed O2, O4 (plane). */
export type PivotChoice = 'moving' | 'fixed';

/** The synthesis page's Motion mode: the poses and what the designer chose for their count. */
export interface SynMotionState {
  /**
   * 2 to 20 poses; their count chooses the method (two-position rocker, three positions, Burmester curves, points,
   * least squares for 6 or more).
   */
  poses: PoseDeg[];
  /** Three poses: which pivots are placed. */
  pivotChoice: PivotChoice;
  /** Three poses: A, B in pose 1's coupler frame (moving) or O2, O4 in the plane (fixed); length unit. */
  pivots: [Point, Point];
  /** Four poses: where the centre-point curve was clicked (plane, 0 to 2 points); each picks the curve's nearest dyad. */
  dyadPicks: Point[];
  /** Which result is shown: the four-bar of five poses, or the crank pivot of two (0-based). */
  choice: number;
  /** Two poses: ground length |O2 O4| (length unit); null: twice the rocker length. */
  groundLength: number | null;
  /** Two poses: quick-return time ratio Q (1 to MAX_TIME_RATIO). */
  timeRatio: number;
}

/** Fewest and most poses. */
export const MIN_POSES = 2;
export const MAX_POSES = 20;
/** Largest time ratio accepted (Q = 10 already needs a crank pivot angle of 147°). */
export const MAX_TIME_RATIO = 10;
/** Largest |coordinate| of a pose, pivot or pick (length unit): the canvas cannot show more spread than this. */
export const COORD_MAX = 1e9;
/** Largest index of a shown result (five poses give at most 6 four-bars, 6 to 20 poses at most 15). */
export const MAX_CHOICE = 14;

/**
 * Five poses of the coupler point of a crank-rocker (r = 10, 3, 9, 7 placed at O2 = (−5, −6), P at 5 and 34°)
 * at θ2 = 40°, 80°, …, 200°, rounded to 0.1 and 1°: the first three are the default, Add pose appends the next.
 */
export const DEFAULT_POSES_FIVE: readonly PoseDeg[] = [
  { x: -0.9, y: 0.6, angleDeg: 34 },
  { x: -2, y: 1.3, angleDeg: 26 },
  { x: -3.8, y: 0.8, angleDeg: 24 },
  { x: -5.4, y: -0.6, angleDeg: 27 },
  { x: -6.1, y: -2.3, angleDeg: 36 },
];

/**
 * The same crank-rocker's poses over its whole turn, θ2 = 40°, 80°, …, 360° (the first five are DEFAULT_POSES_FIVE,
 * rounded alike): Add pose appends them in order, so six to nine poses still have a four-bar that fits them closely.
 */
export const DEFAULT_POSES_TURN: readonly PoseDeg[] = [
  ...DEFAULT_POSES_FIVE,
  { x: -5.9, y: -3.6, angleDeg: 49 },
  { x: -4.9, y: -4, angleDeg: 60 },
  { x: -3.3, y: -3, angleDeg: 62 },
  { x: -1.5, y: -1, angleDeg: 50 },
];

/** Three of the crank-rocker's poses with its moving pivots (rounded): a defect-free crank-rocker from the start. */
export const DEFAULT_SYN_MOTION: SynMotionState = {
  poses: DEFAULT_POSES_FIVE.slice(0, 3),
  pivotChoice: 'moving',
  pivots: [
    { x: -4.1, y: -2.9 },
    { x: 4.9, y: -2.8 },
  ],
  dyadPicks: [],
  choice: 0,
  groundLength: null,
  timeRatio: 1,
};

/** Actions only the Motion mode's slice handles. */
export type SynMotionAction =
  | { type: 'setSynPoses'; poses: PoseDeg[] }
  | { type: 'setSynPose'; index: number; pose: PoseDeg }
  | { type: 'setSynPivotChoice'; choice: PivotChoice; pivots: [Point, Point] }
  | { type: 'setSynPivot'; index: 0 | 1; point: Point }
  | { type: 'pickSynDyad'; center: Point }
  | { type: 'clearSynDyads' }
  | { type: 'setSynChoice'; choice: number }
  | { type: 'setSynGround'; length: number | null }
  | { type: 'setSynTimeRatio'; ratio: number };

const samePose = (a: PoseDeg, b: PoseDeg) => a.x === b.x && a.y === b.y && a.angleDeg === b.angleDeg;

/**
 * The Motion slice's reducer: pure, returns the same object when nothing changes. A new count of poses starts its
 * method afresh (no picks, the first result); a third pick replaces the older of two; angles are kept in (−180, 180].
 */
export function synMotionReducer(s: SynMotionState, action: Action): SynMotionState {
  switch (action.type) {
    case 'setSynPoses': {
      const poses = action.poses.map((p) => ({ ...p, angleDeg: wrapDeg180(p.angleDeg) }));
      if (poses.length === s.poses.length && poses.every((p, i) => samePose(p, s.poses[i]))) return s;
      return poses.length === s.poses.length ? { ...s, poses } : { ...s, poses, dyadPicks: [], choice: 0 };
    }
    case 'setSynPose': {
      const pose = { ...action.pose, angleDeg: wrapDeg180(action.pose.angleDeg) };
      if (!(action.index >= 0 && action.index < s.poses.length) || samePose(pose, s.poses[action.index])) return s;
      return { ...s, poses: s.poses.map((p, i) => (i === action.index ? pose : p)) };
    }
    case 'setSynPivotChoice':
      return { ...s, pivotChoice: action.choice, pivots: action.pivots };
    case 'setSynPivot':
      return { ...s, pivots: action.index === 0 ? [action.point, s.pivots[1]] : [s.pivots[0], action.point] };
    case 'pickSynDyad':
      return { ...s, dyadPicks: [...s.dyadPicks, action.center].slice(-2) };
    case 'clearSynDyads':
      return s.dyadPicks.length ? { ...s, dyadPicks: [] } : s;
    case 'setSynChoice':
      return action.choice === s.choice ? s : { ...s, choice: action.choice };
    case 'setSynGround':
      return action.length === s.groundLength ? s : { ...s, groundLength: action.length };
    case 'setSynTimeRatio':
      return action.ratio === s.timeRatio ? s : { ...s, timeRatio: action.ratio };
    default:
      return s;
  }
}

/** Significant digits of a length in the URL: 10 keep a typed value and drop a drag's float noise. */
const URL_LENGTH_DIGITS = 10;

const lengthText = (v: number) => significantText(v, URL_LENGTH_DIGITS);
const angleText = (deg: number) =>
  fixedText(wrapDeg180(Number(fixedText(deg, URL_ANGLE_DECIMALS))), URL_ANGLE_DECIMALS);

/**
 * The numbers of "a,b,c" (decimal text, as parseDecimal reads it), exactly count of them, each finite with
 * |v| ≤ max; or why not, naming the item (`pose 2`).
 */
export function decimalTuple(text: string, count: number, item: string, max: number): Decoded<number[]> {
  const parts = text.split(',');
  if (parts.length !== count) {
    return { ok: false, why: `${item} must be ${count} comma-separated numbers, got ${parts.length}` };
  }
  const values = parts.map(parseDecimal);
  const bad = values.findIndex((v) => !Number.isFinite(v));
  if (bad >= 0) return { ok: false, why: `${item}: ${JSON.stringify(parts[bad].trim())} is not a number` };
  if (values.some((v) => Math.abs(v) > max)) return { ok: false, why: `${item}: a value is beyond ±${max}` };
  return { ok: true, value: values.map((v) => (v === 0 ? 0 : v)) };
}

/** A ;-separated list of min to max items, each parsed by item (1-based index); "none" is the empty list. */
function listOf<T>(
  min: number,
  max: number,
  what: string,
  item: (text: string, index: number) => Decoded<T>,
  format: (value: T) => string,
): Codec<T[]> {
  return {
    parse(raw) {
      const s = raw.trim();
      const parts = s === '' || s.toLowerCase() === 'none' ? [] : s.split(';');
      if (parts.length < min || parts.length > max) {
        return { ok: false, why: `expected ${min} to ${max} ${what} separated by ;, got ${parts.length}` };
      }
      const out: T[] = [];
      for (let i = 0; i < parts.length; i++) {
        const r = item(parts[i], i + 1);
        if (!r.ok) return r;
        out.push(r.value);
      }
      return { ok: true, value: out };
    },
    format: (list) => (list.length ? list.map(format).join(';') : 'none'),
  };
}

const pointText = (p: Point) => `${lengthText(p.x)},${lengthText(p.y)}`;
const pointItem =
  (name: string) =>
  (text: string, i: number): Decoded<Point> => {
    const r = decimalTuple(text, 2, `${name} ${i}`, COORD_MAX);
    return r.ok ? { ok: true, value: { x: r.value[0], y: r.value[1] } } : r;
  };

/** Poses as x,y,deg;x,y,deg;… (2 to 20; lengths to 10 significant digits, angles to 1e-9° in (−180, 180]). */
export const posesCodec: Codec<PoseDeg[]> = listOf(
  MIN_POSES,
  MAX_POSES,
  'poses x,y,deg',
  (text, i) => {
    const r = decimalTuple(text, 3, `pose ${i}`, COORD_MAX);
    if (!r.ok) return r;
    return { ok: true, value: { x: r.value[0], y: r.value[1], angleDeg: Number(angleText(r.value[2])) } };
  },
  (p) => `${pointText(p)},${angleText(p.angleDeg)}`,
);

/** Two pivots as x,y;x,y. */
export const pivotsCodec: Codec<[Point, Point]> = listOf(2, 2, 'pivots x,y', pointItem('pivot'), pointText) as Codec<
  [Point, Point]
>;

/** Up to two picks on the centre-point curve as x,y;x,y, or none. */
export const picksCodec: Codec<Point[]> = listOf(0, 2, 'picks x,y', pointItem('pick'), pointText);

/** A whole number from 0 to MAX_CHOICE. */
const choiceCodec: Codec<number> = {
  parse(raw) {
    const s = raw.trim();
    return /^\d{1,2}$/.test(s) && Number(s) <= MAX_CHOICE
      ? { ok: true, value: Number(s) }
      : { ok: false, why: `expected a whole number from 0 to ${MAX_CHOICE}` };
  },
  format: (v) => String(v),
};

/** A positive length, or auto (null). */
const groundCodec: Codec<number | null> = {
  parse(raw) {
    if (raw.trim() === 'auto') return { ok: true, value: null };
    const v = parseDecimal(raw);
    return v > 0 && v <= COORD_MAX
      ? { ok: true, value: Number(lengthText(v)) }
      : { ok: false, why: `expected auto or a length above 0 and at most ${COORD_MAX}` };
  },
  format: (v) => (v === null ? 'auto' : lengthText(v)),
};

/** The time ratio Q, 1 to MAX_TIME_RATIO. */
const ratioCodec: Codec<number> = {
  parse(raw) {
    const v = parseDecimal(raw);
    return v >= 1 && v <= MAX_TIME_RATIO
      ? { ok: true, value: Number(significantText(v, URL_LENGTH_DIGITS)) }
      : { ok: false, why: `expected a time ratio from 1 to ${MAX_TIME_RATIO}` };
  },
  format: (v) => significantText(v, URL_LENGTH_DIGITS),
};

const field = sliceLens('synMotion');

/** The Motion mode's URL keys, each written when it differs from the default: ps, pc, pv, dy, mc, mg, mq. */
export const SYN_MOTION_URL_KEYS: readonly UrlKey<unknown>[] = [
  optionalKey('ps', posesCodec, field('poses'), DEFAULT_SYN_MOTION.poses),
  optionalKey(
    'pc',
    enumCodec(sameText(['moving', 'fixed'] as const)),
    field('pivotChoice'),
    DEFAULT_SYN_MOTION.pivotChoice,
  ),
  optionalKey('pv', pivotsCodec, field('pivots'), DEFAULT_SYN_MOTION.pivots),
  optionalKey('dy', picksCodec, field('dyadPicks'), DEFAULT_SYN_MOTION.dyadPicks),
  optionalKey('mc', choiceCodec, field('choice'), DEFAULT_SYN_MOTION.choice),
  optionalKey('mg', groundCodec, field('groundLength'), DEFAULT_SYN_MOTION.groundLength),
  optionalKey('mq', ratioCodec, field('timeRatio'), DEFAULT_SYN_MOTION.timeRatio),
];

/** The synMotion slice's registration in SLICES (appState.ts). */
export const SYN_MOTION_SLICE: Slice<SynMotionState, SynMotionAction> = {
  summary: "the synthesis page's Motion mode: poses and the pivots or dyads chosen",
  defaults: DEFAULT_SYN_MOTION,
  reducer: synMotionReducer,
  urlKeys: SYN_MOTION_URL_KEYS,
};
