import { describe } from '../solver/validate';
import type { MechanismSpec } from './types';

/** The frame's link name. */
export const GROUND = 'ground';

/** Grübler–Kutzbach mobility of a planar linkage of R and P joints: 3 (n - 1) - 2 joints. Throws for a non-array. */
export function mobility(spec: MechanismSpec): number {
  if (typeof spec !== 'object' || spec === null) throw new Error(`spec must be an object, got ${describe(spec)}`);
  if (!Array.isArray(spec.links)) throw new Error(`links must be an array of link names, got ${describe(spec.links)}`);
  if (!Array.isArray(spec.joints)) throw new Error(`joints must be an array, got ${describe(spec.joints)}`);
  return 3 * (spec.links.length - 1) - 2 * spec.joints.length;
}

/** What a mobility other than 1 means, for the error message. */
function mobilityMessage(m: number): string {
  if (m > 1) return `mobility ${m}: add a joint or fix a link`;
  return `mobility ${m}: this is a structure`;
}

function checkFiniteField(name: string, v: unknown): void {
  if (typeof v !== 'number' || !Number.isFinite(v))
    throw new Error(`${name} must be a finite number, got ${describe(v)}`);
}

function checkName(name: string, v: unknown): asserts v is string {
  if (typeof v !== 'string' || v === '') throw new Error(`${name} must be a non-empty string, got ${describe(v)}`);
}

/**
 * Throws an Error naming the offending id or field unless spec is a linkage this module can move: known links,
 * unique ids, finite coordinates, a P joint's angle, a known input joint, mobility 1 and every link connected to
 * the ground through joints.
 */
export function validateSpec(spec: unknown): asserts spec is MechanismSpec {
  validateStructure(spec);
  const s = spec as MechanismSpec;
  const input = s.input as unknown as Record<string, unknown> | undefined;
  if (typeof input !== 'object' || input === null) throw new Error(`input must be { joint }, got ${describe(input)}`);
  if (!s.joints.some((j) => j.id === input.joint))
    throw new Error(`input.joint: unknown joint ${describe(input.joint)}`);
  const m = mobility(s);
  if (m !== 1) throw new Error(mobilityMessage(m));
  // Every link must reach the ground through joints, or it floats free (and another part is over-constrained).
  const reached = new Set<string>([GROUND]);
  let grew = true;
  while (grew) {
    grew = false;
    for (const j of s.joints) {
      const [a, b] = j.links;
      if (reached.has(a) !== reached.has(b)) {
        reached.add(a);
        reached.add(b);
        grew = true;
      }
    }
  }
  const loose = s.links.filter((l) => !reached.has(l));
  if (loose.length > 0) {
    throw new Error(`links ${loose.map((l) => describe(l)).join(', ')} are disconnected from the ground`);
  }
}

/**
 * Throws an Error naming the offending id or field unless spec is a well-formed drawing of pins and sliders: known
 * links with 'ground' among them, unique ids, finite coordinates, a P joint's angle, tracers on known links. The
 * input, the mobility and the connection to the ground are validateSpec's (an editor holds linkages still being
 * built: mobility 2, no input yet).
 */
export function validateStructure(spec: unknown): asserts spec is Omit<MechanismSpec, 'input'> {
  if (typeof spec !== 'object' || spec === null) throw new Error(`spec must be an object, got ${describe(spec)}`);
  const s = spec as Record<string, unknown>;
  if (!Array.isArray(s.links)) throw new Error(`links must be an array of link names, got ${describe(s.links)}`);
  const links = new Set<string>();
  s.links.forEach((l, i) => {
    checkName(`links[${i}]`, l);
    if (links.has(l)) throw new Error(`links: duplicate link ${describe(l)}`);
    links.add(l);
  });
  if (!links.has(GROUND)) throw new Error(`links must include 'ground', got ${describe(s.links)}`);
  if (!Array.isArray(s.joints)) throw new Error(`joints must be an array, got ${describe(s.joints)}`);
  const joints = new Map<string, Record<string, unknown>>();
  s.joints.forEach((j: unknown, i) => {
    if (typeof j !== 'object' || j === null) throw new Error(`joints[${i}] must be an object, got ${describe(j)}`);
    const jr = j as Record<string, unknown>;
    checkName(`joints[${i}].id`, jr.id);
    const id = jr.id;
    if (joints.has(id)) throw new Error(`joint ${describe(id)}: duplicate joint id`);
    joints.set(id, jr);
    if (jr.kind !== 'R' && jr.kind !== 'P')
      throw new Error(`joint ${describe(id)}: kind must be 'R' or 'P', got ${describe(jr.kind)}`);
    const jl = jr.links;
    if (!Array.isArray(jl) || jl.length !== 2) {
      throw new Error(`joint ${describe(id)}: links must be two link names, got ${describe(jl)}`);
    }
    for (const l of jl) {
      if (!links.has(l)) throw new Error(`joint ${describe(id)}: unknown link ${describe(l)}`);
    }
    if (jl[0] === jl[1]) throw new Error(`joint ${describe(id)}: joins link ${describe(jl[0])} to itself`);
    checkFiniteField(`joint ${describe(id)}: x`, jr.x);
    checkFiniteField(`joint ${describe(id)}: y`, jr.y);
    if (jr.kind === 'P') {
      if (jr.angle === undefined)
        throw new Error(`joint ${describe(id)}: a P joint needs an angle (slide direction, radians)`);
      checkFiniteField(`joint ${describe(id)}: angle`, jr.angle);
    }
  });
  if (s.points !== undefined) {
    if (!Array.isArray(s.points)) throw new Error(`points must be an array, got ${describe(s.points)}`);
    const ids = new Set<string>();
    s.points.forEach((p: unknown, i) => {
      if (typeof p !== 'object' || p === null) throw new Error(`points[${i}] must be an object, got ${describe(p)}`);
      const pr = p as Record<string, unknown>;
      checkName(`points[${i}].id`, pr.id);
      if (ids.has(pr.id)) throw new Error(`point ${describe(pr.id)}: duplicate point id`);
      ids.add(pr.id);
      if (!links.has(pr.link as string)) throw new Error(`point ${describe(pr.id)}: unknown link ${describe(pr.link)}`);
      checkFiniteField(`point ${describe(pr.id)}: x`, pr.x);
      checkFiniteField(`point ${describe(pr.id)}: y`, pr.y);
    });
  }
}
