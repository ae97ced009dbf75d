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

/** Checks threePositionSynthesis's input; throws naming the field. */
function checkThree(poses: readonly [Pose, Pose, Pose], given: ThreePositionGiven): void {
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

/** The problem scaled by k (a power of two, so exactly): poses' positions and the given pivots. */
function scaleProblem(
  poses: readonly [Pose, Pose, Pose],
  given: ThreePositionGiven,
  k: number,
): [[Pose, Pose, Pose], ThreePositionGiven] {
  const down = (q: Point): Point => ({ x: q.x * k, y: q.y * k });
  const unitPoses = poses.map((p) => ({ x: p.x * k, y: p.y * k, angle: p.angle })) as [Pose, Pose, Pose];
  const unitGiven: ThreePositionGiven =
    'moving' in given
      ? { moving: [down(given.moving[0]), down(given.moving[1])] }
      : {
          fixed: [
            down((given as { fixed: [Point, Point] }).fixed[0]),
            down((given as { fixed: [Point, Point] }).fixed[1]),
          ],
        };
  return [unitPoses, unitGiven];
}

/** The two constructions on a validated problem, at the scale given. */
function constructions(
  poses: readonly [Pose, Pose, Pose],
  given: ThreePositionGiven,
): [PivotConstruction, PivotConstruction] {
  if ('moving' in given) {
    const [a, b] = given.moving;
    return [construct('A', 'O2', poses, (p) => toPlane(p, a)), construct('B', 'O4', poses, (p) => toPlane(p, b))];
  }
  const [o2, o4] = given.fixed;
  return [construct('O2', 'A', poses, (p) => toFrame(p, o2)), construct('O4', 'B', poses, (p) => toFrame(p, o4))];
}

/**
 * The construction threePositionSynthesis builds its design from, for each of the two given pivots: their three
 * positions and the circle's centre (null where none passes; threePositionSynthesis throws there). Checks its input
 * as threePositionSynthesis does; solved at unit scale as it is.
 */
export function threePositionConstruction(
  poses: readonly [Pose, Pose, Pose],
  given: ThreePositionGiven,
): [PivotConstruction, PivotConstruction] {
  checkThree(poses, given);
  const k = 2 ** -unitExponent(poses, given);
  const up = (q: Point): Point => ({ x: q.x / k, y: q.y / k });
  return constructions(...scaleProblem(poses, given, k)).map((c) => ({
    ...c,
    points: c.points.map(up) as [Point, Point, Point],
    centre: c.centre ? up(c.centre) : null,
  })) as [PivotConstruction, PivotConstruction];
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
 * says. Throws for bad input (both kinds of pivot given included), when a pivot's three positions are collinear or
 * two coincide (no circle passes through them: the message names the pivot), and when two pivots of the result
 * coincide.
 */
export function threePositionSynthesis(poses: readonly [Pose, Pose, Pose], given: ThreePositionGiven): MotionDesign {
  checkThree(poses, given);
  // Solved at the unit scale: the poses' spread (and the pivots' distance from pose 1) is brought near 1 by a power
  // of two, which is exact, so circumcentres and the branch's cross products neither overflow (beyond 1e103 they
  // would square 1e206 and multiply two of those) nor underflow (below 1e-110); the design is scaled back.
  const k = 2 ** -unitExponent(poses, given);
  const [unitPoses, unitGiven] = scaleProblem(poses, given, k);
  const [c0, c1] = constructions(unitPoses, unitGiven);
  const [p0, p1] = [centreOf(c0, k), centreOf(c1, k)];
  const out =
    'moving' in unitGiven
      ? motionDesign(unitPoses, [p0, p1], unitGiven.moving)
      : motionDesign(unitPoses, unitGiven.fixed, [p0, p1]);
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

/** The centre a construction found (at scale k); throws naming the pivot, in the caller's scale, when there is none. */
function centreOf(c: PivotConstruction, k: number): Point {
  if (c.centre) return c.centre;
  const moving = c.given === 'A' || c.given === 'B';
  const points = c.points.map((q) => ({ x: q.x / k, y: q.y / k }));
  throw new Error(
    `no circle passes through the three positions of ${moving ? 'moving' : 'fixed'} pivot ${c.given} in ${moving ? 'the plane' : 'the coupler frame'}: they are collinear or two coincide, got ${show(points)}`,
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
