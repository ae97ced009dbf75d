import type { Radians } from '../../../solver/angles';
import { degToRad, wrapDeg360 } from '../../../solver/angles';
import type { Branch } from '../../../solver/types';
import type { InputRangeDeg } from '../../../shared/state/animation';
import { LIMIT_INSET_DEG, advanceTheta2, inputTurnsFully } from '../../../shared/state/animation';
import type { Direction } from '../../../shared/state/appState';
import { NOMINAL_FPS } from '../../../shared/state/appState';

// The bounds live in their own module so the Export panel can show them without loading the planner.
import { FRAMES_PER_CYCLE_MAX, FRAMES_PER_CYCLE_MIN } from './framesPerCycle';
export { FRAMES_PER_CYCLE_DEFAULT, FRAMES_PER_CYCLE_MAX, FRAMES_PER_CYCLE_MIN } from './framesPerCycle';

/** One frame of an exported animation: the input angle (radians, [0, 2π)) and the assembly branch to draw. */
export interface AnimationFrame {
  theta2Rad: Radians;
  branch: Branch;
}

/**
 * What one cycle is: a full turn of the input, the rocking input's out-and-back between its limits, a single
 * still frame (an input range of zero width), or nothing (the linkage assembles at no input angle).
 */
export type CycleKind = 'full-turn' | 'rocking' | 'still' | 'none';

/** The frames of one cycle, in playing order, without repeating the first frame at the end. */
export interface FramePlan {
  kind: CycleKind;
  frames: AnimationFrame[];
  /** Degrees the input travels in one cycle: 360 for a full turn, twice the interval's width when rocking. */
  travelDeg: number;
}

/** Where the animation starts: the app's input angle (degrees), direction and branch, and the input's range. */
export interface FramePlanInput {
  theta2Deg: number;
  direction: Direction;
  branch: Branch;
  /** The input's reachable range in degrees (rangeToDeg of the solver's classification). */
  range: InputRangeDeg;
  /** Frames in one cycle, an integer from FRAMES_PER_CYCLE_MIN to FRAMES_PER_CYCLE_MAX. */
  framesPerCycle: number;
}

/** The interval (inset from its limits as Play insets it) holding theta (degrees), as lo <= t <= hi; null if none. */
function holdingIntervalWidthDeg(thetaDeg: number, range: InputRangeDeg): number | null {
  for (const iv of range.intervals) {
    const width = iv.hi - iv.lo;
    const lo = width <= 2 * LIMIT_INSET_DEG ? (iv.lo + iv.hi) / 2 : iv.lo + LIMIT_INSET_DEG;
    const hi = width <= 2 * LIMIT_INSET_DEG ? lo : iv.hi - LIMIT_INSET_DEG;
    const t = thetaDeg + 360 * Math.ceil((lo - thetaDeg) / 360);
    // A tolerance of a few ulps of 360: the start comes from advanceTheta2, which wrapped it into [0, 360).
    if (t <= hi + 1e-9) return hi - lo;
  }
  return null;
}

/**
 * The frames of one cycle of the app's Play motion from its current state. A full-turn input turns through
 * 360° in the animation's direction; a rocking input goes out to one limit, reverses there and switches
 * branch (as advanceTheta2 does in Play), goes back to the other limit, switches again and returns to the
 * start. Frame k is advanceTheta2 of the start by k · travel / framesPerCycle, so the cycle closes on itself
 * and its motion is Play's. Throws when framesPerCycle is not an integer from 36 to 720.
 */
export function planAnimationFrames(input: FramePlanInput): FramePlan {
  const n = input.framesPerCycle;
  if (!Number.isInteger(n) || n < FRAMES_PER_CYCLE_MIN || n > FRAMES_PER_CYCLE_MAX) {
    throw new Error(
      `framesPerCycle must be an integer from ${FRAMES_PER_CYCLE_MIN} to ${FRAMES_PER_CYCLE_MAX}, got ${n}`,
    );
  }
  if (!Number.isFinite(input.theta2Deg)) throw new Error(`theta2Deg must be a finite angle, got ${input.theta2Deg}`);
  const { range } = input;
  if (inputTurnsFully(range)) {
    const stepDeg = 360 / n;
    const frames = Array.from({ length: n }, (_, k) => ({
      theta2Rad: degToRad(wrapDeg360(input.theta2Deg + input.direction * k * stepDeg)),
      branch: input.branch,
    }));
    return { kind: 'full-turn', frames, travelDeg: 360 };
  }
  if (range.intervals.length === 0) return { kind: 'none', frames: [], travelDeg: 0 };
  // Play first moves an unreachable angle to the nearest limit; start from where Play would be.
  const start = advanceTheta2(input.theta2Deg, 0, input.direction, input.branch, range);
  const widthDeg = holdingIntervalWidthDeg(start.theta2Deg, range) ?? 0;
  if (!(widthDeg > 0)) {
    return { kind: 'still', frames: [{ theta2Rad: degToRad(start.theta2Deg), branch: start.branch }], travelDeg: 0 };
  }
  const travelDeg = 2 * widthDeg;
  const stepDeg = travelDeg / n;
  const frames = Array.from({ length: n }, (_, k) => {
    const s = advanceTheta2(start.theta2Deg, k * stepDeg, start.direction, start.branch, range);
    return { theta2Rad: degToRad(s.theta2Deg), branch: s.branch };
  });
  return { kind: 'rocking', frames, travelDeg };
}

/**
 * Frames per second that make the exported cycle last as long as one cycle of Play at speedDegPerFrame
 * (degrees per nominal 60 FPS frame). Returns 0 for a plan that does not move.
 */
export function playbackFps(plan: FramePlan, speedDegPerFrame: number): number {
  if (plan.travelDeg <= 0 || !(speedDegPerFrame > 0)) return 0;
  const cycleSeconds = plan.travelDeg / (speedDegPerFrame * NOMINAL_FPS);
  return plan.frames.length / cycleSeconds;
}
