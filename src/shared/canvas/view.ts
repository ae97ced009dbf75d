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
