import { GROUND } from '../../mechanism';
import type { JointSpec, MechanismSpec, TracerSpec } from '../../mechanism';

/**
 * Edits of a linkage as pure functions (spec in, new spec out, the input untouched): the editor's tools, the
 * table's fields and the canvas's drags all go through them. A refused edit throws an Error naming the field and
 * the value (a name taken, an empty name); the caller shows it and keeps the last valid linkage.
 */

/** A linkage with nothing but the ground: where building from scratch starts. */
export function emptySpec(): MechanismSpec {
  return { links: [GROUND], joints: [], input: { joint: '' } };
}

/** Every name in use: links, joints and tracers (a new name is none of them). */
function namesOf(spec: MechanismSpec): Set<string> {
  return new Set([...spec.links, ...spec.joints.map((j) => j.id), ...(spec.points ?? []).map((p) => p.id)]);
}

/** The first of prefix1, prefix2, … not in use. */
export function freshName(spec: MechanismSpec, prefix: string): string {
  const used = namesOf(spec);
  for (let i = 1; ; i++) if (!used.has(`${prefix}${i}`)) return `${prefix}${i}`;
}

/** Moves a joint or a tracer (by id) in the drawn configuration to (x, y). */
export function moveJoint(spec: MechanismSpec, id: string, x: number, y: number): MechanismSpec {
  if (spec.joints.some((j) => j.id === id))
    return { ...spec, joints: spec.joints.map((j) => (j.id === id ? { ...j, x, y } : j)) };
  if (spec.points?.some((p) => p.id === id))
    return { ...spec, points: spec.points.map((p) => (p.id === id ? { ...p, x, y } : p)) };
  throw new Error(`no joint or tracer named ${JSON.stringify(id)}`);
}

/** Sets a slider's slide direction (radians from +x, as drawn). */
export function setSlideAngle(spec: MechanismSpec, id: string, angleRad: number): MechanismSpec {
  return { ...spec, joints: spec.joints.map((j) => (j.id === id && j.kind === 'P' ? { ...j, angle: angleRad } : j)) };
}

function checkNewName(spec: MechanismSpec, name: string, field: string, old?: string): string {
  const n = name.trim();
  if (n === '') throw new Error(`${field}: a name cannot be empty`);
  if (n !== old && namesOf(spec).has(n)) throw new Error(`${field}: the name ${JSON.stringify(n)} is taken`);
  return n;
}

/** Renames a joint or a tracer (the input follows); throws for an empty or taken name. */
export function renameJoint(spec: MechanismSpec, id: string, name: string): MechanismSpec {
  const n = checkNewName(spec, name, `name of ${id}`, id);
  if (n === id) return spec;
  return {
    ...spec,
    joints: spec.joints.map((j) => (j.id === id ? { ...j, id: n } : j)),
    ...(spec.points ? { points: spec.points.map((p) => (p.id === id ? { ...p, id: n } : p)) } : {}),
    input: { joint: spec.input.joint === id ? n : spec.input.joint },
  };
}

/** Renames a link everywhere (the ground keeps its name: make another link the ground instead). */
export function renameLink(spec: MechanismSpec, link: string, name: string): MechanismSpec {
  if (link === GROUND) throw new Error(`name of ${GROUND}: the ground keeps its name`);
  const n = checkNewName(spec, name, `name of ${link}`, link);
  if (n === link) return spec;
  const r = (l: string) => (l === link ? n : l);
  return {
    ...spec,
    links: spec.links.map(r),
    joints: spec.joints.map((j) => ({ ...j, links: [r(j.links[0]), r(j.links[1])] })),
    ...(spec.points ? { points: spec.points.map((p) => ({ ...p, link: r(p.link) })) } : {}),
  };
}

/** Makes a link the frame: it and the ground swap names (the old ground becomes a moving link). */
export function makeGround(spec: MechanismSpec, link: string): MechanismSpec {
  if (link === GROUND) return spec;
  const r = (l: string) => (l === link ? GROUND : l === GROUND ? link : l);
  return {
    ...spec,
    links: spec.links.map(r),
    joints: spec.joints.map((j) => ({ ...j, links: [r(j.links[0]), r(j.links[1])] })),
    ...(spec.points ? { points: spec.points.map((p) => ({ ...p, link: r(p.link) })) } : {}),
  };
}

/** Adds a link named link1, link2, …; returns the spec and the name. */
export function addLink(spec: MechanismSpec): { spec: MechanismSpec; name: string } {
  const name = freshName(spec, 'link');
  return { spec: { ...spec, links: [...spec.links, name] }, name };
}

/** Adds a pin (R) or a slider (P, sliding along +x as drawn) joining links a and b at (x, y); returns it too. */
export function addJoint(
  spec: MechanismSpec,
  kind: 'R' | 'P',
  links: [string, string],
  x: number,
  y: number,
): { spec: MechanismSpec; id: string } {
  if (links[0] === links[1]) throw new Error(`links: a joint joins two different links, got ${links[0]} twice`);
  for (const l of links) if (!spec.links.includes(l)) throw new Error(`links: unknown link ${JSON.stringify(l)}`);
  const id = freshName(spec, kind === 'R' ? 'J' : 'S');
  const joint: JointSpec = kind === 'P' ? { id, kind, links, x, y, angle: 0 } : { id, kind, links, x, y };
  return { spec: { ...spec, joints: [...spec.joints, joint] }, id };
}

/** Adds a tracer on a link at (x, y). */
export function addTracer(
  spec: MechanismSpec,
  link: string,
  x: number,
  y: number,
): { spec: MechanismSpec; id: string } {
  if (!spec.links.includes(link)) throw new Error(`link: unknown link ${JSON.stringify(link)}`);
  const id = freshName(spec, 'T');
  const point: TracerSpec = { id, link, x, y };
  return { spec: { ...spec, points: [...(spec.points ?? []), point] }, id };
}

/** Joins two links at a joint: sets the joint's links (for a slider: block, then guide). */
export function setJointLinks(spec: MechanismSpec, id: string, links: [string, string]): MechanismSpec {
  if (links[0] === links[1])
    throw new Error(`links of ${id}: a joint joins two different links, got ${links[0]} twice`);
  return { ...spec, joints: spec.joints.map((j) => (j.id === id ? { ...j, links } : j)) };
}

/** Moves a tracer to another link. */
export function setTracerLink(spec: MechanismSpec, id: string, link: string): MechanismSpec {
  return { ...spec, points: (spec.points ?? []).map((p) => (p.id === id ? { ...p, link } : p)) };
}

/** Deletes a joint or a tracer (the input is unchosen when it was that joint). */
export function deleteJoint(spec: MechanismSpec, id: string): MechanismSpec {
  const points = (spec.points ?? []).filter((p) => p.id !== id);
  return {
    links: spec.links,
    joints: spec.joints.filter((j) => j.id !== id),
    ...(points.length > 0 ? { points } : {}),
    input: { joint: spec.input.joint === id ? '' : spec.input.joint },
  };
}

/** Deletes a link with its joints and tracers (not the ground). */
export function deleteLink(spec: MechanismSpec, link: string): MechanismSpec {
  if (link === GROUND) throw new Error(`${GROUND}: the frame cannot be deleted (make another link the ground first)`);
  const joints = spec.joints.filter((j) => !j.links.includes(link));
  const points = (spec.points ?? []).filter((p) => p.link !== link);
  return {
    links: spec.links.filter((l) => l !== link),
    joints,
    ...(points.length > 0 ? { points } : {}),
    input: { joint: joints.some((j) => j.id === spec.input.joint) ? spec.input.joint : '' },
  };
}

/** Chooses the input joint ('' for none). */
export function setInput(spec: MechanismSpec, id: string): MechanismSpec {
  return { ...spec, input: { joint: id } };
}
