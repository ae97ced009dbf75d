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

/** True when a and b share interior area (touching edges do not count). */
export function rectsOverlap(a: ScreenRect, b: ScreenRect): boolean {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

/** True when inner lies entirely within outer (edges may touch). */
export function rectInside(inner: ScreenRect, outer: ScreenRect): boolean {
  return (
    inner.x >= outer.x &&
    inner.y >= outer.y &&
    inner.x + inner.width <= outer.x + outer.width &&
    inner.y + inner.height <= outer.y + outer.height
  );
}

/** The rectangle of width x height centred on c. */
export function rectAround(c: Px, width: number, height: number): ScreenRect {
  return { x: c.x - width / 2, y: c.y - height / 2, width, height };
}

/** r grown by d on every side (shrunk for negative d). */
export function inflateRect(r: ScreenRect, d: number): ScreenRect {
  return { x: r.x - d, y: r.y - d, width: r.width + 2 * d, height: r.height + 2 * d };
}

/**
 * True when the segment a-b passes through the interior of r (Liang-Barsky clipping of the segment's
 * parameter interval against the four slabs).
 */
export function segmentHitsRect(a: Px, b: Px, r: ScreenRect): boolean {
  let t0 = 0;
  let t1 = 1;
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const slabs: [number, number][] = [
    [-dx, a.x - r.x],
    [dx, r.x + r.width - a.x],
    [-dy, a.y - r.y],
    [dy, r.y + r.height - a.y],
  ];
  for (const [p, q] of slabs) {
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
