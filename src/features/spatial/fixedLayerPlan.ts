/**
 * When the 3D view may draw its fixed parts from a cached layer (fixedLayer.ts) instead of drawing them again. During
 * Play only the links, pins and fans move; the sphere or floor, the axes, bearings, ground and the paths do not, and
 * under a software WebGL they are most of a frame's cost (docs/benchmarks.md, session 28). The layer is one picture of
 * them for one view: one camera, one drawing buffer, one build of the fixed parts. Pure: no three.js, no DOM.
 */

/** What a frame is drawn for: the camera, the drawing buffer and the fixed parts' build. */
export interface FixedLayerView {
  /** The camera's world matrix then its projection matrix: 32 numbers (three's Matrix4.elements, column-major). */
  camera: readonly number[];
  /** The drawing buffer's size in device pixels. */
  widthPx: number;
  heightPx: number;
  /** Counts the fixed parts' builds (a new linkage, a leaner look): a layer of an older build is stale. */
  build: number;
}

/** How a frame is drawn: everything ('full'), the layer drawn first then used ('build'), or the layer used ('cached'). */
export type FixedLayerPlan = 'full' | 'build' | 'cached';

/** The inputs of planFixedLayer. */
export interface FixedLayerState {
  /** The look caches its fixed parts while moving (RenderQuality.cacheFixedWhileMoving) and the layer works here. */
  enabled: boolean;
  /** The frame is part of a motion (Play, orbit), drawn in the lean look's moving resolution; false at rest. */
  moving: boolean;
  /** The view the layer was drawn for (null: none). */
  cached: FixedLayerView | null;
  /** The view of the frame drawn before this one (null: none). */
  previous: FixedLayerView | null;
  /** This frame's view. */
  now: FixedLayerView;
}

function checkView(v: FixedLayerView, name: string): void {
  if (v.camera.length !== 32) throw new Error(`${name}.camera must hold 32 numbers, got ${v.camera.length}`);
  for (const x of v.camera) if (!Number.isFinite(x)) throw new Error(`${name}.camera must be finite, got ${x}`);
  for (const key of ['widthPx', 'heightPx'] as const) {
    const px = v[key];
    if (!(Number.isInteger(px) && px > 0)) throw new Error(`${name}.${key} must be a positive integer, got ${px}`);
  }
}

/** True when two frames see the fixed parts alike: the same camera (exactly), buffer size and build. */
export function sameFixedView(a: FixedLayerView | null, b: FixedLayerView): boolean {
  if (!a || a.widthPx !== b.widthPx || a.heightPx !== b.heightPx || a.build !== b.build) return false;
  for (let i = 0; i < 32; i++) if (a.camera[i] !== b.camera[i]) return false;
  return true;
}

/**
 * How to draw a frame. At rest, or where the look does not cache: 'full' (the view at rest is drawn as it always was).
 * Moving with a layer for this very view: 'cached'. Moving with the view unchanged since the last frame (Play, the
 * camera still): 'build', so from its second frame Play draws only the moving parts over the layer. Moving with the
 * view changed since the last frame (orbit, zoom, pan; or Play's first frame at the moving resolution): 'full', since a
 * layer drawn for a view that changes every frame would cost more than it saves. Throws on a view whose camera is not
 * 32 finite numbers or whose size is not positive whole pixels.
 */
export function planFixedLayer(s: FixedLayerState): FixedLayerPlan {
  checkView(s.now, 'now');
  if (!s.enabled || !s.moving) return 'full';
  if (sameFixedView(s.cached, s.now)) return 'cached';
  return sameFixedView(s.previous, s.now) ? 'build' : 'full';
}
