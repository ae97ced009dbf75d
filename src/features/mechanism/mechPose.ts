import { GROUND } from '../../mechanism';
import type { MechanismSpec, MechanismSweep } from '../../mechanism';
import type { InputGrid } from './mechAnalysis';

/** A point in the plane (length unit). */
export interface Pt {
  x: number;
  y: number;
}

/** The linkage at one input: every joint's and tracer's place, and every moving link's rotation from as drawn (rad). */
export interface MechPose {
  joints: Record<string, Pt>;
  points: Record<string, Pt>;
  rotation: Record<string, number>;
  /** Each slider's slide (block relative to guide along its direction, from as drawn). */
  slide: Record<string, number>;
}

/** The linkage as drawn (input 0): the spec's own coordinates, no rotation. */
export function drawnPose(spec: MechanismSpec): MechPose {
  const joints: Record<string, Pt> = {};
  for (const j of spec.joints) joints[j.id] = { x: j.x, y: j.y };
  const points: Record<string, Pt> = {};
  for (const p of spec.points ?? []) points[p.id] = { x: p.x, y: p.y };
  const rotation: Record<string, number> = {};
  for (const l of spec.links) if (l !== GROUND) rotation[l] = 0;
  const slide: Record<string, number> = {};
  for (const j of spec.joints) if (j.kind === 'P') slide[j.id] = 0;
  return { joints, points, rotation, slide };
}

/**
 * The pose at input t, interpolated linearly between the two grid samples about it (1° apart for a pin input, so
 * a link's length is off by at most 4e-5 of it); null where either sample is not assembled or t is off the grid.
 */
export function poseAt(spec: MechanismSpec, grid: InputGrid, sweep: MechanismSweep, t: number): MechPose | null {
  const u = t / grid.step - grid.kLo;
  if (!(u >= 0 && u <= grid.inputs.length - 1)) return null;
  const i = Math.min(Math.floor(u), grid.inputs.length - 2);
  const f = u - i;
  const j = Math.max(0, Math.min(grid.inputs.length - 1, i + 1));
  if (!sweep.ok[i] || !sweep.ok[j]) {
    // On a sample exactly, the other may be missing (the end of a rocking run).
    const k = f < 1e-9 ? i : f > 1 - 1e-9 ? j : -1;
    if (k < 0 || !sweep.ok[k]) return null;
    return poseAtIndex(spec, sweep, k, k, 0);
  }
  return poseAtIndex(spec, sweep, i, j, f);
}

function poseAtIndex(spec: MechanismSpec, sweep: MechanismSweep, i: number, j: number, f: number): MechPose {
  const lerp = (a: ArrayLike<number>) => a[i] + (a[j] - a[i]) * f;
  const joints: Record<string, Pt> = {};
  for (const jt of spec.joints) {
    const s = sweep.joints[jt.id];
    joints[jt.id] = { x: lerp(s.x), y: lerp(s.y) };
  }
  const points: Record<string, Pt> = {};
  for (const p of spec.points ?? []) {
    const s = sweep.points[p.id];
    points[p.id] = { x: lerp(s.x), y: lerp(s.y) };
  }
  const rotation: Record<string, number> = {};
  for (const l of spec.links) if (l !== GROUND) rotation[l] = sweep.links[l] ? lerp(sweep.links[l].angle) : 0;
  const slide: Record<string, number> = {};
  for (const j of spec.joints) if (j.kind === 'P') slide[j.id] = lerp(sweep.sliders[j.id].s);
  return { joints, points, rotation, slide };
}

/** The path of a joint or a tracer over the grid indices [a, b] (NaN where not assembled: a gap). */
export function pathOf(sweep: MechanismSweep, id: string, run: [number, number]): { x: Float64Array; y: Float64Array } {
  const s = sweep.joints[id] ?? sweep.points[id];
  return { x: s.x.subarray(run[0], run[1] + 1), y: s.y.subarray(run[0], run[1] + 1) };
}
