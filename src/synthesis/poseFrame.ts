/**
 * The coupler frame of a pose (origin at the pose's point, axes turned by its angle) and the circle through three
 * points: the two constructions motion generation is built from.
 */
import type { Point } from '../solver';
import type { Pose } from './types';

/** A point given in the pose's coupler frame, in the plane (length unit). */
export function toPlane(pose: Pose, q: Point): Point {
  const c = Math.cos(pose.angle);
  const s = Math.sin(pose.angle);
  return { x: pose.x + c * q.x - s * q.y, y: pose.y + s * q.x + c * q.y };
}

/** A point of the plane, in the pose's coupler frame (length unit). */
export function toFrame(pose: Pose, p: Point): Point {
  const c = Math.cos(pose.angle);
  const s = Math.sin(pose.angle);
  const dx = p.x - pose.x;
  const dy = p.y - pose.y;
  return { x: c * dx + s * dy, y: -s * dx + c * dy };
}

/**
 * Centre of the circle through a, b and c, or null when they are collinear or two coincide (to within 1e-12 of
 * the triangle's size squared). Computed relative to a, so far-away points lose nothing to their offset.
 */
export function circumcentre(a: Point, b: Point, c: Point): Point | null {
  const bx = b.x - a.x;
  const by = b.y - a.y;
  const cx = c.x - a.x;
  const cy = c.y - a.y;
  const d = 2 * (bx * cy - by * cx);
  const b2 = bx * bx + by * by;
  const c2 = cx * cx + cy * cy;
  if (!(Math.abs(d) > 1e-12 * Math.max(b2, c2, (bx - cx) ** 2 + (by - cy) ** 2))) return null;
  return { x: a.x + (cy * b2 - by * c2) / d, y: a.y + (bx * c2 - cx * b2) / d };
}
