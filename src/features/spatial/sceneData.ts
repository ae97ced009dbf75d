import { COLORS } from '../../shared/theme/tokens';
import type { SpatialModel, SpatialSweep, Vec3 } from '../../spatial';

/** An axis of the ground drawn as a line, with a bearing (the ground symbol) centred at `bearing`. */
export interface SceneAxis {
  from: Vec3;
  to: Vec3;
  bearing: Vec3;
}

/** A dashed path (x y z flat, pairs of points: one segment each). */
export interface ScenePath {
  color: string;
  segments: number[];
}

/**
 * The fixed parts of the 3D view in scene units (the unit sphere; an RSSR scaled by `scale` so its size is about 1):
 * the pivots the crank and rocker turn about, the axes and bearings, the ground link, the coupler curve and the pins'
 * paths (segments), a floor height for an RSSR, and the view's fit (centre, radius). Pure data, no three.js.
 */
export interface SceneLinkage {
  kind: 'spherical' | 'rssr';
  /** Scene units per length unit of the linkage (1 for the unit sphere). */
  scale: number;
  crankPivot: Vec3;
  rockerPivot: Vec3;
  axes: SceneAxis[];
  ground: number[];
  groundPins: Vec3[];
  curve: number[];
  paths: ScenePath[];
  floorZ: number | null;
  centre: Vec3;
  radius: number;
  /** Pin radius in scene units. */
  pinRadius: number;
  /** Direction from the view's centre to the first camera (unit). */
  viewDir: Vec3;
}

/** The moving pins in scene units. */
export interface ScenePose {
  A: Vec3;
  B: Vec3;
  P?: Vec3;
}

const vec = (x: number, y: number, z: number): Vec3 => ({ x, y, z });
const scaled = (p: Vec3, s: number): Vec3 => vec(p.x * s, p.y * s, p.z * s);
const unit = (p: Vec3): Vec3 => scaled(p, 1 / Math.hypot(p.x, p.y, p.z));

/** Segments (pairs of points) between consecutive valid samples of an interleaved x y z column, scaled. */
export function pathSegments(xyz: Float64Array, valid: Uint8Array, s: number): number[] {
  const out: number[] = [];
  for (let i = 0; i + 1 < valid.length; i++) {
    if (!valid[i] || !valid[i + 1]) continue;
    const a = 3 * i;
    const b = a + 3;
    if (!Number.isFinite(xyz[a]) || !Number.isFinite(xyz[b])) continue;
    out.push(xyz[a] * s, xyz[a + 1] * s, xyz[a + 2] * s, xyz[b] * s, xyz[b + 1] * s, xyz[b + 2] * s);
  }
  return out;
}

/**
 * Points along the shorter great-circle arc from p to q on the unit sphere (x y z flat, `steps` segments); the
 * straight chord when they are antipodal or equal within rounding.
 */
export function arcPoints(p: Vec3, q: Vec3, steps = 32): number[] {
  const out = new Array<number>(3 * (steps + 1));
  arcPointsInto(out, p, q, steps);
  return out;
}

/**
 * arcPoints written into out (3 (steps + 1) numbers from offset 0), allocating nothing: the 3D view's moving links,
 * every frame of Play.
 */
export function arcPointsInto(out: Float32Array | number[], p: Vec3, q: Vec3, steps: number): void {
  const dot = Math.min(1, Math.max(-1, p.x * q.x + p.y * q.y + p.z * q.z));
  const angle = Math.acos(dot);
  const s = Math.sin(angle);
  for (let i = 0; i <= steps; i++) {
    const t = i / steps;
    let a = 1 - t;
    let b = t;
    if (s > 1e-9) {
      a = Math.sin((1 - t) * angle) / s;
      b = Math.sin(t * angle) / s;
    }
    out[3 * i] = a * p.x + b * q.x;
    out[3 * i + 1] = a * p.y + b * q.y;
    out[3 * i + 2] = a * p.z + b * q.z;
  }
}

/** The straight segment from p to q as steps + 1 points into out (an RSSR's rods on the same buffers as arcs). */
export function chordPointsInto(out: Float32Array, p: Vec3, q: Vec3, steps: number): void {
  for (let i = 0; i <= steps; i++) {
    const t = i / steps;
    out[3 * i] = p.x + t * (q.x - p.x);
    out[3 * i + 1] = p.y + t * (q.y - p.y);
    out[3 * i + 2] = p.z + t * (q.z - p.z);
  }
}

/** The view's fit: centre and radius of everything drawn. */
export function sceneBounds(l: SceneLinkage): { centre: Vec3; radius: number } {
  return { centre: l.centre, radius: l.radius };
}

/** The fixed parts of the 3D view of a model and its sweep over a turn (see SceneLinkage). */
export function sceneLinkage(model: SpatialModel, sweep: SpatialSweep): SceneLinkage {
  if (model.kind === 'spherical') {
    const { a1 } = model.linkage;
    const O2 = vec(0, 0, 1);
    const O4 = vec(Math.sin(a1), 0, Math.cos(a1));
    const axis = (o: Vec3): SceneAxis => ({ from: scaled(o, -0.15), to: scaled(o, 1.32), bearing: scaled(o, 1.08) });
    return {
      kind: 'spherical',
      scale: 1,
      crankPivot: O2,
      rockerPivot: O4,
      axes: [axis(O2), axis(O4)],
      ground: arcPoints(O2, O4),
      groundPins: [O2, O4],
      curve: sweep.P ? pathSegments(sweep.P, sweep.valid, 1) : [],
      paths: [
        { color: COLORS.crank, segments: pathSegments(sweep.A, sweep.valid, 1) },
        { color: COLORS.rocker, segments: pathSegments(sweep.B, sweep.valid, 1) },
      ],
      floorZ: null,
      centre: vec(0, 0, 0),
      radius: 1.35,
      pinRadius: 0.04,
      // Towards the ground arc's middle, turned aside and raised a little: the linkage faces the camera.
      viewDir: unit(vec(Math.sin(a1 / 2) + 0.55, -0.95, Math.cos(a1 / 2) + 0.45)),
    };
  }
  const { r2, r3, r4, a, beta, h2, h4 } = model.linkage;
  const w = vec(0, -Math.sin(beta), Math.cos(beta));
  const size = Math.max(a + r4 + Math.abs(h4), r2 + Math.abs(h2), r3, 1e-300);
  const s = 1 / size;
  const foot2 = vec(0, 0, h2 * s);
  const c4 = vec(a * s, 0, 0);
  const foot4 = vec(c4.x + h4 * w.x * s, c4.y + h4 * w.y * s, c4.z + h4 * w.z * s);
  // Axis lines: through the origin of each axis and past the pin's foot by a margin.
  const m = 0.35;
  const z0 = Math.min(0, h2 * s) - m;
  const z1 = Math.max(0, h2 * s) + m;
  const t0 = Math.min(0, h4 * s) - m;
  const t1 = Math.max(0, h4 * s) + m;
  const along = (t: number) => vec(c4.x + t * w.x, c4.y + t * w.y, c4.z + t * w.z);
  const pts: Vec3[] = [vec(0, 0, z0), vec(0, 0, z1), along(t0), along(t1)];
  for (let i = 0; i < sweep.valid.length; i++) {
    if (!sweep.valid[i]) continue;
    pts.push(scaled(vec(sweep.A[3 * i], sweep.A[3 * i + 1], sweep.A[3 * i + 2]), s));
    pts.push(scaled(vec(sweep.B[3 * i], sweep.B[3 * i + 1], sweep.B[3 * i + 2]), s));
  }
  const lo = vec(Infinity, Infinity, Infinity);
  const hi = vec(-Infinity, -Infinity, -Infinity);
  for (const p of pts) {
    lo.x = Math.min(lo.x, p.x);
    lo.y = Math.min(lo.y, p.y);
    lo.z = Math.min(lo.z, p.z);
    hi.x = Math.max(hi.x, p.x);
    hi.y = Math.max(hi.y, p.y);
    hi.z = Math.max(hi.z, p.z);
  }
  const centre = vec((lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2);
  const radius = Math.max(0.5, Math.hypot(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z) / 2) * 1.08;
  return {
    kind: 'rssr',
    scale: s,
    crankPivot: foot2,
    rockerPivot: foot4,
    axes: [
      { from: vec(0, 0, z0), to: vec(0, 0, z1), bearing: foot2 },
      { from: along(t0), to: along(t1), bearing: foot4 },
    ],
    ground: [0, 0, 0, c4.x, c4.y, c4.z],
    groundPins: [vec(0, 0, 0), c4],
    curve: [],
    paths: [
      { color: COLORS.crank, segments: pathSegments(sweep.A, sweep.valid, s) },
      { color: COLORS.rocker, segments: pathSegments(sweep.B, sweep.valid, s) },
    ],
    floorZ: lo.z - 0.05,
    centre,
    radius,
    pinRadius: 0.035,
    viewDir: unit(vec(0.9, -2.0, 1.1)),
  };
}

/** The pins of a pose in scene units. */
export function scenePose(l: SceneLinkage, pose: { A: Vec3; B: Vec3; P?: Vec3 }): ScenePose {
  const s = l.scale;
  return { A: scaled(pose.A, s), B: scaled(pose.B, s), ...(pose.P ? { P: scaled(pose.P, s) } : {}) };
}
