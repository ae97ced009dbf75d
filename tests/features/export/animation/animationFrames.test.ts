import { describe, expect, it } from 'vitest';
import type { AnimationFrame } from '../../../../src/features/export/animation/animationFrames';
import { planAnimationFrames, playbackFps } from '../../../../src/features/export/animation/animationFrames';
import { classify, jointPositions, solveClosedForm } from '../../../../src/solver';
import type { Branch, Linkage } from '../../../../src/solver';
import type { InputRangeDeg } from '../../../../src/shared/state/animation';
import { advanceTheta2, rangeToDeg } from '../../../../src/shared/state/animation';

const CRANK_ROCKER: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };
/** Triple rocker of the hard-case table: one interval of about ±135.95°. */
const TRIPLE_ROCKER: Linkage = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
/** Grashof with the coupler shortest (GRRC): the input rocks in one of two disjoint intervals. */
const DOUBLE_ROCKER: Linkage = { r1: 4, r2: 3, r3: 1, r4: 3.5 };

const DEG = 180 / Math.PI;

function rangeOf(l: Linkage): InputRangeDeg {
  return rangeToDeg(classify(l).inputRange);
}

/** Signed smallest angle from a to b, degrees in (-180, 180]. */
function turnDeg(a: number, b: number): number {
  const d = (((b - a) % 360) + 360) % 360;
  return d > 180 ? d - 360 : d;
}

function frameDeg(f: AnimationFrame): number {
  return f.theta2Rad * DEG;
}

/** Coupler pin B of a frame's pose, from the closed form (an oracle independent of the plan). */
function pinB(l: Linkage, f: AnimationFrame): { x: number; y: number } {
  const a = solveClosedForm(l, f.theta2Rad, f.branch);
  if (!a) throw new Error(`frame at ${frameDeg(f)}° (${f.branch}) does not assemble`);
  return jointPositions(l, f.theta2Rad, a).B;
}

/** Indices k where the branch differs from frame k + 1 (cyclically: the last frame is followed by the first). */
function branchChanges(frames: AnimationFrame[]): number[] {
  return frames.flatMap((f, k) => (f.branch !== frames[(k + 1) % frames.length].branch ? [k] : []));
}

describe('planAnimationFrames', () => {
  it('turns a crank once counter-clockwise from the current angle, first frame not repeated', () => {
    const plan = planAnimationFrames({
      theta2Deg: 45,
      direction: 1,
      branch: 'open',
      range: rangeOf(CRANK_ROCKER),
      framesPerCycle: 120,
    });
    expect(plan.kind).toBe('full-turn');
    expect(plan.travelDeg).toBe(360);
    expect(plan.frames).toHaveLength(120);
    expect(frameDeg(plan.frames[0])).toBeCloseTo(45, 12);
    // Every step, including last -> first, is +3°: the cycle closes without a doubled frame.
    for (let k = 0; k < 120; k++) {
      const step = turnDeg(frameDeg(plan.frames[k]), frameDeg(plan.frames[(k + 1) % 120]));
      expect(step).toBeCloseTo(3, 9);
    }
    expect(new Set(plan.frames.map((f) => f.branch))).toEqual(new Set(['open']));
    for (const f of plan.frames) expect(f.theta2Rad).toBeGreaterThanOrEqual(0);
    for (const f of plan.frames) expect(f.theta2Rad).toBeLessThan(2 * Math.PI);
  });

  it('turns clockwise (decreasing θ2) when the direction is -1, on the crossed branch when asked', () => {
    const plan = planAnimationFrames({
      theta2Deg: 10,
      direction: -1,
      branch: 'crossed',
      range: rangeOf(CRANK_ROCKER),
      framesPerCycle: 36,
    });
    expect(plan.frames).toHaveLength(36);
    expect(frameDeg(plan.frames[1])).toBeCloseTo(0, 9);
    expect(frameDeg(plan.frames[2])).toBeCloseTo(350, 9);
    expect(plan.frames.every((f) => f.branch === 'crossed')).toBe(true);
  });

  it('rocks a triple rocker out to one limit and back to the other, switching branch at each limit', () => {
    const range = rangeOf(TRIPLE_ROCKER);
    const [iv] = range.intervals;
    const n = 240;
    const plan = planAnimationFrames({ theta2Deg: 0, direction: 1, branch: 'open', range, framesPerCycle: n });
    expect(plan.kind).toBe('rocking');
    expect(plan.frames).toHaveLength(n);
    // Travel: twice the interval (inset by 1e-6° at each limit, as Play does).
    expect(plan.travelDeg).toBeCloseTo(2 * (iv.hi - iv.lo), 4);
    const step = plan.travelDeg / n;
    const deg = plan.frames.map((f) => turnDeg(0, frameDeg(f)));
    // It first moves in the animation's direction.
    expect(deg[1] - deg[0]).toBeCloseTo(step, 9);
    // It comes within one step of both limits and never passes them.
    expect(Math.max(...deg)).toBeGreaterThan(iv.hi - step);
    expect(Math.min(...deg)).toBeLessThan(iv.lo + step);
    for (const d of deg) expect(d).toBeLessThanOrEqual(iv.hi);
    for (const d of deg) expect(d).toBeGreaterThanOrEqual(iv.lo);
    // Exactly two branch changes per cycle, each where θ2 turns back (at a limit).
    const changes = branchChanges(plan.frames);
    expect(changes).toHaveLength(2);
    for (const k of changes) {
      const atLimit = Math.min(iv.hi - deg[k], deg[k] - iv.lo, iv.hi - deg[(k + 1) % n], deg[(k + 1) % n] - iv.lo);
      expect(atLimit).toBeLessThan(step);
    }
    // The open branch goes out towards hi first (direction +1), the crossed branch comes back.
    expect(plan.frames[1].branch).toBe('open');
  });

  it('moves the coupler continuously through the whole rocking cycle and back to the start', () => {
    // The independent check: the closed-form pose of consecutive frames. A branch switched away from a limit
    // would make pin B jump across the loop (the two branches are far apart inside the interval).
    const range = rangeOf(TRIPLE_ROCKER);
    const n = 720;
    const plan = planAnimationFrames({ theta2Deg: 60, direction: -1, branch: 'crossed', range, framesPerCycle: n });
    // Clockwise: the first step decreases θ2.
    expect(turnDeg(frameDeg(plan.frames[0]), frameDeg(plan.frames[1]))).toBeCloseTo(-plan.travelDeg / n, 9);
    let worst = 0;
    for (let k = 0; k < n; k++) {
      const a = pinB(TRIPLE_ROCKER, plan.frames[k]);
      const b = pinB(TRIPLE_ROCKER, plan.frames[(k + 1) % n]);
      worst = Math.max(worst, Math.hypot(a.x - b.x, a.y - b.y));
    }
    // Step ~0.76°; away from the limits B moves at most ~r4 · |dθ4/dθ2| · step, near a limit like
    // sqrt(step): both stay well under the open-to-crossed separation at 60° (about 4.5 length units).
    const open = pinB(TRIPLE_ROCKER, { theta2Rad: Math.PI / 3, branch: 'open' });
    const crossed = pinB(TRIPLE_ROCKER, { theta2Rad: Math.PI / 3, branch: 'crossed' });
    const separation = Math.hypot(open.x - crossed.x, open.y - crossed.y);
    expect(separation).toBeGreaterThan(2);
    expect(worst).toBeLessThan(0.5);
  });

  it('is the motion of Play: stepping advanceTheta2 by travel / N from the start gives each next frame', () => {
    const range = rangeOf(TRIPLE_ROCKER);
    const n = 90;
    const plan = planAnimationFrames({ theta2Deg: 100, direction: 1, branch: 'open', range, framesPerCycle: n });
    let s = { theta2Deg: 100, direction: 1 as const as 1 | -1, branch: 'open' as Branch };
    for (let k = 0; k < n; k++) {
      expect(turnDeg(s.theta2Deg, frameDeg(plan.frames[k]))).toBeCloseTo(0, 6);
      expect(plan.frames[k].branch).toBe(s.branch);
      s = advanceTheta2(s.theta2Deg, plan.travelDeg / n, s.direction, s.branch, range);
    }
    // After N steps Play is back at the first frame, on its branch.
    expect(turnDeg(s.theta2Deg, frameDeg(plan.frames[0]))).toBeCloseTo(0, 6);
    expect(s.branch).toBe(plan.frames[0].branch);
  });

  it('rocks within the interval that holds the start when the input has two', () => {
    const range = rangeOf(DOUBLE_ROCKER);
    expect(range.intervals).toHaveLength(2);
    const upper = range.intervals.find((iv) => iv.lo > 0)!;
    const mid = (upper.lo + upper.hi) / 2;
    const plan = planAnimationFrames({ theta2Deg: mid, direction: 1, branch: 'open', range, framesPerCycle: 120 });
    expect(plan.kind).toBe('rocking');
    expect(plan.travelDeg).toBeCloseTo(2 * (upper.hi - upper.lo), 4);
    for (const f of plan.frames) {
      expect(frameDeg(f)).toBeGreaterThanOrEqual(upper.lo);
      expect(frameDeg(f)).toBeLessThanOrEqual(upper.hi);
    }
    expect(branchChanges(plan.frames)).toHaveLength(2);
  });

  it('starts an unreachable angle from the nearest limit, as Play does', () => {
    const range = rangeOf(TRIPLE_ROCKER);
    const plan = planAnimationFrames({ theta2Deg: 170, direction: 1, branch: 'open', range, framesPerCycle: 36 });
    expect(frameDeg(plan.frames[0])).toBeCloseTo(range.intervals[0].hi, 4);
    // From the upper limit the only way is back: decreasing θ2.
    expect(turnDeg(frameDeg(plan.frames[0]), frameDeg(plan.frames[1]))).toBeLessThan(0);
  });

  it('gives one still frame for an interval of zero width and none when the linkage never assembles', () => {
    const still = planAnimationFrames({
      theta2Deg: 10,
      direction: 1,
      branch: 'open',
      range: { full: false, intervals: [{ lo: 30, hi: 30 }] },
      framesPerCycle: 120,
    });
    expect(still.kind).toBe('still');
    expect(still.frames).toHaveLength(1);
    expect(frameDeg(still.frames[0])).toBeCloseTo(30, 9);
    const none = planAnimationFrames({
      theta2Deg: 10,
      direction: 1,
      branch: 'open',
      range: { full: false, intervals: [] },
      framesPerCycle: 120,
    });
    expect(none).toEqual({ kind: 'none', frames: [], travelDeg: 0 });
  });

  it('names the bad frame count', () => {
    const base = { theta2Deg: 0, direction: 1 as const, branch: 'open' as const, range: rangeOf(CRANK_ROCKER) };
    expect(() => planAnimationFrames({ ...base, framesPerCycle: 35 })).toThrow(/framesPerCycle.*got 35/);
    expect(() => planAnimationFrames({ ...base, framesPerCycle: 721 })).toThrow(/got 721/);
    expect(() => planAnimationFrames({ ...base, framesPerCycle: 120.5 })).toThrow(/got 120.5/);
    expect(planAnimationFrames({ ...base, framesPerCycle: 36 }).frames).toHaveLength(36);
    expect(planAnimationFrames({ ...base, framesPerCycle: 720 }).frames).toHaveLength(720);
  });
});

describe('playbackFps', () => {
  it('makes the export last one cycle of Play', () => {
    const range = rangeOf(CRANK_ROCKER);
    const plan = planAnimationFrames({ theta2Deg: 0, direction: 1, branch: 'open', range, framesPerCycle: 120 });
    // 1°/frame at 60 frames/s: 360° in 6 s, so 120 frames at 20 per second.
    expect(playbackFps(plan, 1)).toBeCloseTo(20, 12);
    expect(playbackFps(plan, 3)).toBeCloseTo(60, 12);
    expect(playbackFps({ kind: 'none', frames: [], travelDeg: 0 }, 1)).toBe(0);
  });
});
