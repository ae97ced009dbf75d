import type { ViewOffset } from '../state/appState';

/** Axis-aligned box in world (length) units. */
export interface Bounds {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/** Maps world coordinates (length unit, y up) to CSS pixels (y down) of a view width x height. */
export interface ViewTransform {
  width: number;
  height: number;
  /** CSS pixels per length unit. */
  scale: number;
  /** World point drawn at the centre of the view before panning. */
  centerX: number;
  centerY: number;
  /** Pan in CSS pixels. */
  panXPx: number;
  panYPx: number;
  /** Where the linkage's own frame (O2 at its origin, ground along its +x) sits in the world; absent: the world's. */
  frame?: PlacementTransform;
}

/** A rigid placement of the linkage's frame in the world: its origin and the cosine and sine of its rotation. */
export interface PlacementTransform {
  x: number;
  y: number;
  cos: number;
  sin: number;
}

/** The frame with origin (x, y) turned by angleRad; undefined for the identity (nothing to transform). */
export function placementTransform(x: number, y: number, angleRad: number): PlacementTransform | undefined {
  if (x === 0 && y === 0 && angleRad === 0) return undefined;
  return { x, y, cos: Math.cos(angleRad), sin: Math.sin(angleRad) };
}

/** The view's frame rotation (radians; 0 without a frame): add it to an angle of the linkage's frame. */
export function frameAngle(v: ViewTransform): number {
  return v.frame ? Math.atan2(v.frame.sin, v.frame.cos) : 0;
}

/** A point of the linkage's frame in world coordinates (unchanged without a frame). */
export function placePoint(f: PlacementTransform | undefined, p: { x: number; y: number }): { x: number; y: number } {
  if (!f) return p;
  return { x: f.x + f.cos * p.x - f.sin * p.y, y: f.y + f.sin * p.x + f.cos * p.y };
}

/** A world point in the linkage's frame (the inverse of placePoint). */
export function unplacePoint(f: PlacementTransform | undefined, p: { x: number; y: number }): { x: number; y: number } {
  if (!f) return p;
  const dx = p.x - f.x;
  const dy = p.y - f.y;
  return { x: f.cos * dx + f.sin * dy, y: -f.sin * dx + f.cos * dy };
}

/** A point of the linkage's frame (length unit) to CSS pixels through the view's frame. */
export function frameToScreen(v: ViewTransform, p: { x: number; y: number }): { x: number; y: number } {
  const w = placePoint(v.frame, p);
  return { x: toScreenX(v, w.x), y: toScreenY(v, w.y) };
}

/** The world box holding bounds given in a frame (its four corners placed). */
export function placeBounds(b: Bounds, f: PlacementTransform | undefined): Bounds {
  if (!f) return { ...b };
  const out = emptyBounds();
  for (const [x, y] of [
    [b.minX, b.minY],
    [b.maxX, b.minY],
    [b.minX, b.maxY],
    [b.maxX, b.maxY],
  ]) {
    const w = placePoint(f, { x, y });
    extendBounds(out, w.x, w.y);
  }
  return out;
}

/** Empty bounds (to grow with extendBounds). */
export function emptyBounds(): Bounds {
  return { minX: Infinity, minY: Infinity, maxX: -Infinity, maxY: -Infinity };
}

/** Grows b in place to include (x, y); ignores non-finite points. */
export function extendBounds(b: Bounds, x: number, y: number): void {
  if (!Number.isFinite(x) || !Number.isFinite(y)) return;
  if (x < b.minX) b.minX = x;
  if (x > b.maxX) b.maxX = x;
  if (y < b.minY) b.minY = y;
  if (y > b.maxY) b.maxY = y;
}

/** Grows b in place to include a circle of radius r (length unit) about (x, y). */
export function extendBoundsCircle(b: Bounds, x: number, y: number, r: number): void {
  extendBounds(b, x - r, y - r);
  extendBounds(b, x + r, y + r);
}

/** Least margin (CSS pixels) fitView leaves around the bounds: room for the widest angle arc (34 px) at a pivot. */
export const FIT_MIN_PAD_PX = 40;

/**
 * Fits bounds into a width x height view (CSS pixels) with a margin (fraction of the smaller side,
 * default 0.08, but at least FIT_MIN_PAD_PX, or a quarter of the smaller side in a tiny view) and applies
 * the user's zoom and pan. Works at any scale: lengths of 1e-7 or 1e7 give the same picture. Degenerate
 * bounds (a point, or nothing) get a unit box around them.
 */
export function fitView(
  bounds: Bounds,
  width: number,
  height: number,
  offset: ViewOffset,
  margin = 0.08,
): ViewTransform {
  let { minX, minY, maxX, maxY } = bounds;
  if (!(minX <= maxX && minY <= maxY)) {
    minX = -1;
    minY = -1;
    maxX = 1;
    maxY = 1;
  }
  let spanX = maxX - minX;
  let spanY = maxY - minY;
  const span = Math.max(spanX, spanY);
  const minSpan =
    span > 0 ? span * 1e-3 : Math.max(Math.abs(minX), Math.abs(maxX), Math.abs(minY), Math.abs(maxY)) || 1;
  spanX = Math.max(spanX, minSpan);
  spanY = Math.max(spanY, minSpan);
  const w = Math.max(1, width);
  const h = Math.max(1, height);
  const pad = Math.max(Math.min(w, h) * margin, Math.min(FIT_MIN_PAD_PX, Math.min(w, h) / 4));
  const fit = Math.min((w - 2 * pad) / spanX, (h - 2 * pad) / spanY);
  const scale = (Number.isFinite(fit) && fit > 0 ? fit : 1) * offset.zoom;
  return {
    width: w,
    height: h,
    scale,
    centerX: (minX + maxX) / 2,
    centerY: (minY + maxY) / 2,
    panXPx: offset.panX * w,
    panYPx: offset.panY * h,
  };
}

/** World x (length unit) to CSS pixels. */
export function toScreenX(v: ViewTransform, x: number): number {
  return v.width / 2 + (x - v.centerX) * v.scale + v.panXPx;
}

/** World y (length unit, up) to CSS pixels (down). */
export function toScreenY(v: ViewTransform, y: number): number {
  return v.height / 2 - (y - v.centerY) * v.scale + v.panYPx;
}

/** CSS pixel position back to world coordinates (length unit). */
export function toWorld(v: ViewTransform, sx: number, sy: number): { x: number; y: number } {
  return {
    x: v.centerX + (sx - v.width / 2 - v.panXPx) / v.scale,
    y: v.centerY - (sy - v.height / 2 - v.panYPx) / v.scale,
  };
}

/** New offset after zooming by factor about the CSS pixel (cx, cy): the world point under it stays put. */
export function zoomAbout(
  offset: ViewOffset,
  factor: number,
  cx: number,
  cy: number,
  width: number,
  height: number,
): ViewOffset {
  const zoom = Math.min(1e3, Math.max(1e-3, offset.zoom * factor));
  const f = zoom / offset.zoom;
  const dx = cx - width / 2;
  const dy = cy - height / 2;
  return {
    zoom,
    panX: (dx - f * (dx - offset.panX * width)) / width,
    panY: (dy - f * (dy - offset.panY * height)) / height,
  };
}

/** A round grid spacing (1, 2 or 5 times a power of ten, length unit) giving about target pixels between lines. */
export function niceStep(scale: number, targetPx = 60): number {
  const raw = targetPx / scale;
  if (!(raw > 0) || !Number.isFinite(raw)) return 1;
  const p = 10 ** Math.floor(Math.log10(raw));
  const m = raw / p;
  const k = m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10;
  return k * p;
}

/** The grid drawn under the linkage: its spacing (length unit) and the index range of lines in view. */
export interface GridLines {
  step: number;
  i0: number;
  i1: number;
  j0: number;
  j1: number;
}

/** Grid lines about targetPx apart (default 64) covering the view; null when there would be over 400 in a direction. */
export function gridLines(v: ViewTransform, targetPx = 64): GridLines | null {
  const step = niceStep(v.scale, targetPx);
  const tl = toWorld(v, 0, 0);
  const br = toWorld(v, v.width, v.height);
  const g = {
    step,
    i0: Math.ceil(tl.x / step),
    i1: Math.floor(br.x / step),
    j0: Math.ceil(br.y / step),
    j1: Math.floor(tl.y / step),
  };
  if (g.i1 - g.i0 > 400 || g.j1 - g.j0 > 400) return null;
  return g;
}
