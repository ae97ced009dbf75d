import { useState } from 'react';
import { useAnimationFrame } from '../../shared/hooks/useAnimationFrame';
import { PI, TWO_PI } from '../../solver/angles';
import type { Playhead, PlayheadSource } from './livePlayhead';

/** Where the input rests and how Play moves it (Play's playhead itself is in the page's PlayheadSource). */
export interface MechDrive {
  /** The committed input: radians for a pin, length for a slider; 0 = as drawn. */
  input: number;
  playing: boolean;
  direction: 1 | -1;
  /** Degrees per second for a pin; for a slider, 1/360 of the range per second per unit. */
  speed: number;
  /** The input at which Play last reversed at a limit, or null. */
  limitAt: number | null;
}

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

/** The committed drive (the mech slice's input, direction and speed) and how to change it. */
export interface CommittedDrive {
  input: number;
  direction: 1 | -1;
  speed: number;
}

/**
 * The input and Play of the mechanism page. At rest the input, direction and speed are the slice's (committed):
 * Step, the slider and Reverse commit to it, so a link or a design file holds them. While playing, one
 * animation-frame loop (useAnimationFrame) moves the playhead in `playhead` (a source the views that follow Play read),
 * so a frame of Play re-renders neither the app nor the page: the page re-renders only when Play starts or stops, turns
 * at a limit or is reversed. Pause commits where it stopped. rate converts speed to input units per second.
 */
export function useMechDrive(
  range: [number, number] | null,
  fullTurn: boolean,
  rate: (speed: number) => number,
  committed: CommittedDrive,
  commit: (patch: Partial<CommittedDrive>) => void,
  playhead: PlayheadSource,
) {
  // The playhead's direction and limit as the page shows them (Reverse's state, the status line): they change at a
  // turn, not every frame.
  const [shown, setShown] = useState<{ direction: 1 | -1; limitAt: number | null } | null>(null);
  const canRun = range !== null;
  const playing = shown !== null;
  const move = (next: Playhead | null) => {
    playhead.set(next);
    setShown(next && { direction: next.direction, limitAt: next.limitAt });
  };
  useAnimationFrame(playing && canRun, (dt) => {
    const p = playhead.get();
    if (!range || !p) return;
    const { next, turned } = playFrame(p, rate(committed.speed) * dt, range, fullTurn);
    if (turned) move(next);
    else playhead.set(next);
  });
  const drive: MechDrive = shown
    ? { input: committed.input, ...shown, playing: true, speed: committed.speed }
    : { input: committed.input, direction: committed.direction, speed: committed.speed, playing: false, limitAt: null };
  const from = () => playhead.get() ?? committed;
  return {
    drive,
    setPlaying: (on: boolean) => {
      if (on === (playhead.get() !== null)) return;
      if (on) move({ input: committed.input, direction: committed.direction, limitAt: null });
      else {
        const p = from();
        commit({ input: p.input, direction: p.direction });
        move(null);
      }
    },
    step: (delta: number) => {
      if (!range) return;
      const p = from();
      const s = advanceInput(p.input, p.direction, delta, range, fullTurn);
      commit({ input: s.input, direction: s.direction });
      move(null);
    },
    setInput: (input: number) => {
      const p = playhead.get();
      if (p) move({ ...p, input, limitAt: null });
      else commit({ input });
    },
    reverse: () => {
      const p = playhead.get();
      const direction = (p ?? committed).direction === 1 ? -1 : 1;
      if (p) move({ ...p, direction });
      else commit({ direction });
    },
    setSpeed: (speed: number) => commit({ speed }),
    stop: (input = 0) => {
      move(null);
      commit({ input });
    },
  };
}
