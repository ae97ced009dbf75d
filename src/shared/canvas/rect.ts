/** A point in CSS pixels of the canvas (x right, y down). */
export interface Px {
  x: number;
  y: number;
}

/** An axis-aligned rectangle in CSS pixels of the canvas: top-left corner, width and height. */
export interface ScreenRect {
  x: number;
  y: number;
  width: number;
  height: number;
}

/** The rectangle of width x height centred on c. */
export function rectAround(c: Px, width: number, height: number): ScreenRect {
  return { x: c.x - width / 2, y: c.y - height / 2, width, height };
}

/**
 * True when the segment (ax, ay)-(bx, by) passes through the interior of the box with corners (x0, y0) and
 * (x1, y1): Liang-Barsky clipping of the segment's parameter interval against the four slabs.
 */
export function segmentHitsBox(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  x0: number,
  y0: number,
  x1: number,
  y1: number,
): boolean {
  // Quick rejection by the segment's own bounding box.
  if ((ax > bx ? ax : bx) <= x0 || (ax < bx ? ax : bx) >= x1 || (ay > by ? ay : by) <= y0 || (ay < by ? ay : by) >= y1)
    return false;
  const dx = bx - ax;
  const dy = by - ay;
  let t0 = 0;
  let t1 = 1;
  const ps = [-dx, dx, -dy, dy];
  const qs = [ax - x0, x1 - ax, ay - y0, y1 - ay];
  for (let k = 0; k < 4; k++) {
    const p = ps[k];
    const q = qs[k];
    if (p === 0) {
      if (q <= 0) return false;
      continue;
    }
    const t = q / p;
    if (p < 0) {
      if (t > t1) return false;
      if (t > t0) t0 = t;
    } else {
      if (t < t0) return false;
      if (t < t1) t1 = t;
    }
  }
  return t0 < t1;
}

/**
 * Distance from the centre of a width x height rectangle to its edge along the unit direction u: how far
 * to push a label's centre along u so its box just clears a point.
 */
export function halfExtentAlong(ux: number, uy: number, width: number, height: number): number {
  const ax = Math.abs(ux);
  const ay = Math.abs(uy);
  const tx = ax > 1e-12 ? width / 2 / ax : Infinity;
  const ty = ay > 1e-12 ? height / 2 / ay : Infinity;
  return Math.min(tx, ty);
}
