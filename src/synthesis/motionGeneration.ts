/**
 * Three-position motion generation (Sandor & Erdman §2.x; Norton ch. 5): a four-bar whose coupler passes through
 * three poses. Given the moving pivots A and B in the coupler frame, each fixed pivot is the centre of the circle
 * through its moving pivot's three positions. Given the fixed pivots O2 and O4, kinematic inversion turns the
 * problem round: seen from the coupler, a fixed pivot takes three positions, and the moving pivot is the centre
 * of the circle through them.
 */
import type { Point } from '../solver';
import { screenPoses } from './defects';
import type { MotionDefect } from './defects';
import { circumcentre, toFrame, toPlane } from './poseFrame';
import { fourBarFromJoints } from './placed';
import type { PlacedFourBar, Pose } from './types';
import { checkArray, checkPoint, checkPose, show } from './validate';

/** The pivots the designer chooses: the moving pivots A, B in the coupler frame, or the fixed pivots O2, O4 in the plane. */
export type ThreePositionGiven = { moving: [Point, Point] } | { fixed: [Point, Point] };

/** A motion-generation design: the placed four-bar (P at the coupler frame's origin), θ2 at each pose, its defects. */
export interface MotionDesign {
  design: PlacedFourBar;
  /** θ2 (radians, from the design's ground line, wrapped to (−π, π]) that puts the coupler at each pose. */
  theta2: number[];
  defects: MotionDefect[];
}

/**
 * The four-bar whose coupler frame passes through three poses, from the moving pivots (coupler frame) or the fixed
 * pivots (plane); P is the frame's origin. θ2[i] puts the coupler at pose i; defects are screened as screenPoses
 * says. Throws for bad input, when a pivot's three positions are collinear or two coincide (no circle passes
 * through them: the message names the pivot), and when two pivots of the result coincide.
 */
export function threePositionSynthesis(poses: readonly [Pose, Pose, Pose], given: ThreePositionGiven): MotionDesign {
  checkArray('poses', poses, 3, 3);
  poses.forEach((p, i) => checkPose(`poses[${i}]`, p));
  if (typeof given !== 'object' || given === null) {
    throw new Error(`given must be { moving: [A, B] } or { fixed: [O2, O4] }, got ${show(given)}`);
  }
  if ('moving' in given && 'fixed' in given) {
    throw new Error(`given must hold either moving or fixed pivots, not both, got ${show(given)}`);
  }
  if ('moving' in given) {
    checkArray('given.moving', given.moving, 2, 2);
    given.moving.forEach((q, i) => checkPoint(`given.moving[${i}]`, q));
  } else if ('fixed' in given) {
    checkArray('given.fixed', given.fixed, 2, 2);
    given.fixed.forEach((q, i) => checkPoint(`given.fixed[${i}]`, q));
  } else {
    throw new Error(`given must be { moving: [A, B] } or { fixed: [O2, O4] }, got ${show(given)}`);
  }
  // Solved at the unit scale: the poses' spread (and the pivots' distance from pose 1) is brought near 1 by a power
  // of two, which is exact, so circumcentres and the branch's cross products neither overflow (beyond 1e103 today
  // they would square 1e206 and multiply two of those) nor underflow (below 1e-110); the design is scaled back.
  const k = 2 ** -unitExponent(poses, given);
  const down = (q: Point): Point => ({ x: q.x * k, y: q.y * k });
  const unitPoses = poses.map((p) => ({ x: p.x * k, y: p.y * k, angle: p.angle })) as [Pose, Pose, Pose];
  const unitGiven: ThreePositionGiven =
    'moving' in given
      ? { moving: [down(given.moving[0]), down(given.moving[1])] }
      : { fixed: [down(given.fixed[0]), down(given.fixed[1])] };
  const out = solveThree(unitPoses, unitGiven, k);
  const up = (v: number) => v / k;
  const d = out.design;
  return {
    ...out,
    design: {
      ...d,
      links: { r1: up(d.links.r1), r2: up(d.links.r2), r3: up(d.links.r3), r4: up(d.links.r4) },
      O2: { x: up(d.O2.x), y: up(d.O2.y) },
      pDist: up(d.pDist),
    },
  };
}

/** The exponent of the power of two nearest the problem's size: the poses' spread and the pivots' reach. */
function unitExponent(poses: readonly Pose[], given: ThreePositionGiven): number {
  const P = poses[0];
  let size = 0;
  for (const p of poses) size = Math.max(size, Math.hypot(p.x - P.x, p.y - P.y));
  if ('moving' in given) for (const q of given.moving) size = Math.max(size, Math.hypot(q.x, q.y));
  else for (const q of given.fixed) size = Math.max(size, Math.hypot(q.x - P.x, q.y - P.y));
  if (!(size > 0) || !Number.isFinite(size)) return 0;
  return Math.max(-1000, Math.min(1000, Math.round(Math.log2(size))));
}

/** threePositionSynthesis on a validated problem scaled by k to a size about 1. */
function solveThree(poses: readonly [Pose, Pose, Pose], given: ThreePositionGiven, k: number): MotionDesign {
  let moving: [Point, Point];
  let fixed: [Point, Point];
  if ('moving' in given) {
    moving = given.moving;
    fixed = [
      centreOf(
        poses.map((p) => toPlane(p, moving[0])),
        'moving pivot A',
        'the plane',
        k,
      ),
      centreOf(
        poses.map((p) => toPlane(p, moving[1])),
        'moving pivot B',
        'the plane',
        k,
      ),
    ];
  } else {
    fixed = given.fixed;
    moving = [
      centreOf(
        poses.map((p) => toFrame(p, fixed[0])),
        'fixed pivot O2',
        'the coupler frame',
        k,
      ),
      centreOf(
        poses.map((p) => toFrame(p, fixed[1])),
        'fixed pivot O4',
        'the coupler frame',
        k,
      ),
    ];
  }
  return motionDesign(poses, fixed, moving);
}

/** Centre of the circle through three positions of a pivot (scaled by k); throws naming the pivot when there is none. */
function centreOf(points: Point[], pivot: string, where: string, k: number): Point {
  const c = circumcentre(points[0], points[1], points[2]);
  if (!c) {
    throw new Error(
      `no circle passes through the three positions of ${pivot} in ${where}: they are collinear or two coincide, got ${show(points.map((q) => ({ x: q.x / k, y: q.y / k })))}`,
    );
  }
  return c;
}

/**
 * The placed four-bar with fixed pivots O2, O4 and moving pivots A, B (coupler frame, P at its origin), built at
 * the first pose, with θ2 and defects at every pose. Throws when two pivots coincide.
 */
export function motionDesign(
  poses: readonly Pose[],
  fixed: readonly [Point, Point],
  moving: readonly [Point, Point],
): MotionDesign {
  const pins = poses.map((p) => ({ A: toPlane(p, moving[0]), B: toPlane(p, moving[1]) }));
  const { design } = fourBarFromJoints({ O2: fixed[0], A: pins[0].A, B: pins[0].B, O4: fixed[1], P: poses[0] });
  return { design, ...screenPoses(design, pins) };
}
