/**
 * The Motion mode's edits that need a little geometry: the pose Add pose appends, and the pivots that keep the same
 * linkage when the designer switches between placing moving and fixed pivots.
 */
import type { Point } from '../../../solver';
import { placedJoints, toFrame } from '../../../synthesis';
import type { PivotChoice, PoseDeg } from '../../../shared/state/slices/synMotionSlice';
import { DEFAULT_POSES_TURN, MAX_POSES } from '../../../shared/state/slices/synMotionSlice';
import type { MotionCandidate } from './motionSolve';
import { toPose } from './motionSolve';

const same = (a: PoseDeg, b: PoseDeg) => a.x === b.x && a.y === b.y && a.angleDeg === b.angleDeg;

/**
 * The pose Add pose appends: the default crank-rocker's next pose while the poses are still its first ones (so the
 * defaults grow into a Burmester problem with real answers, then into six to nine poses a four-bar fits closely: a
 * pose extrapolated from the default five leaves the least-squares fit a single dyad), else one step further along
 * the last two.
 */
export function nextPose(poses: readonly PoseDeg[]): PoseDeg | null {
  const n = poses.length;
  if (n >= MAX_POSES) return null;
  if (n < DEFAULT_POSES_TURN.length && poses.every((p, i) => same(p, DEFAULT_POSES_TURN[i])))
    return DEFAULT_POSES_TURN[n];
  const a = poses[n - 2];
  const b = poses[n - 1];
  const r = (v: number) => Number(v.toPrecision(10));
  return { x: r(2 * b.x - a.x), y: r(2 * b.y - a.y), angleDeg: r(2 * b.angleDeg - a.angleDeg) };
}

/**
 * The pivots to place after switching to choice: those of the linkage shown (its fixed pivots, or its moving
 * pivots in pose 1's frame), so the design stays; without one, the pivots as they are.
 */
export function pivotsFor(
  choice: PivotChoice,
  chosen: MotionCandidate | null,
  poses: readonly PoseDeg[],
  current: readonly [Point, Point],
): [Point, Point] {
  const j = chosen ? placedJoints(chosen.design, chosen.theta2[0]) : null;
  if (!j) return [current[0], current[1]];
  if (choice === 'fixed') return [j.O2, j.O4];
  const pose1 = toPose(poses[0]);
  return [toFrame(pose1, j.A), toFrame(pose1, j.B)];
}
