import { useRef, useState } from 'react';
import { useAnimationFrame } from '../../shared/hooks/useAnimationFrame';
import type { Playhead, PlayheadSource } from './livePlayhead';
import { advanceInput, playFrame } from './mechDriveStep';
import type { MechLiveStage } from './stage/mechLiveStage';
import type { MechDriveRun } from './stage/mechStageProtocol';

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

/** The committed drive (the mech slice's input, direction and speed) and how to change it. */
export interface CommittedDrive {
  input: number;
  direction: 1 | -1;
  speed: number;
}

/** Whether two drives move the input alike (the same rate, run and wrapping). */
function sameDrive(a: MechDriveRun, b: MechDriveRun): boolean {
  return (
    a.ratePerS === b.ratePerS && a.range[0] === b.range[0] && a.range[1] === b.range[1] && a.fullTurn === b.fullTurn
  );
}

/**
 * The input and Play of the mechanism page. At rest the input, direction and speed are the slice's (committed):
 * Step, the slider and Reverse commit to it, so a link or a design file holds them. While playing, one
 * animation-frame loop (useAnimationFrame) moves the playhead in `playhead` (a source the views that follow Play read),
 * so a frame of Play re-renders neither the app nor the page: the page re-renders only when Play starts or stops, turns
 * at a limit or is reversed. Pause commits where it stopped. rate converts speed to input units per second.
 * With a live stage (Play drawn in a worker on its own clock) the playhead follows the stage's newest frame; the page
 * advances it itself only until the stage has drawn one (or where the stage failed), and re-bases the stage on a
 * playhead someone else set (the slider, Reverse) or a new speed or run. Pause keeps the stage's newest frame.
 */
export function useMechDrive(
  range: [number, number] | null,
  fullTurn: boolean,
  rate: (speed: number) => number,
  committed: CommittedDrive,
  commit: (patch: Partial<CommittedDrive>) => void,
  playhead: PlayheadSource,
  stage: MechLiveStage | null = null,
) {
  // The playhead's direction and limit as the page shows them (Reverse's state, the status line): they change at a
  // turn, not every frame.
  const [shown, setShown] = useState<{ direction: 1 | -1; limitAt: number | null } | null>(null);
  const canRun = range !== null;
  const playing = shown !== null;
  // What the stage plays and the playhead this loop set last (null: the stage is not playing).
  const staged = useRef<{ drive: MechDriveRun; set: Playhead } | null>(null);
  const move = (next: Playhead | null) => {
    if (!next && playhead.get()) {
      staged.current = null;
      stage?.stop();
    }
    playhead.set(next);
    setShown(next && { direction: next.direction, limitAt: next.limitAt });
  };
  useAnimationFrame(playing && canRun, (dt, now) => {
    const p = playhead.get();
    if (!range || !p) return;
    const drive: MechDriveRun = { ratePerS: rate(committed.speed), range, fullTurn };
    let next = playFrame(p, drive.ratePerS * dt, range, fullTurn).next;
    if (stage?.usable()) {
      const s = staged.current;
      if (!s || s.set !== p || !sameDrive(s.drive, drive)) stage.play(next, now, drive);
      else next = stage.latest() ?? next;
      staged.current = { drive, set: next };
    }
    if (next.direction !== p.direction || next.limitAt !== p.limitAt) move(next);
    else playhead.set(next);
  });
  const drive: MechDrive = shown
    ? { input: committed.input, ...shown, playing: true, speed: committed.speed }
    : { input: committed.input, direction: committed.direction, speed: committed.speed, playing: false, limitAt: null };
  /** Where the input is: the stage's newest frame while it plays what this loop set, else the playhead, else at rest. */
  const from = () => {
    const p = playhead.get();
    const drawn = p && staged.current?.set === p && stage?.usable() ? stage.latest() : null;
    return drawn ?? p ?? committed;
  };
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
