import { radToDeg } from '../../solver/angles';
import type { AngleInterval, Branch } from '../../solver/types';
import type { Direction } from './appState';
import type { PlayFrame } from './playhead';
import { NOMINAL_FPS, normalizeTheta2Deg } from './appState';

/** The next animation state: input angle in degrees [0, 360), direction and branch. */
export interface AnimationStep {
  theta2Deg: number;
  direction: Direction;
  branch: Branch;
}

/** Where the input may go, in degrees: a full turn, or closed intervals lo <= hi (hi may pass 180). */
export interface InputRangeDeg {
  full: boolean;
  intervals: AngleInterval[];
}

/** Inset from an input limit, degrees: the limit itself can be unreachable by an ulp of the classification. */
export const LIMIT_INSET_DEG = 1e-6;

/** Converts the solver's input range (radians) to degrees. */
export function rangeToDeg(range: { full: boolean; intervals: readonly AngleInterval[] }): InputRangeDeg {
  return {
    full: range.full,
    intervals: range.intervals.map((iv) => ({ lo: radToDeg(iv.lo), hi: radToDeg(iv.hi) })),
  };
}

/**
 * Whether the input is a full-turn crank: it turns through every angle (Grashof with the input shortest or
 * the ground shortest, and every change point whose classification says so: parallelograms, kites on their
 * crank). The only place the UI decides it; the solver's classification is the source (inputRange.full).
 */
export function inputTurnsFully(range: { full: boolean }): boolean {
  return range.full;
}

/** Whether the linkage assembles at some input angle (a full turn, or at least one interval). */
export function assemblesAnywhere(range: { full: boolean; intervals: readonly unknown[] }): boolean {
  return range.full || range.intervals.length > 0;
}

/** Whether the animation rocks: the input is limited and can move at all (a linkage that never assembles stays). */
export function isRocking(range: { full: boolean; intervals: readonly unknown[] }): boolean {
  return !inputTurnsFully(range) && range.intervals.length > 0;
}

/** Degrees the input turns in dtSeconds at speedDegPerFrame (time based: frames are nominal 60 FPS ones). */
export function degreesForElapsed(speedDegPerFrame: number, dtSeconds: number): number {
  return speedDegPerFrame * NOMINAL_FPS * Math.max(0, dtSeconds);
}

function inset(iv: AngleInterval): AngleInterval {
  const e = LIMIT_INSET_DEG;
  if (iv.hi - iv.lo <= 2 * e) {
    const m = (iv.lo + iv.hi) / 2;
    return { lo: m, hi: m };
  }
  return { lo: iv.lo + e, hi: iv.hi - e };
}

/** The representative of theta (degrees) inside iv, shifting by whole turns; null when it is not inside. */
function inInterval(theta: number, iv: AngleInterval): number | null {
  const k = Math.ceil((iv.lo - theta) / 360);
  const t = theta + 360 * k;
  return t <= iv.hi ? t : null;
}

function angularGap(a: number, b: number): number {
  const d = Math.abs(normalizeTheta2Deg(a) - normalizeTheta2Deg(b));
  return Math.min(d, 360 - d);
}

/**
 * Advances the input by deltaDeg (>= 0) in direction. A full-turn input wraps; a limited input rocks:
 * at a limit it reverses and switches branch, as the real linkage does (the limit is where the coupler
 * and rocker are collinear, the boundary between the branches). Outside every interval it jumps to
 * the nearest limit. With no interval at all it stays where it is.
 */
export function advanceTheta2(
  theta2Deg: number,
  deltaDeg: number,
  direction: Direction,
  branch: Branch,
  range: InputRangeDeg,
): AnimationStep {
  if (range.full) {
    return { theta2Deg: normalizeTheta2Deg(theta2Deg + direction * deltaDeg), direction, branch };
  }
  if (range.intervals.length === 0) return { theta2Deg: normalizeTheta2Deg(theta2Deg), direction, branch };
  const intervals = range.intervals.map(inset);
  let current: AngleInterval | null = null;
  let t = 0;
  for (const iv of intervals) {
    const r = inInterval(theta2Deg, iv);
    if (r !== null) {
      current = iv;
      t = r;
      break;
    }
  }
  if (!current) {
    let best = intervals[0];
    let bestT = best.lo;
    let bestGap = Infinity;
    for (const iv of intervals) {
      for (const end of [iv.lo, iv.hi]) {
        const g = angularGap(theta2Deg, end);
        if (g < bestGap) {
          bestGap = g;
          best = iv;
          bestT = end;
        }
      }
    }
    current = best;
    t = bestT;
  }
  let dir = direction;
  let br = branch;
  let next = t + dir * deltaDeg;
  const width = current.hi - current.lo;
  // Reflect at the limits; a step longer than the interval folds several times.
  for (let guard = 0; guard < 8 && (next > current.hi || next < current.lo); guard++) {
    if (next > current.hi) next = current.hi - (next - current.hi);
    else next = current.lo + (current.lo - next);
    dir = (dir === 1 ? -1 : 1) as Direction;
    br = br === 'open' ? 'crossed' : 'open';
    if (width === 0) break;
  }
  next = Math.min(current.hi, Math.max(current.lo, next));
  return { theta2Deg: normalizeTheta2Deg(next), direction: dir, branch: br };
}

/** The state a Step button reads: input angle, samples per turn (one step is 360 / samples degrees), direction, branch. */
export interface StepState extends PlayFrame {
  samples: number;
}

/** How far a fraction of a step may be off the grid and still count as on it (float noise of Play and the URL). */
const ON_GRID = 1e-7;

/**
 * Degrees from theta2Deg to the next multiple of stepDeg in direction moving: a whole step from a grid point,
 * less from between two (Play and a drag leave θ2 anywhere, and Step then lands on round values again).
 */
export function stepToGrid(theta2Deg: number, stepDeg: number, moving: Direction): number {
  const k = theta2Deg / stepDeg;
  const nearest = Math.round(k);
  if (Math.abs(k - nearest) < ON_GRID) return stepDeg;
  const target = moving === 1 ? Math.ceil(k) : Math.floor(k);
  return Math.abs(target - k) * stepDeg;
}

/**
 * One press of Step forward (sign +1) or Step back (-1) along the animation's direction (Clockwise steps forward
 * to smaller angles), or against it. A full-turn input goes to the next multiple of 360 / samples degrees (a
 * whole step from a grid point); a rocking input goes a whole step, reverses at a limit and switches branch as in
 * Play, and the direction follows, so Step back undoes Step forward. A null range (the cycle is not solved yet)
 * steps as a full turn.
 */
export function stepTheta2(state: StepState, range: InputRangeDeg | null, sign: 1 | -1): AnimationStep {
  const moving = (sign * state.direction) as Direction;
  const step = 360 / state.samples;
  const r = range ?? { full: true, intervals: [] };
  // A rocking input reflects at its limits, off any grid: it steps whole steps, so that Step back undoes Step forward.
  const delta = r.full ? stepToGrid(state.theta2Deg, step, moving) : step;
  const next = advanceTheta2(state.theta2Deg, delta, moving, state.branch, r);
  // On a full turn the result is a grid point: write it as one, so steps never collect rounding.
  const theta2Deg = r.full ? normalizeTheta2Deg(Math.round(next.theta2Deg / step) * step) : next.theta2Deg;
  return { theta2Deg, branch: next.branch, direction: (sign * next.direction) as Direction };
}
