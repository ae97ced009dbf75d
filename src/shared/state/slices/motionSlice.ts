import { enumCodec, boolCodec, numberCodec } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { optionalKey, sliceLens, urlKey } from '../../url/urlKey';
import { URL_ANGLE_DECIMALS } from '../../url/urlPrecision';
import { wrapDeg360 } from '../../../solver/angles';
import type { Action } from '../appState';
import type { Slice } from '../slice';
import type { OmegaUnit } from '../inputMotion';

/** Direction of the animated input: +1 counter-clockwise (theta2 increasing), -1 clockwise. */
export type Direction = 1 | -1;

/** The motion slice: where the crank is, how it is played, and the input motion of the rate analysis. */
export interface MotionState {
  /** Input angle in degrees, kept in [0, 360). */
  theta2Deg: number;
  playing: boolean;
  /** Animation speed in degrees per frame at a nominal 60 frames per second (0.5 to 10). */
  speedDegPerFrame: number;
  direction: Direction;
  /** Input crank angular velocity for the rate analysis, rad/s, counter-clockwise positive (default 10). */
  omega2RadPerS: number;
  /** Input crank angular acceleration for the rate analysis, rad/s², counter-clockwise positive (default 0). */
  alpha2RadPerS2: number;
  /** The unit the ω2 control shows (the state keeps rad/s in omega2RadPerS); default 'rad/s'. */
  omegaUnit: OmegaUnit;
}

/** Actions only the motion slice handles. */
export type MotionAction =
  | { type: 'setTheta2'; deg: number }
  | { type: 'setPlaying'; playing: boolean }
  | { type: 'setSpeed'; degPerFrame: number }
  | { type: 'setDirection'; direction: Direction }
  | { type: 'setInputMotion'; omega2RadPerS?: number; alpha2RadPerS2?: number }
  | { type: 'setOmegaUnit'; unit: OmegaUnit };

/** Nominal frame rate (frames per second) that converts degrees per frame into degrees per second. */
export const NOMINAL_FPS = 60;

/** Slowest and fastest animation speeds, degrees per frame. */
export const SPEED_MIN = 0.5;
export const SPEED_MAX = 10;
/** Step of the speed slider, degrees per frame: fine enough that typed speeds such as 0.75 sit on it. */
export const SPEED_STEP = 0.05;

/** theta2 = 45 deg, paused, 1 deg per frame counter-clockwise; input motion 10 rad/s without acceleration, shown in rad/s. */
export const DEFAULT_MOTION: MotionState = {
  theta2Deg: 45,
  playing: false,
  speedDegPerFrame: 1,
  direction: 1,
  omega2RadPerS: 10,
  alpha2RadPerS2: 0,
  omegaUnit: 'rad/s',
};

/** Wraps degrees into [0, 360); non-finite input gives 0. Kept as the state's name for the units module's wrap. */
export const normalizeTheta2Deg = wrapDeg360;

/** Clamps x into [lo, hi]. */
export function clamp(x: number, lo: number, hi: number): number {
  return Math.min(hi, Math.max(lo, x));
}

function withTheta2(s: MotionState, theta2Deg: number): MotionState {
  const deg = normalizeTheta2Deg(theta2Deg);
  return deg === s.theta2Deg ? s : { ...s, theta2Deg: deg };
}

/** The motion slice's reducer: pure, returns the same object when nothing changes. */
export function motionReducer(s: MotionState, action: Action): MotionState {
  switch (action.type) {
    case 'setTheta2':
    case 'applyPreset':
      return withTheta2(s, action.type === 'setTheta2' ? action.deg : action.theta2Deg);
    case 'setPlaying':
      return action.playing === s.playing ? s : { ...s, playing: action.playing };
    case 'setSpeed':
      return { ...s, speedDegPerFrame: clamp(action.degPerFrame, SPEED_MIN, SPEED_MAX) };
    case 'setDirection':
      return { ...s, direction: action.direction };
    case 'animate': {
      const next = withTheta2(s, action.theta2Deg);
      return action.direction === s.direction ? next : { ...next, direction: action.direction };
    }
    case 'setInputMotion': {
      const omega2RadPerS = action.omega2RadPerS ?? s.omega2RadPerS;
      const alpha2RadPerS2 = action.alpha2RadPerS2 ?? s.alpha2RadPerS2;
      if (omega2RadPerS === s.omega2RadPerS && alpha2RadPerS2 === s.alpha2RadPerS2) return s;
      return { ...s, omega2RadPerS, alpha2RadPerS2 };
    }
    case 'setOmegaUnit':
      return action.unit === s.omegaUnit ? s : { ...s, omegaUnit: action.unit };
    default:
      return s;
  }
}

const field = sliceLens('motion');
const angle360 = numberCodec('theta2', { decimals: URL_ANGLE_DECIMALS, normalize: normalizeTheta2Deg });

/** The motion's URL keys: t2, play, spd, dir, and w2, a2 and the ω2 unit w2u (rad, rpm, deg) when not the defaults. */
export const MOTION_URL_KEYS: readonly UrlKey<unknown>[] = [
  urlKey('t2', angle360, field('theta2Deg')),
  urlKey('play', boolCodec, field('playing')),
  urlKey('spd', numberCodec('speed'), field('speedDegPerFrame')),
  urlKey(
    'dir',
    enumCodec([
      ['ccw', 1],
      ['cw', -1],
    ] as const),
    field('direction'),
  ),
  optionalKey('w2', numberCodec('omega2'), field('omega2RadPerS'), DEFAULT_MOTION.omega2RadPerS),
  optionalKey('a2', numberCodec('alpha2'), field('alpha2RadPerS2'), DEFAULT_MOTION.alpha2RadPerS2),
  optionalKey(
    'w2u',
    enumCodec([
      ['rad', 'rad/s'],
      ['rpm', 'rpm'],
      ['deg', 'deg/s'],
    ] as const),
    field('omegaUnit'),
    DEFAULT_MOTION.omegaUnit,
  ),
];

/** The motion slice's registration in SLICES (appState.ts). */
export const MOTION_SLICE: Slice<MotionState, MotionAction> = {
  summary: 'where the crank is, how it plays, and the input motion of the rate analysis',
  defaults: DEFAULT_MOTION,
  reducer: motionReducer,
  urlKeys: MOTION_URL_KEYS,
};
