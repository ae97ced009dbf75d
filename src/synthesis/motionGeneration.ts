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

/** The pivot a construction finds, named as the design names it. */
export type PivotName = 'A' | 'B' | 'O2' | 'O4';

/**
 * One pivot's three-position construction: the three positions of a given pivot (a moving pivot's in the plane; a
 * fixed pivot's seen from the coupler, in the coupler frame) and the centre of the circle through them, which is the
 * pivot found (its fixed pivot; by inversion, its moving pivot in the coupler frame), or null when no circle passes
 * through them (collinear, or two coincide).
 */
export interface PivotConstruction {
  /** The pivot found (O2, O4 from A, B; A, B from O2, O4). */
  found: PivotName;
  /** The given pivot whose positions these are. */
  given: PivotName;
  points: [Point, Point, Point];
  centre: Point | null;
}

/**
 * The construction threePositionSynthesis builds its design from, for each of the two given pivots: their three
 * positions and the circle's centre (null where none passes; threePositionSynthesis throws there). Checks its input
 * as threePositionSynthesis does.
 */
export function threePositionConstruction(
  poses: readonly [Pose, Pose, Pose],
  given: ThreePositionGiven,
): [PivotConstruction, PivotConstruction] {
  checkArray('poses', poses, 3, 3);
  poses.forEach((p, i) => checkPose(`poses[${i}]`, p));
  if (typeof given === 'object' && given !== null && 'moving' in given) {
    checkArray('given.moving', given.moving, 2, 2);
    given.moving.forEach((q, i) => checkPoint(`given.moving[${i}]`, q));
    const [a, b] = given.moving;
    return [construct('A', 'O2', poses, (p) => toPlane(p, a)), construct('B', 'O4', poses, (p) => toPlane(p, b))];
  }
  if (typeof given === 'object' && given !== null && 'fixed' in given) {
    checkArray('given.fixed', given.fixed, 2, 2);
    given.fixed.forEach((q, i) => checkPoint(`given.fixed[${i}]`, q));
    const [o2, o4] = given.fixed;
    return [construct('O2', 'A', poses, (p) => toFrame(p, o2)), construct('O4', 'B', poses, (p) => toFrame(p, o4))];
  }
  throw new Error(`given must be { moving: [A, B] } or { fixed: [O2, O4] }, got ${show(given)}`);
}

function construct(
  given: PivotName,
  found: PivotName,
  poses: readonly [Pose, Pose, Pose],
  position: (p: Pose) => Point,
): PivotConstruction {
  const points = poses.map(position) as [Point, Point, Point];
  return { given, found, points, centre: circumcentre(points[0], points[1], points[2]) };
}

/**
 * The four-bar whose coupler frame passes through three poses, from the moving pivots (coupler frame) or the fixed
 * pivots (plane); P is the frame's origin. θ2[i] puts the coupler at pose i; defects are screened as screenPoses
 * says. Throws for bad input, when a pivot's three positions are collinear or two coincide (no circle passes
 * through them: the message names the pivot), and when two pivots of the result coincide.
 */
export function threePositionSynthesis(poses: readonly [Pose, Pose, Pose], given: ThreePositionGiven): MotionDesign {
  const [c0, c1] = threePositionConstruction(poses, given);
  const [p0, p1] = [centreOf(c0), centreOf(c1)];
  return 'moving' in given ? motionDesign(poses, [p0, p1], given.moving) : motionDesign(poses, given.fixed, [p0, p1]);
}

/** The centre a construction found; throws naming the pivot when there is none. */
function centreOf(c: PivotConstruction): Point {
  if (c.centre) return c.centre;
  const moving = c.given === 'A' || c.given === 'B';
  throw new Error(
    `no circle passes through the three positions of ${moving ? 'moving' : 'fixed'} pivot ${c.given} in ${moving ? 'the plane' : 'the coupler frame'}: they are collinear or two coincide, got ${show(c.points)}`,
  );
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
