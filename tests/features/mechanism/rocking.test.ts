import { describe, expect, it } from 'vitest';
import { MECHANISM_TEMPLATES } from '../../../src/mechanism';
import { degToRad } from '../../../src/solver/angles';
import { analyseMechanism, runRange } from '../../../src/features/mechanism/mechAnalysis';
import { poseAt } from '../../../src/features/mechanism/mechPose';
import { advanceInput } from '../../../src/features/mechanism/mechDriveStep';

// Issue 33: "at a limit the input reverses (rocking)". Stephenson II's input rocks: Play and Step must land on the
// limit (its pose drawn), never pass it, and turn back at once (no frame standing still).

const SPEC = MECHANISM_TEMPLATES.stephensonII.spec;
const A = analyseMechanism(SPEC, false);
const RANGE = runRange(A)!;
const ONE_DEG = degToRad(1);

describe('Play and Step at a rocking limit (Stephenson II)', () => {
  it('rocks: its input runs over part of a turn', () => {
    expect(A.fullTurn).toBe(false);
    expect(RANGE[1] - RANGE[0]).toBeGreaterThan(degToRad(90));
    expect(RANGE[1] - RANGE[0]).toBeLessThan(degToRad(359));
  });

  it('Step by 1° from the drawn pose visits the 1° grid, lands on each end, turns back at once, every pose assembled', () => {
    let s = { input: 0, direction: 1 as 1 | -1, limitAt: null as number | null };
    const seen: number[] = [0];
    const limits: number[] = [];
    // Two full swings: up to the top end, down to the bottom, back up.
    const steps = Math.round((2 * (RANGE[1] - RANGE[0])) / ONE_DEG) + 10;
    for (let k = 0; k < steps; k++) {
      const prev = s.input;
      s = advanceInput(s.input, s.direction, ONE_DEG, RANGE, false);
      if (s.limitAt !== null && !limits.includes(s.limitAt)) limits.push(s.limitAt);
      // Never past an end; on the grid of whole degrees (the ends are grid points); never standing still.
      expect(s.input).toBeGreaterThanOrEqual(RANGE[0]);
      expect(s.input).toBeLessThanOrEqual(RANGE[1]);
      expect(Math.abs(s.input / ONE_DEG - Math.round(s.input / ONE_DEG))).toBeLessThan(1e-9);
      expect(Math.abs(s.input - prev)).toBeCloseTo(ONE_DEG, 12);
      expect(poseAt(SPEC, A.grid!, A.sweep!, s.input), `pose at ${s.input}`).not.toBeNull();
      seen.push(s.input);
    }
    expect(limits).toEqual([RANGE[1], RANGE[0]]);
    expect(seen).toContain(RANGE[0]);
    expect(seen).toContain(RANGE[1]);
  });

  it('Play’s frames (60 °/s at 60 frames/s, then a jittery 37 frames/s) stop on the limit and come back', () => {
    for (const dt of [1 / 60, 1 / 37]) {
      const delta = degToRad(60) * dt;
      let s = { input: RANGE[1] - 2.5 * delta, direction: 1 as 1 | -1, limitAt: null as number | null };
      const path: number[] = [];
      for (let k = 0; k < 6; k++) {
        s = advanceInput(s.input, s.direction, delta, RANGE, false);
        path.push(s.input);
      }
      // Up by delta twice, onto the end (half a step), then down by delta each frame.
      const want = [-1.5, -0.5, 0, -1, -2, -3].map((k) => RANGE[1] + k * delta);
      path.forEach((x, k) => expect(x).toBeCloseTo(want[k], 12));
      expect(Math.max(...path)).toBe(RANGE[1]);
    }
  });

  it('from the limit itself (the slider set there, then Play or Step outward) turns back without standing still', () => {
    expect(advanceInput(RANGE[1], 1, ONE_DEG, RANGE, false)).toEqual({
      input: RANGE[1] - ONE_DEG,
      direction: -1,
      limitAt: RANGE[1],
    });
    expect(advanceInput(RANGE[0], -1, ONE_DEG, RANGE, false)).toEqual({
      input: RANGE[0] + ONE_DEG,
      direction: 1,
      limitAt: RANGE[0],
    });
  });
});
