import { TWO_SUM_MAX_RAD, angleDiff, reduceDifference } from './angles';
import type { AngleParts } from './angles';
import type { Angles, Linkage } from './types';
import { checkNumber, checkObject, validateLinkage } from './validate';

/** A point in the linkage's length unit. */
export interface Point {
  x: number;
  y: number;
}

/** Joint positions of a pose: O2 at the origin, O4 at (r1, 0), crank pin A, coupler pin B. */
export interface Joints {
  O2: Point;
  A: Point;
  B: Point;
  O4: Point;
}

// The kinematics functions take a pose that may be missing: a NaN angle (a point the solver did not
// solve) gives NaN coordinates and ratios, which callers read as "no pose". Anything that is not a
// number, or a linkage that is not four positive lengths, throws.

/** Throws unless l is a linkage, theta2 a number and a an object with numeric theta3, theta4. */
function checkPose(l: Linkage, theta2: number, a: Angles): void {
  validateLinkage(l);
  checkNumber('theta2', theta2);
  checkAngleObject(a);
}

/** Throws unless a is an object with numeric theta3 and theta4. */
function checkAngleObject(a: Angles): void {
  checkObject('angles', a);
  checkNumber('angles.theta3', a.theta3);
  checkNumber('angles.theta4', a.theta4);
}

/** Joint positions (length unit) for theta2 and the solved angles (radians); NaN angles give NaN points. Throws an Error naming a bad argument. */
export function jointPositions(l: Linkage, theta2: number, a: Angles): Joints {
  checkPose(l, theta2, a);
  const A = { x: l.r2 * Math.cos(theta2), y: l.r2 * Math.sin(theta2) };
  const B = { x: A.x + l.r3 * Math.cos(a.theta3), y: A.y + l.r3 * Math.sin(a.theta3) };
  return { O2: { x: 0, y: 0 }, A, B, O4: { x: l.r1, y: 0 } };
}

/**
 * Coupler point P at distance pDist (length unit, finite, any sign) from A, at angle pAngle (radians)
 * measured from the coupler line AB, counter-clockwise; a NaN argument gives a NaN point. Throws an Error
 * naming a bad argument (a linkage that is not four positive lengths, or a non-number).
 */
export function couplerPoint(l: Linkage, theta2: number, theta3: number, pDist: number, pAngle: number): Point {
  validateLinkage(l);
  checkNumber('theta2', theta2);
  checkNumber('theta3', theta3);
  checkNumber('pDist', pDist);
  checkNumber('pAngle', pAngle);
  const ax = l.r2 * Math.cos(theta2);
  const ay = l.r2 * Math.sin(theta2);
  if (Math.abs(theta3) <= TWO_SUM_MAX_RAD && Math.abs(pAngle) <= TWO_SUM_MAX_RAD) {
    return { x: ax + pDist * Math.cos(theta3 + pAngle), y: ay + pDist * Math.sin(theta3 + pAngle) };
  }
  // A huge angle: theta3 + pAngle rounds by up to a radian at 1e16, so the exact sum is reduced first.
  reduceDifference(theta3, -pAngle, parts);
  const c = Math.cos(parts.hi);
  const s = Math.sin(parts.hi);
  return { x: ax + pDist * (c - s * parts.lo), y: ay + pDist * (s + c * parts.lo) };
}

const parts: AngleParts = { hi: 0, lo: 0 };

/** sin(a - b), with the exact difference reduced first when an angle is huge (its rounding would be radians). */
function sinDiff(a: number, b: number): number {
  if (Math.abs(a) <= TWO_SUM_MAX_RAD && Math.abs(b) <= TWO_SUM_MAX_RAD) return Math.sin(a - b);
  reduceDifference(a, b, parts);
  return Math.sin(parts.hi) + parts.lo * Math.cos(parts.hi);
}

/** Transmission angle mu in radians, in [0, pi]: the angle between coupler and rocker at B (NaN for NaN angles). Throws for non-numbers. */
export function transmissionAngle(a: Angles): number {
  checkAngleObject(a);
  // The exact difference reduced to (-pi, pi] (also for huge angles, where theta4 - theta3 rounds).
  return Math.abs(angleDiff(a.theta4, a.theta3));
}

/** Velocity ratios d theta3 / d theta2 and d theta4 / d theta2 (dimensionless); infinite at a limit. Throws an Error naming a bad argument. */
export function velocityRatios(l: Linkage, theta2: number, a: Angles): { dTheta3: number; dTheta4: number } {
  checkPose(l, theta2, a);
  const sin34 = sinDiff(a.theta3, a.theta4);
  return {
    dTheta3: (l.r2 * sinDiff(a.theta4, theta2)) / (l.r3 * sin34),
    dTheta4: (l.r2 * sinDiff(theta2, a.theta3)) / (-l.r4 * sin34),
  };
}

/** Loop-closure residual norm |f| (length unit) of a pose. Throws an Error naming a bad argument. */
export function loopResidual(l: Linkage, theta2: number, a: Angles): number {
  checkPose(l, theta2, a);
  const f1 = l.r2 * Math.cos(theta2) + l.r3 * Math.cos(a.theta3) - l.r4 * Math.cos(a.theta4) - l.r1;
  const f2 = l.r2 * Math.sin(theta2) + l.r3 * Math.sin(a.theta3) - l.r4 * Math.sin(a.theta4);
  return Math.hypot(f1, f2);
}
