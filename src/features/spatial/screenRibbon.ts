/**
 * A line of constant width on screen drawn as a plain triangle strip: for each point of a polyline, two vertices
 * offset across it, perpendicular to the line and to the view, by half the width in scene units at that point's depth.
 * three's Line2 does the same in its vertex shader per segment instance, which under a software WebGL costs far more
 * than this loop over a few dozen points on the page (docs/benchmarks.md, Spatial). Pure: no three.js, no DOM.
 */

/** Where the view is: the camera's position and unit forward axis, its kind, and its scene units per pixel. */
export interface RibbonView {
  eye: readonly [x: number, y: number, z: number];
  /** The camera's viewing direction (unit). */
  forward: readonly [x: number, y: number, z: number];
  perspective: boolean;
  /**
   * Scene units per pixel: at unit depth for a perspective view (2·tan(fov/2) / (height px · zoom)), everywhere for an
   * orthographic one ((top − bottom) / (height px · zoom)).
   */
  unitsPerPx: number;
}

/** Vertex count of a ribbon over `count` points (two per point). */
export const ribbonVertexCount = (count: number): number => 2 * count;

/** Triangle indices of a ribbon over `count` points: two triangles per segment. */
export function ribbonIndex(count: number): number[] {
  const index: number[] = [];
  for (let i = 0; i + 1 < count; i++) index.push(2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 1, 2 * i + 3, 2 * i + 2);
  return index;
}

/**
 * Writes the ribbon of `count` points (x y z flat in points) into out (6·count numbers: the two sides of each point),
 * widthPx wide on screen. A point whose tangent lies along the view keeps the side of the point before it. Throws on a
 * width that is not a positive finite number or buffers too short for count.
 */
export function ribbonInto(
  out: Float32Array,
  points: Float32Array,
  count: number,
  view: RibbonView,
  widthPx: number,
): void {
  if (!(Number.isFinite(widthPx) && widthPx > 0))
    throw new Error(`widthPx must be a positive finite number, got ${widthPx}`);
  if (points.length < 3 * count || out.length < 6 * count)
    throw new Error(`ribbonInto needs ${3 * count} point and ${6 * count} vertex numbers for count ${count}`);
  const [ex, ey, ez] = view.eye;
  const [fx, fy, fz] = view.forward;
  let sx = 0;
  let sy = 0;
  let sz = 0;
  for (let i = 0; i < count; i++) {
    const a = 3 * Math.max(0, i - 1);
    const b = 3 * Math.min(count - 1, i + 1);
    const tx = points[b] - points[a];
    const ty = points[b + 1] - points[a + 1];
    const tz = points[b + 2] - points[a + 2];
    const px = points[3 * i];
    const py = points[3 * i + 1];
    const pz = points[3 * i + 2];
    // Towards the eye: from the point (perspective) or against the forward axis (orthographic).
    const vx = view.perspective ? ex - px : -fx;
    const vy = view.perspective ? ey - py : -fy;
    const vz = view.perspective ? ez - pz : -fz;
    const cx = ty * vz - tz * vy;
    const cy = tz * vx - tx * vz;
    const cz = tx * vy - ty * vx;
    const len = Math.hypot(cx, cy, cz);
    if (len > 1e-12) {
      sx = cx / len;
      sy = cy / len;
      sz = cz / len;
    }
    const depth = view.perspective ? Math.max(1e-6, (px - ex) * fx + (py - ey) * fy + (pz - ez) * fz) : 1;
    const half = 0.5 * widthPx * view.unitsPerPx * depth;
    const o = 6 * i;
    out[o] = px + half * sx;
    out[o + 1] = py + half * sy;
    out[o + 2] = pz + half * sz;
    out[o + 3] = px - half * sx;
    out[o + 4] = py - half * sy;
    out[o + 5] = pz - half * sz;
  }
}
