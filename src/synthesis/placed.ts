import { solveClosedForm, validateLinkage, wrapAngle } from '../solver';
import type { Branch, Point } from '../solver';
import type { PlacedFourBar, PlacedJoints } from './types';
import { checkFiniteNumber, checkPoint, show } from './validate';

/** Throws unless d is a placed four-bar: positive links, a branch, a finite O2, ground angle, pDist and pAngle. */
export function checkPlaced(name: string, d: unknown): asserts d is PlacedFourBar {
  if (typeof d !== 'object' || d === null) throw new Error(`${name} must be a placed four-bar, got ${show(d)}`);
  const r = d as Record<string, unknown>;
  validateLinkage(r.links);
  if (r.branch !== 'open' && r.branch !== 'crossed') {
    throw new Error(`${name}.branch must be 'open' or 'crossed', got ${show(r.branch)}`);
  }
  checkPoint(`${name}.O2`, r.O2);
  checkFiniteNumber(`${name}.groundAngle`, r.groundAngle, 'angle in radians');
  checkFiniteNumber(`${name}.pDist`, r.pDist, 'length');
  checkFiniteNumber(`${name}.pAngle`, r.pAngle, 'angle in radians');
}

/**
 * Joints and coupler point of a placed four-bar at θ2 (radians, from its ground line) on its branch, in the
 * task's plane; null where the loop cannot close. Throws for a design that is not a placed four-bar.
 */
export function placedJoints(d: PlacedFourBar, theta2: number): PlacedJoints | null {
  checkPlaced('design', d);
  checkFiniteNumber('theta2', theta2, 'angle in radians');
  const a = solveClosedForm(d.links, theta2, d.branch);
  if (!a) return null;
  const g = d.groundAngle;
  const cg = Math.cos(g);
  const sg = Math.sin(g);
  const local = (x: number, y: number): Point => ({ x: d.O2.x + cg * x - sg * y, y: d.O2.y + sg * x + cg * y });
  const ax = d.links.r2 * Math.cos(theta2);
  const ay = d.links.r2 * Math.sin(theta2);
  const bx = ax + d.links.r3 * Math.cos(a.theta3);
  const by = ay + d.links.r3 * Math.sin(a.theta3);
  const px = ax + d.pDist * Math.cos(a.theta3 + d.pAngle);
  const py = ay + d.pDist * Math.sin(a.theta3 + d.pAngle);
  return {
    O2: { x: d.O2.x, y: d.O2.y },
    A: local(ax, ay),
    B: local(bx, by),
    O4: local(d.links.r1, 0),
    P: local(px, py),
    theta3: a.theta3 + g,
    theta4: a.theta4 + g,
  };
}

/** The coupler point P of a placed four-bar at θ2 (radians), or null where it cannot assemble. */
export function placedCouplerPoint(d: PlacedFourBar, theta2: number): Point | null {
  return placedJoints(d, theta2)?.P ?? null;
}

/**
 * The placed four-bar whose joints sit at O2, A, B, O4 (and coupler point P) in one pose, with the θ2 of that pose
 * (radians, from the ground line O2→O4). The branch is read from the pose: open when B lies left of the ray A→O4.
 * Throws when two pivots coincide (a link of zero length) or a point is not finite.
 */
export function fourBarFromJoints(joints: { O2: Point; A: Point; B: Point; O4: Point; P: Point }): {
  design: PlacedFourBar;
  theta2: number;
} {
  const { O2, A, B, O4, P } = joints;
  for (const k of ['O2', 'A', 'B', 'O4', 'P'] as const) checkPoint(k, joints[k]);
  const r1 = Math.hypot(O4.x - O2.x, O4.y - O2.y);
  const r2 = Math.hypot(A.x - O2.x, A.y - O2.y);
  const r3 = Math.hypot(B.x - A.x, B.y - A.y);
  const r4 = Math.hypot(B.x - O4.x, B.y - O4.y);
  const names = { r1: 'O2 and O4', r2: 'O2 and A', r3: 'A and B', r4: 'O4 and B' };
  const links = { r1, r2, r3, r4 };
  for (const k of ['r1', 'r2', 'r3', 'r4'] as const) {
    if (!(links[k] > 0) || !Number.isFinite(links[k])) {
      throw new Error(`${names[k]} coincide: ${k} would be ${show(links[k])}`);
    }
  }
  const groundAngle = Math.atan2(O4.y - O2.y, O4.x - O2.x);
  const theta3 = Math.atan2(B.y - A.y, B.x - A.x);
  const pDist = Math.hypot(P.x - A.x, P.y - A.y);
  const pAngle = pDist === 0 ? 0 : Math.atan2(P.y - A.y, P.x - A.x) - theta3;
  // Open: B left of the ray A→O4, i.e. cross(O4 - A, B - A) > 0 (the solver's sin(θ4 − θ3) > 0).
  const cross = (O4.x - A.x) * (B.y - A.y) - (O4.y - A.y) * (B.x - A.x);
  const branch: Branch = cross >= 0 ? 'open' : 'crossed';
  const theta2 = Math.atan2(A.y - O2.y, A.x - O2.x) - groundAngle;
  return {
    design: { links, branch, O2: { x: O2.x, y: O2.y }, groundAngle, pDist, pAngle: wrapAngle(pAngle) },
    theta2: wrapAngle(theta2),
  };
}
