import { useState } from 'react';
import { useAnimationFrame } from '../../shared/hooks/useAnimationFrame';
import { PI, TWO_PI } from '../../solver/angles';

/** Where the input is and how Play moves it. */
export interface MechDrive {
  /** The input: radians for a pin, length for a slider; 0 = as drawn. */
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
 * else reversing at an end (the linkage cannot go on: it rocks) and reporting where.
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
  if (next > hi) return { input: hi, direction: -1, limitAt: hi };
  if (next < lo) return { input: lo, direction: 1, limitAt: lo };
  return { input: next, direction, limitAt: null };
}

/** The committed drive (the mech slice's input, direction and speed) and how to change it. */
export interface CommittedDrive {
  input: number;
  direction: 1 | -1;
  speed: number;
}

/** Where Play is while it runs (the frames stay in the page; the slice gets the input when Play stops). */
interface Playing {
  input: number;
  direction: 1 | -1;
  limitAt: number | null;
}

/**
 * The input and Play of the mechanism page. At rest the input, direction and speed are the slice's (committed):
 * Step, the slider and Reverse commit to it, so a link or a design file holds them. While playing, one
 * animation-frame loop (useAnimationFrame) moves a local input, so Play does not re-render the app every frame;
 * Pause commits where it stopped. rate converts speed to input units per second.
 */
export function useMechDrive(
  range: [number, number] | null,
  fullTurn: boolean,
  rate: (speed: number) => number,
  committed: CommittedDrive,
  commit: (patch: Partial<CommittedDrive>) => void,
) {
  const [play, setPlay] = useState<Playing | null>(null);
  const canRun = range !== null;
  useAnimationFrame(play !== null && canRun, (dt) => {
    if (!range) return;
    setPlay((p) => {
      if (!p) return p;
      const s = advanceInput(p.input, p.direction, rate(committed.speed) * dt, range, fullTurn);
      return { ...s, limitAt: s.limitAt ?? p.limitAt };
    });
  });
  const drive: MechDrive = play
    ? { ...play, playing: true, speed: committed.speed }
    : { input: committed.input, direction: committed.direction, speed: committed.speed, playing: false, limitAt: null };
  const from = play ?? committed;
  return {
    drive,
    setPlaying: (playing: boolean) => {
      if (playing === (play !== null)) return;
      if (playing) setPlay({ input: committed.input, direction: committed.direction, limitAt: null });
      else {
        commit({ input: from.input, direction: from.direction });
        setPlay(null);
      }
    },
    step: (delta: number) => {
      if (!range) return;
      const s = advanceInput(from.input, from.direction, delta, range, fullTurn);
      commit({ input: s.input, direction: s.direction });
      setPlay(null);
    },
    setInput: (input: number) => {
      if (play) setPlay({ ...play, input, limitAt: null });
      else commit({ input });
    },
    reverse: () => {
      const direction = from.direction === 1 ? -1 : 1;
      if (play) setPlay({ ...play, direction });
      else commit({ direction });
    },
    setSpeed: (speed: number) => commit({ speed }),
    stop: (input = 0) => {
      setPlay(null);
      commit({ input });
    },
  };
}
