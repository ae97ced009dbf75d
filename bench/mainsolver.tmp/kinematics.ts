import type { Angles, Linkage } from './types';

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

/** Joint positions (length unit) for theta2 and the solved angles (radians). */
export function jointPositions(l: Linkage, theta2: number, a: Angles): Joints {
  const A = { x: l.r2 * Math.cos(theta2), y: l.r2 * Math.sin(theta2) };
  const B = { x: A.x + l.r3 * Math.cos(a.theta3), y: A.y + l.r3 * Math.sin(a.theta3) };
  return { O2: { x: 0, y: 0 }, A, B, O4: { x: l.r1, y: 0 } };
}

/**
 * Coupler point P at distance pDist (length unit) from A, at angle pAngle (radians) measured from
 * the coupler line AB, counter-clockwise.
 */
export function couplerPoint(l: Linkage, theta2: number, theta3: number, pDist: number, pAngle: number): Point {
  const ax = l.r2 * Math.cos(theta2);
  const ay = l.r2 * Math.sin(theta2);
  return { x: ax + pDist * Math.cos(theta3 + pAngle), y: ay + pDist * Math.sin(theta3 + pAngle) };
}

/** Transmission angle mu in radians, in [0, pi]: the angle between coupler and rocker at B. */
export function transmissionAngle(a: Angles): number {
  return Math.abs(Math.atan2(Math.sin(a.theta4 - a.theta3), Math.cos(a.theta4 - a.theta3)));
}

/** Velocity ratios d theta3 / d theta2 and d theta4 / d theta2 (dimensionless); infinite at a limit. */
export function velocityRatios(l: Linkage, theta2: number, a: Angles): { dTheta3: number; dTheta4: number } {
  const sin34 = Math.sin(a.theta3 - a.theta4);
  return {
    dTheta3: (l.r2 * Math.sin(a.theta4 - theta2)) / (l.r3 * sin34),
    dTheta4: (l.r2 * Math.sin(theta2 - a.theta3)) / (-l.r4 * sin34),
  };
}

/** Loop-closure residual norm |f| (length unit) of a pose. */
export function loopResidual(l: Linkage, theta2: number, a: Angles): number {
  const f1 = l.r2 * Math.cos(theta2) + l.r3 * Math.cos(a.theta3) - l.r4 * Math.cos(a.theta4) - l.r1;
  const f2 = l.r2 * Math.sin(theta2) + l.r3 * Math.sin(a.theta3) - l.r4 * Math.sin(a.theta4);
  return Math.hypot(f1, f2);
}
