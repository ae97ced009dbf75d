/**
 * Fixtures for the function- and motion-generation tests: a seeded generator, random designs, and poses and pins
 * computed from the 60-digit oracle's angles (tests/oracle/reference.ts), so the data a synthesis is given does not
 * come from the solver it is checked against.
 */
import type { Branch, Linkage, Point } from '../../src/solver';
import { classify } from '../../src/solver';
import type { PlacedFourBar, Pose } from '../../src/synthesis';
import { referenceAngles } from '../oracle/reference';

/** Mulberry32: a small seeded generator, uniform in [0, 1). */
export function seeded(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** +1 open, −1 crossed, as the oracle takes it. */
export const sigmaOf = (b: Branch): 1 | -1 => (b === 'open' ? 1 : -1);

/** A random Grashof crank-rocker (crank shortest, S + L clearly below P + Q) with comparable links. */
export function randomCrankRocker(rnd: () => number): Linkage {
  for (;;) {
    const l = { r1: 2 + 2 * rnd(), r2: 0.5 + 0.7 * rnd(), r3: 2 + 2 * rnd(), r4: 1.5 + 2 * rnd() };
    const c = classify(l);
    if (c.type === 'crank-rocker' && c.S + c.L < 0.9 * (c.P + c.Q)) return l;
  }
}

/** A random placed design around the origin with a random coupler point. */
export function randomPlaced(rnd: () => number, links: Linkage, branch: Branch): PlacedFourBar {
  return {
    links,
    branch,
    O2: { x: 2 * rnd() - 1, y: 2 * rnd() - 1 },
    groundAngle: 6 * rnd() - 3,
    pDist: 0.5 + 2 * rnd(),
    pAngle: 6 * rnd() - 3,
  };
}

/** Pins, coupler point and coupler pose of a placed design at θ2 (radians) on a branch, from the oracle's θ3. */
export function oraclePose(
  d: PlacedFourBar,
  theta2: number,
  branch: Branch = d.branch,
): { A: Point; B: Point; O4: Point; pose: Pose } {
  const ref = referenceAngles(d.links, theta2, sigmaOf(branch));
  if (!ref) throw new Error(`fixture: the design does not assemble at θ2 = ${theta2}`);
  const g = d.groundAngle;
  const place = (x: number, y: number): Point => ({
    x: d.O2.x + Math.cos(g) * x - Math.sin(g) * y,
    y: d.O2.y + Math.sin(g) * x + Math.cos(g) * y,
  });
  const { r1, r2, r3 } = d.links;
  const ax = r2 * Math.cos(theta2);
  const ay = r2 * Math.sin(theta2);
  const A = place(ax, ay);
  const B = place(ax + r3 * Math.cos(ref.theta3), ay + r3 * Math.sin(ref.theta3));
  const P = place(ax + d.pDist * Math.cos(ref.theta3 + d.pAngle), ay + d.pDist * Math.sin(ref.theta3 + d.pAngle));
  // The coupler frame: origin at P, turned with the coupler (θ3 in the plane).
  return { A, B, O4: place(r1, 0), pose: { x: P.x, y: P.y, angle: ref.theta3 + g } };
}

/** A point of the plane in a pose's coupler frame (written out here, independent of src/synthesis/poseFrame.ts). */
export function inFrame(pose: Pose, p: Point): Point {
  const dx = p.x - pose.x;
  const dy = p.y - pose.y;
  return {
    x: Math.cos(pose.angle) * dx + Math.sin(pose.angle) * dy,
    y: -Math.sin(pose.angle) * dx + Math.cos(pose.angle) * dy,
  };
}

/** Distance between two points. */
export const dist = (p: Point, q: Point): number => Math.hypot(p.x - q.x, p.y - q.y);
