import { PI, TWO_PI } from '../../solver/angles';
import type { Playhead } from './livePlayhead';

/** What moves an input within a range, one step or one frame: the next input, direction and the limit met. */
export interface DriveStep {
  input: number;
  direction: 1 | -1;
  limitAt: number | null;
}

/**
 * Advances the input by delta in its direction within [lo, hi]: wrapping into [−π, π) when the input turns fully,
 * else reversing at an end (the linkage cannot go on: it rocks) and reporting where: a step that would pass the end
 * lands on it, and a step from the end (or beyond it) goes back by delta.
 */
export function advanceInput(
  input: number,
  direction: 1 | -1,
  delta: number,
  range: [number, number],
  fullTurn: boolean,
): DriveStep {
  let next = input + direction * delta;
  if (fullTurn) {
    next = ((((next + PI) % TWO_PI) + TWO_PI) % TWO_PI) - PI;
    return { input: next, direction, limitAt: null };
  }
  const [lo, hi] = range;
  // From inside, a step that would pass an end stops on it (the limit's pose is shown); from the end itself it
  // turns back at once, so no frame or Step is spent standing at the limit.
  if (next > hi) return input < hi ? { input: hi, direction: -1, limitAt: hi } : turnBack(hi, -1, delta, range);
  if (next < lo) return input > lo ? { input: lo, direction: 1, limitAt: lo } : turnBack(lo, 1, delta, range);
  return { input: next, direction, limitAt: null };
}

/** From the end `at` of [lo, hi], delta the other way (within the range), reporting the limit met. */
function turnBack(at: number, direction: 1 | -1, delta: number, [lo, hi]: [number, number]): DriveStep {
  return { input: Math.min(hi, Math.max(lo, at + direction * delta)), direction, limitAt: at };
}

/**
 * One frame of Play: the playhead moved by delta (advanceInput), keeping the last limit met, and whether it turned
 * (a new direction or a new limit: what the page shows changes; else only the views that follow the playhead redraw).
 */
export function playFrame(
  p: Playhead,
  delta: number,
  range: [number, number],
  fullTurn: boolean,
): { next: Playhead; turned: boolean } {
  const s = advanceInput(p.input, p.direction, delta, range, fullTurn);
  const next = { ...s, limitAt: s.limitAt ?? p.limitAt };
  return { next, turned: next.direction !== p.direction || next.limitAt !== p.limitAt };
}
