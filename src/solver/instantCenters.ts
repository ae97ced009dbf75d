/**
 * Instant centres of a four-bar pose that are not at a pivot or a pin: I13, the coupler's centre of
 * rotation relative to the ground (where the lines O2 A and O4 B meet), and I24, the point where crank
 * and rocker have the same velocity (where the line A B meets the ground line O2 O4, Kennedy's theorem).
 * The lines are those of the pose as given: O2 A along theta2, O4 B along theta4, A B along theta3 from
 * A = r2 (cos theta2, sin theta2), as jointPositions draws them.
 */
import { TWO_SUM_MAX_RAD, reduceDifference } from './angles';
import type { AngleParts } from './angles';
import { twoSum } from './exact';
import type { Point } from './kinematics';
import type { Angles, Linkage } from './types';
import { checkAngles, checkFinite, validateLinkage } from './validate';

/** Instant centres I13 and I24 in the linkage's length unit (frame of jointPositions); null at infinity. */
export interface InstantCenters {
  I13: Point | null;
  I24: Point | null;
}

/**
 * Two lines count as parallel when the sine of the angle between them is at most this (8 eps, about
 * 4 ulps of an angle near pi). A double angle cannot resolve directions more finely, so beyond it the
 * side on which the lines meet is decided by the last bits of the input. The test is on a sine of unit
 * directions, so it does not depend on the length unit: an instant centre is reported up to about
 * 1 / (8 eps) = 5.6e14 link lengths away and as null (at infinity) beyond.
 */
export const PARALLEL_SIN = 8 * Number.EPSILON;

/**
 * sin(a - b) for double a, b with the difference kept exactly as hi + lo: relatively accurate down to
 * |sin| ~ ulp(a - b), and absolutely to eps^2 |a - b| below (plain sin(a - b) would be off by eps |a - b|).
 * Past TWO_SUM_MAX_RAD the TwoSum lo is too large for the first-order correction: the exact difference is
 * reduced modulo 2 pi first, as hi + lo again.
 */
function sinOfDifference(a: number, b: number): number {
  const d = Math.abs(a) <= TWO_SUM_MAX_RAD && Math.abs(b) <= TWO_SUM_MAX_RAD ? twoSum(a, -b) : reduced(a, b);
  return Math.sin(d.hi) + d.lo * Math.cos(d.hi);
}

/** a - b reduced exactly modulo 2 pi as hi + lo (angles.ts reduceDifference). */
function reduced(a: number, b: number): AngleParts {
  const out = { hi: 0, lo: 0 };
  reduceDifference(a, b, out);
  return out;
}

/**
 * Instant centres I13 (lines O2 A and O4 B) and I24 (line A B and the ground line) of the pose
 * (theta3, theta4 in radians) at input angle theta2 (radians). Each is null when its two lines are
 * parallel to within PARALLEL_SIN (or coincide), i.e. at infinity. Throws an Error naming the field
 * and value for a bad length, a non-finite theta2 or a pose without finite theta3 and theta4.
 */
export function instantCenters(l: Linkage, theta2: number, pose: Angles): InstantCenters {
  validateLinkage(l);
  checkFinite('theta2', theta2, 'angle in radians');
  checkAngles('pose', pose);
  const { theta3, theta4 } = pose;

  // O2 + t (cos t2, sin t2) = O4 + u (cos t4, sin t4): crossing with (cos t4, sin t4) gives
  // t sin(t4 - t2) = r1 sin t4.
  let I13: Point | null = null;
  const sin42 = sinOfDifference(theta4, theta2);
  if (Math.abs(sin42) > PARALLEL_SIN) {
    const t = l.r1 * (Math.sin(theta4) / sin42);
    const p = { x: t * Math.cos(theta2), y: t * Math.sin(theta2) };
    if (Number.isFinite(p.x) && Number.isFinite(p.y)) I13 = p;
  }

  // A + u (cos t3, sin t3) on y = 0: u = -r2 sin t2 / sin t3, so x = r2 sin(t3 - t2) / sin t3.
  let I24: Point | null = null;
  const sin3 = Math.sin(theta3);
  if (Math.abs(sin3) > PARALLEL_SIN) {
    const x = l.r2 * (sinOfDifference(theta3, theta2) / sin3);
    if (Number.isFinite(x)) I24 = { x, y: 0 };
  }
  return { I13, I24 };
}
