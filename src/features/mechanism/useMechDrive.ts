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

/** Default Play speed: 60 °/s (a turn in 6 s). */
export const DEFAULT_MECH_SPEED = 60;

/**
 * The input and Play of the mechanism page: one animation-frame loop while playing (useAnimationFrame), Step, a
 * set input (clamped by the caller), direction and speed. rate converts speed to input units per second.
 */
export function useMechDrive(range: [number, number] | null, fullTurn: boolean, rate: (speed: number) => number) {
  const [drive, setDrive] = useState<MechDrive>({
    input: 0,
    playing: false,
    direction: 1,
    speed: DEFAULT_MECH_SPEED,
    limitAt: null,
  });
  const canRun = range !== null;
  useAnimationFrame(drive.playing && canRun, (dt) => {
    if (!range) return;
    setDrive((d) => {
      const s = advanceInput(d.input, d.direction, rate(d.speed) * dt, range, fullTurn);
      return { ...d, ...s, limitAt: s.limitAt ?? d.limitAt };
    });
  });
  return {
    drive,
    setPlaying: (playing: boolean) => setDrive((d) => ({ ...d, playing, limitAt: playing ? d.limitAt : null })),
    step: (delta: number) =>
      setDrive((d) => {
        if (!range) return d;
        const s = advanceInput(d.input, d.direction, delta, range, fullTurn);
        return { ...d, ...s, playing: false };
      }),
    setInput: (input: number) => setDrive((d) => ({ ...d, input, limitAt: null })),
    reverse: () => setDrive((d) => ({ ...d, direction: d.direction === 1 ? -1 : 1 })),
    setSpeed: (speed: number) => setDrive((d) => ({ ...d, speed })),
    stop: (input = 0) => setDrive((d) => ({ ...d, input, playing: false, limitAt: null })),
  };
}
