import { describe, expect, it } from 'vitest';
import { poseKey, roundToPixel } from '../../../../src/features/synthesis/motion/MotionCanvas';
import type { MotionPicture } from '../../../../src/features/synthesis/motion/motionPicture';
import {
  TURN_HANDLE_PX,
  handleAt,
  motionBounds,
  turnHandlePx,
} from '../../../../src/features/synthesis/motion/motionPicture';
import { nextPose, pivotsFor } from '../../../../src/features/synthesis/motion/motionEdits';
import { solveMotion, toPose } from '../../../../src/features/synthesis/motion/motionSolve';
import {
  DEFAULT_POSES_FIVE,
  DEFAULT_POSES_TURN,
  DEFAULT_SYN_MOTION,
} from '../../../../src/shared/state/slices/synMotionSlice';
import type { ViewTransform } from '../../../../src/shared/canvas/view';
import { toScreenX, toScreenY } from '../../../../src/shared/canvas/view';
import { placedJoints } from '../../../../src/synthesis';

/** 100 px per unit, the origin at the centre of a 400 × 300 view. */
const VIEW: ViewTransform = { width: 400, height: 300, scale: 100, centerX: 0, centerY: 0, panXPx: 0, panYPx: 0 };

function picture(): MotionPicture {
  return {
    poses: [
      { x: 0, y: 0, angle: 0 },
      { x: 1, y: 0.5, angle: Math.PI / 2 },
      { x: -1, y: 0.2, angle: 0.3 },
    ],
    selected: 0,
    outcome: solveMotion(DEFAULT_SYN_MOTION),
    pivotChoice: 'fixed',
    pivots: [
      { x: 0, y: 0 },
      { x: -1.5, y: -1 },
    ],
    shownPose: 0,
    cursor: null,
    legend: { centre: 'c', circle: 'k' },
  };
}

describe('handleAt', () => {
  it('grabs a pose’s turning handle, its point, and a pivot, the handle and point before a pivot under them', () => {
    const pic = picture();
    const at = (x: number, y: number) => ({ x: toScreenX(VIEW, x), y: toScreenY(VIEW, y) });
    expect(handleAt(pic, VIEW, at(0, 0), 12)).toEqual({ kind: 'point', index: 0 });
    // Pose 2 turned to 90°: its handle is TURN_HANDLE_PX straight up on screen.
    const h = turnHandlePx(VIEW, pic.poses[1]);
    expect(h.x).toBeCloseTo(toScreenX(VIEW, 1), 9);
    expect(h.y).toBeCloseTo(toScreenY(VIEW, 0.5) - TURN_HANDLE_PX, 9);
    expect(handleAt(pic, VIEW, { x: h.x + 3, y: h.y }, 12)).toEqual({ kind: 'turn', index: 1 });
    expect(handleAt(pic, VIEW, at(-1.5, -1), 12)).toEqual({ kind: 'pivot', index: 1 });
    expect(handleAt(pic, VIEW, at(-1.5, -1.3), 12)).toBeNull();
  });

  it('fits the poses, the placed pivots and the design’s fixed pivots', () => {
    const pic = picture();
    const b = motionBounds(pic);
    expect(b.minX).toBeLessThanOrEqual(-1.5);
    expect(b.minY).toBeLessThanOrEqual(-1);
    const { O2 } = pic.outcome.chosen!.design;
    expect(b.minX).toBeLessThanOrEqual(O2.x);
    expect(b.minY).toBeLessThanOrEqual(O2.y);
  });
});

describe('poseKey', () => {
  it('moves by 10 px (1 with Shift) and turns by 5° (1 with Shift); other keys do nothing', () => {
    expect(poseKey({ key: 'ArrowRight', shiftKey: false })).toEqual({ dx: 10, dy: 0 });
    expect(poseKey({ key: 'ArrowUp', shiftKey: true })).toEqual({ dx: 0, dy: 1 });
    expect(poseKey({ key: 'ArrowDown', shiftKey: false })).toEqual({ dx: 0, dy: -10 });
    expect(poseKey({ key: '[', shiftKey: false })).toEqual({ turnDeg: 5 });
    expect(poseKey({ key: ']', shiftKey: true })).toEqual({ turnDeg: -1 });
    expect(poseKey({ key: 'a', shiftKey: false })).toBeNull();
  });
});

describe('roundToPixel', () => {
  it('rounds to the power of ten at or below a pixel, leaving short decimals', () => {
    expect(roundToPixel(1.23456, 100)).toBe(1.23);
    expect(roundToPixel(0.1 + 0.2, 1000)).toBe(0.3);
    expect(roundToPixel(123.456, 0.5)).toBe(123);
    expect(roundToPixel(-0.004, 100)).toBe(0);
  });
});

describe('nextPose', () => {
  it('grows the default poses along the default crank-rocker’s turn, then steps along the last two up to twenty', () => {
    expect(nextPose(DEFAULT_POSES_FIVE.slice(0, 3))).toEqual(DEFAULT_POSES_FIVE[3]);
    // Past five, the same crank-rocker's next poses (least squares takes 6 to 20), then steps along the last two.
    expect(nextPose(DEFAULT_POSES_FIVE)).toEqual(DEFAULT_POSES_TURN[5]);
    expect(nextPose(DEFAULT_POSES_TURN.slice(0, 8))).toEqual(DEFAULT_POSES_TURN[8]);
    expect(nextPose(DEFAULT_POSES_TURN)).toEqual({ x: 0.3, y: 1, angleDeg: 38 });
    const mine = [
      { x: 0, y: 0, angleDeg: 10 },
      { x: 1, y: 2, angleDeg: 30 },
    ];
    expect(nextPose(mine)).toEqual({ x: 2, y: 4, angleDeg: 50 });
    // Twenty is the most.
    const twenty = Array.from({ length: 20 }, (_, i) => ({ x: i, y: 0, angleDeg: i }));
    expect(nextPose(twenty)).toBeNull();
  });
});

describe('pivotsFor', () => {
  it('keeps the linkage when switching: its fixed pivots, or its moving pivots in pose 1’s frame', () => {
    const o = solveMotion(DEFAULT_SYN_MOTION);
    const chosen = o.chosen!;
    const j = placedJoints(chosen.design, chosen.theta2[0])!;
    const [O2, O4] = pivotsFor('fixed', chosen, DEFAULT_SYN_MOTION.poses, DEFAULT_SYN_MOTION.pivots);
    expect(O2).toEqual(j.O2);
    expect(O4.x).toBeCloseTo(j.O4.x, 12);
    const switched = solveMotion({ ...DEFAULT_SYN_MOTION, pivotChoice: 'fixed', pivots: [O2, O4] });
    expect(switched.chosen!.design.links.r2).toBeCloseTo(chosen.design.links.r2, 9);
    const [A] = pivotsFor('moving', switched.chosen, DEFAULT_SYN_MOTION.poses, [O2, O4]);
    expect(A.x).toBeCloseTo(DEFAULT_SYN_MOTION.pivots[0].x, 9);
    expect(A.y).toBeCloseTo(DEFAULT_SYN_MOTION.pivots[0].y, 9);
    expect(pivotsFor('fixed', null, DEFAULT_SYN_MOTION.poses, DEFAULT_SYN_MOTION.pivots)).toEqual(
      DEFAULT_SYN_MOTION.pivots,
    );
    expect(toPose(DEFAULT_SYN_MOTION.poses[0]).x).toBe(-0.9);
  });
});
