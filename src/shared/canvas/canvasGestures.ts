import { radToDeg, wrapDeg180, wrapDeg360 } from '../../solver/angles';
import type { LinkageScene } from '../linkage/scene';
import type { ViewTransform } from './view';
import { frameToScreen, toWorld, unplacePoint, zoomAbout } from './view';
import type { CouplerPoint, ViewOffset } from '../state/appState';

/** A point on the canvas in CSS pixels from its top-left corner. */
export interface ScreenPoint {
  x: number;
  y: number;
}

/** What a press on the canvas grabs: the crank pin A, the coupler point P, or nothing (the view pans). */
export type CanvasHandle = 'A' | 'P' | null;

/** Grab radius around a joint, CSS pixels: a fingertip needs more room than a mouse pointer. */
export function grabRadiusPx(pointerType: string): number {
  return pointerType === 'mouse' ? 12 : 24;
}

/**
 * The handle under the pointer at (x, y) CSS pixels: A or P when within radiusPx of it (the nearer one
 * when both are, A on a tie), null when neither is, when there is no pose, or when the handle is not
 * movable (allowed[h] false).
 */
export function hitHandle(
  scene: LinkageScene,
  view: ViewTransform,
  at: ScreenPoint,
  radiusPx: number,
  allowed: { A: boolean; P: boolean },
): CanvasHandle {
  const pose = scene.pose;
  if (!pose) return null;
  const dist = (p: { x: number; y: number }) => {
    const s = frameToScreen(view, p);
    return Math.hypot(s.x - at.x, s.y - at.y);
  };
  const dA = allowed.A ? dist(pose.A) : Infinity;
  const dP = allowed.P ? dist(pose.P) : Infinity;
  if (dA <= radiusPx && dA <= dP) return 'A';
  if (dP <= radiusPx) return 'P';
  return null;
}

/** Decimal places kept for an angle set by dragging, degrees (0.01° is finer than a pixel at any zoom shown). */
const DRAG_ANGLE_DECIMALS = 2;
/** Significant digits kept for a coupler distance set by dragging. */
const DRAG_LENGTH_DIGITS = 4;

function roundTo(x: number, decimals: number): number {
  const k = 10 ** decimals;
  return Math.round(x * k) / k;
}

/**
 * Crank angle theta2 (degrees in [0, 360), 0.01° steps) that puts the crank pin A in the direction of the
 * pointer as seen from O2 (the origin of the linkage's frame, placed by view.frame); null when the pointer is on O2.
 */
export function crankAngleAt(view: ViewTransform, at: ScreenPoint): number | null {
  const w = unplacePoint(view.frame, toWorld(view, at.x, at.y));
  if (w.x === 0 && w.y === 0) return null;
  return wrapDeg360(roundTo(radToDeg(Math.atan2(w.y, w.x)), DRAG_ANGLE_DECIMALS));
}

/**
 * The coupler point that puts P under the pointer: its distance from A (length unit, 4 significant digits)
 * and its angle from the line AB (degrees in (-180, 180], counter-clockwise, 0.01° steps), for the pose
 * on screen. The inverse of couplerPoint: P = A + d (cos(theta3 + a), sin(theta3 + a)).
 */
export function couplerAt(scene: LinkageScene, view: ViewTransform, at: ScreenPoint): CouplerPoint | null {
  const pose = scene.pose;
  if (!pose) return null;
  const w = unplacePoint(view.frame, toWorld(view, at.x, at.y));
  const dx = w.x - pose.A.x;
  const dy = w.y - pose.A.y;
  const distance = Math.hypot(dx, dy);
  if (!Number.isFinite(distance)) return null;
  if (distance === 0) return { distance: 0, angleDeg: 0 };
  const angleDeg = wrapDeg180(roundTo(radToDeg(Math.atan2(dy, dx) - pose.theta3), DRAG_ANGLE_DECIMALS));
  return { distance: Number(distance.toPrecision(DRAG_LENGTH_DIGITS)), angleDeg };
}

/**
 * The view after a two-finger pinch that started with fingers at a0, b0 on view start and now has them at
 * a1, b1 (CSS pixels): zoom by the ratio of the finger distances about the first midpoint, then pan by how
 * far the midpoint moved. The world point under the fingers' midpoint stays under it.
 */
export function pinchView(
  start: ViewOffset,
  a0: ScreenPoint,
  b0: ScreenPoint,
  a1: ScreenPoint,
  b1: ScreenPoint,
  width: number,
  height: number,
): ViewOffset {
  const d0 = Math.hypot(b0.x - a0.x, b0.y - a0.y);
  const d1 = Math.hypot(b1.x - a1.x, b1.y - a1.y);
  const factor = d0 > 0 && d1 > 0 ? d1 / d0 : 1;
  const m0 = { x: (a0.x + b0.x) / 2, y: (a0.y + b0.y) / 2 };
  const m1 = { x: (a1.x + b1.x) / 2, y: (a1.y + b1.y) / 2 };
  const zoomed = zoomAbout(start, factor, m0.x, m0.y, width, height);
  return {
    zoom: zoomed.zoom,
    panX: zoomed.panX + (m1.x - m0.x) / width,
    panY: zoomed.panY + (m1.y - m0.y) / height,
  };
}
