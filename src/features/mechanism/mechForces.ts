import { GROUND, mechanismForces } from '../../mechanism';
import type { LinkMass, MechanismForces, MechanismSpec } from '../../mechanism';
import { slenderBar } from '../../shared/linkage/slenderBar';
import { hull } from './hull';
import type { Pt } from './mechPose';

/**
 * What the worker needs, beside the spec and the inputs, to solve the forces over the cycle (SI at this edge): the
 * metres in one length unit (the app's lu), the links' mass per length (kg/m), gravity (m/s², pointing -y) and the
 * input's constant speed (rad/s for a pin input, lu/s for a slider input).
 */
export interface MechForcesJob {
  metresPerUnit: number;
  rhoKgPerM: number;
  gravityMPerS2: number;
  inputSpeed: number;
}

/** The points of a moving link as drawn (length unit): its pins, the sliders' blocks it is, its tracers. */
export function linkPoints(spec: MechanismSpec, link: string): Pt[] {
  const pts: Pt[] = [];
  for (const j of spec.joints) {
    if ((j.kind === 'R' && j.links.includes(link)) || (j.kind === 'P' && j.links[0] === link)) pts.push(j);
  }
  for (const p of spec.points ?? []) if (p.link === link) pts.push(p);
  return pts.map(({ x, y }) => ({ x, y }));
}

/**
 * A link's outline as bars (the shape the canvas draws): one bar between two points (the two farthest apart when
 * they are in line), else the edges of their convex hull; none for a single point (a slider's block).
 */
export function outlineBars(points: readonly Pt[]): [Pt, Pt][] {
  const h = hull(points);
  if (h.length < 2) return [];
  if (h.length === 2) return h[0].x === h[1].x && h[0].y === h[1].y ? [] : [[h[0], h[1]]];
  return h.map((p, i) => [p, h[(i + 1) % h.length]]);
}

/**
 * The mass properties (SI) of a link made of uniform bars of rhoKgPerM (ends in the length unit, metresPerUnit
 * metres each): the bars' total mass, their common CG (m) and the inertia about it (each bar's m L²/12 plus its
 * m d² by the parallel-axis theorem); null when the bars have no mass.
 */
export function barsMass(bars: readonly [Pt, Pt][], rhoKgPerM: number, metresPerUnit: number): LinkMass | null {
  const parts = bars.map(([a, b]) => ({
    ...slenderBar(Math.hypot(b.x - a.x, b.y - a.y) * metresPerUnit, rhoKgPerM),
    x: ((a.x + b.x) / 2) * metresPerUnit,
    y: ((a.y + b.y) / 2) * metresPerUnit,
  }));
  const mass = parts.reduce((s, p) => s + p.mass, 0);
  if (!(mass > 0)) return null;
  const x = parts.reduce((s, p) => s + p.mass * p.x, 0) / mass;
  const y = parts.reduce((s, p) => s + p.mass * p.y, 0) / mass;
  const inertia = parts.reduce((s, p) => s + p.inertia + p.mass * ((p.x - x) ** 2 + (p.y - y) ** 2), 0);
  return { mass, inertia, x, y };
}

/** Every moving link's mass properties (SI) as uniform bars along its outline (massless links left out). */
export function barMasses(spec: MechanismSpec, rhoKgPerM: number, metresPerUnit: number): Record<string, LinkMass> {
  const out: Record<string, LinkMass> = {};
  for (const link of spec.links) {
    if (link === GROUND) continue;
    const m = barsMass(outlineBars(linkPoints(spec, link)), rhoKgPerM, metresPerUnit);
    if (m) out[link] = m;
  }
  return out;
}

/** The spec with every coordinate times k (a change of length unit; angles unchanged). */
export function scaleSpec(spec: MechanismSpec, k: number): MechanismSpec {
  return {
    ...spec,
    joints: spec.joints.map((j) => ({ ...j, x: j.x * k, y: j.y * k })),
    ...(spec.points ? { points: spec.points.map((p) => ({ ...p, x: p.x * k, y: p.y * k })) } : {}),
  };
}

/** Whether the spec's input is a slider (its inputs and speed are lengths). */
const slidingInput = (spec: MechanismSpec) => spec.joints.find((j) => j.id === spec.input.joint)?.kind === 'P';

/**
 * The driver's torque (N·m, pin input) or force (N, slider input) and every joint's reaction (N) over inputs
 * (radians, or lengths in the length unit), for links of uniform bars, gravity and the input at a constant speed:
 * mechanismForces on the linkage in metres. Throws as mechanismForces does.
 */
export function solveMechForces(spec: MechanismSpec, inputs: ArrayLike<number>, job: MechForcesJob): MechanismForces {
  const k = job.metresPerUnit;
  const sliding = slidingInput(spec);
  const si = sliding ? Float64Array.from(inputs, (t) => t * k) : inputs;
  return mechanismForces(
    scaleSpec(spec, k),
    si,
    { omega: sliding ? job.inputSpeed * k : job.inputSpeed, alpha: 0 },
    barMasses(spec, job.rhoKgPerM, k),
    job.gravityMPerS2 > 0 ? { gravity: { g: job.gravityMPerS2 } } : {},
  );
}

/** A joint's reaction magnitude |F| (N) over the sweep (NaN where not assembled). */
export function reactionMagnitude(f: MechanismForces, joint: string): Float64Array {
  const r = f.joints[joint];
  if (!r) return new Float64Array(f.input.length).fill(NaN);
  return r.fx.map((fx, i) => Math.hypot(fx, r.fy[i]));
}

/** The joint whose reaction the page shows: the chosen one if the linkage has it, else the first joint after the input. */
export function reactionJoint(spec: MechanismSpec, chosen: string): string {
  if (spec.joints.some((j) => j.id === chosen)) return chosen;
  return spec.joints.find((j) => j.id !== spec.input.joint)?.id ?? spec.joints[0]?.id ?? '';
}
