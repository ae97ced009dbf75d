import type { PoseDeg } from '../../../../src/shared/state/slices/synMotionSlice';

/** A point of the plane. */
export interface P2 {
  x: number;
  y: number;
}

/**
 * A known crank-rocker described independently of src/synthesis: fixed pivots O2, O4, moving pivots a, b in the
 * coupler frame (origin at the pose point), crank r2 and rocker r4 (r1 = |O2 O4| = 2.22, r3 = |b − a| = 1.60:
 * S + L = 2.77 < P + Q = 3.05, crank shortest), on the open branch (B left of the ray A→O4).
 */
export const KNOWN = {
  O2: { x: -1, y: -1.2 },
  O4: { x: 1.2, y: -0.9 },
  a: { x: -0.7, y: -0.5 },
  b: { x: 0.9, y: -0.6 },
  r2: 0.55,
  r4: 1.45,
};

/** The coupler pose at crank angle t (radians from +x), by circle intersection: its point and frame angle (degrees). */
export function knownPose(t: number): PoseDeg {
  const { O2, O4, a, b, r2, r4 } = KNOWN;
  const r3 = Math.hypot(b.x - a.x, b.y - a.y);
  const A = { x: O2.x + r2 * Math.cos(t), y: O2.y + r2 * Math.sin(t) };
  const d = Math.hypot(O4.x - A.x, O4.y - A.y);
  const along = (d * d + r3 * r3 - r4 * r4) / (2 * d);
  const h = Math.sqrt(r3 * r3 - along * along);
  const ux = (O4.x - A.x) / d;
  const uy = (O4.y - A.y) / d;
  // Open branch: B to the left of A→O4.
  const B = { x: A.x + along * ux - h * uy, y: A.y + along * uy + h * ux };
  const phi = Math.atan2(B.y - A.y, B.x - A.x) - Math.atan2(b.y - a.y, b.x - a.x);
  const P = {
    x: A.x - (Math.cos(phi) * a.x - Math.sin(phi) * a.y),
    y: A.y - (Math.sin(phi) * a.x + Math.cos(phi) * a.y),
  };
  return { x: P.x, y: P.y, angleDeg: (phi * 180) / Math.PI };
}

/** A plane point given in a pose's frame. */
export function inPlane(pose: PoseDeg, q: P2): P2 {
  const t = (pose.angleDeg * Math.PI) / 180;
  return { x: pose.x + Math.cos(t) * q.x - Math.sin(t) * q.y, y: pose.y + Math.sin(t) * q.x + Math.cos(t) * q.y };
}
