/**
 * Every four-bar whose coupler curve passes through nine given points (Alt's problem), by a parameter homotopy from a
 * shipped generic start system (Wampler, Morgan and Sommese 1992; see docs/synthesis.md).
 */
import { TWO_PI, classify, inputRange, solveClosedForm, wrapAngle } from '../../solver';
import type { Branch, Point } from '../../solver';
import { fourBarFromJoints, placedCouplerPoint, placedJoints } from '../placed';
import type { AbortSignalLike } from '../pathSynthesis';
import type { PlacedFourBar } from '../types';
import { checkArray, checkPoint } from '../validate';
import { A, AH, B, BH, NV, X, XH, Y, YH, rotation } from './equations';
import { cognateRoots, orbitKey, sameKey, swapDyads } from './group';
import { norm } from './linear';
import { decodeRoots } from './startCodec';
import { Tracker } from './tracker';

/** A four-bar through the nine points: θ2 at each point (radians, as PlacedFourBar) and its assembly there. */
export interface NinePointLinkage extends PlacedFourBar {
  theta2: number[];
  branches: Branch[];
}

/** One real solution class: the three Roberts cognates, whether the first is Grashof, its defects. */
export interface NinePointClass {
  cognates: NinePointLinkage[];
  grashof: boolean;
  defects: ('circuit' | 'order' | 'branch')[];
  /** The start path (index into the shipped start system) that found it. */
  path?: number;
}

/** Where a start path ended at a finite root: its index and the orbit key of its end (8 numbers, see orbitKey). */
export interface NinePointEnd {
  path: number;
  key: number[];
}

/**
 * Every real, non-degenerate class found, and the paths: each tracked path is one orbit of six roots (two labellings ×
 * three cognates); finished counts paths that ended at a regular root or at infinity, failed those lost; retracked
 * the paths tracked again, carefully, because two paths had ended in one orbit (one of them jumped). ends lists every
 * path that ended at a finite root with its orbit key, so that a merge of slices finds a path that jumped onto a path
 * of another slice (ninePointJumps).
 */
export interface NinePointResult {
  classes: NinePointClass[];
  paths: { total: number; finished: number; failed: number; retracked?: number };
  ends?: NinePointEnd[];
  /** The start paths this result tracked again (options.retrack): in a merge they replace those paths' first ends. */
  redone?: number[];
}

/**
 * Options: cancel, progress, and a slice [start, end) of the start solutions for a worker pool; or retrack, start
 * paths to track again carefully (those ninePointJumps names after a merge), which replace them in mergeNinePoint.
 */
export interface NinePointOptions {
  signal?: AbortSignalLike;
  onProgress?: (p: { done: number; total: number; found: number }) => void;
  paths?: { start: number; end: number };
  retrack?: number[];
}

/** A linkage passes through a point when its coupler point is within this of it (relative to the points' size). */
export const RECHECK_TOL = 1e-6;
/** A root is real when its hatted half is the conjugate of the other to this (relative to |z|). */
const REAL_TOL = 1e-8;
/** Links shorter than this (relative to the points' size) make a degenerate linkage. */
const DEGENERATE = 1e-8;
/** The homotopy's γ: fixed, so a run is reproducible and a retry uses the same path. */
const GAMMA: [number, number] = [0.8134, -0.5817];

interface StartSystem {
  params: Float64Array;
  roots: Float64Array[];
}
let startCache: Promise<StartSystem> | null = null;

/** The shipped start system (loaded on first use), its roots polished by Newton at the start parameters. */
export function loadStartSystem(): Promise<StartSystem> {
  startCache ??= import('./startData').then((m) => {
    const params = Float64Array.from(m.START_PARAMS);
    const roots = decodeRoots(m.START_ROOTS, m.START_ORBITS);
    const t = new Tracker();
    t.setSegment(params, params, 1, 0);
    for (const z of roots) t.newton(z, 0, 8, 1e-12);
    return { params, roots };
  });
  return startCache;
}

/** Start paths the shipped start system holds (one per orbit of six roots: 8652 roots in all). */
export const NINE_POINT_PATHS = 1442;

/**
 * Why nine finite points cannot be solved, as data the page words in its language: two coincide (indices, 0-based),
 * or they lie on one line or one circle (the roots go to infinity); null when they can.
 */
export type NinePointRefusal =
  { kind: 'coincide'; i: number; j: number; point: Point } | { kind: 'line' } | { kind: 'circle' };

/** The refusal of nine finite points (see NinePointRefusal), or null when the problem is solvable. */
export function ninePointRefusal(ps: readonly Point[]): NinePointRefusal | null {
  const size = Math.max(...ps.map((p) => Math.hypot(p.x - ps[0].x, p.y - ps[0].y)));
  for (let i = 0; i < ps.length; i++)
    for (let j = i + 1; j < ps.length; j++) {
      if (Math.hypot(ps[i].x - ps[j].x, ps[i].y - ps[j].y) <= 1e-12 * size || size === 0) {
        return { kind: 'coincide', i, j, point: { x: ps[i].x, y: ps[i].y } };
      }
    }
  // Collinear: the smaller principal axis of the points is zero.
  const n = ps.length;
  const cx = ps.reduce((s, p) => s + p.x, 0) / n;
  const cy = ps.reduce((s, p) => s + p.y, 0) / n;
  let sxx = 0,
    syy = 0,
    sxy = 0;
  for (const p of ps) {
    sxx += (p.x - cx) ** 2;
    syy += (p.y - cy) ** 2;
    sxy += (p.x - cx) * (p.y - cy);
  }
  const tr = sxx + syy;
  const lmin = tr / 2 - Math.sqrt(((sxx - syy) / 2) ** 2 + sxy * sxy);
  if (Math.sqrt(Math.max(0, lmin) / n) <= 1e-9 * size) return { kind: 'line' };
  // Concyclic: the circle through three of them passes through all (Kåsa's algebraic fit would do; this is exact).
  const circle = circleThrough(ps[0], ps[3], ps[6]);
  if (circle && ps.every((p) => Math.abs(Math.hypot(p.x - circle.x, p.y - circle.y) - circle.r) <= 1e-9 * size)) {
    return { kind: 'circle' };
  }
  return null;
}

function checkPoints(points: unknown): asserts points is Point[] {
  checkArray('points', points, 9, 9);
  points.forEach((p, i) => checkPoint(`points[${i}]`, p));
  const r = ninePointRefusal(points as Point[]);
  if (r?.kind === 'coincide') {
    throw new Error(
      `points[${r.i}] and points[${r.j}] coincide at (${r.point.x}, ${r.point.y}): nine distinct points needed`,
    );
  }
  if (r) {
    throw new Error(`points lie on one ${r.kind}: the solutions of the nine-point problem go to infinity there`);
  }
}

function circleThrough(a: Point, b: Point, c: Point): { x: number; y: number; r: number } | null {
  const bx = b.x - a.x,
    by = b.y - a.y,
    cx = c.x - a.x,
    cy = c.y - a.y;
  const d = 2 * (bx * cy - by * cx);
  if (d === 0) return null;
  const ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
  const uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
  return { x: a.x + ux, y: a.y + uy, r: Math.hypot(ux, uy) };
}

/** Target parameters: δ_j = (P_j − P_0)/size and their conjugates. */
function targetParams(points: Point[], size: number): Float64Array {
  const p = new Float64Array(4 * NV);
  for (let j = 1; j < 9; j++) {
    const re = (points[j].x - points[0].x) / size;
    const im = (points[j].y - points[0].y) / size;
    p[2 * (j - 1)] = re;
    p[2 * (j - 1) + 1] = im;
    p[16 + 2 * (j - 1)] = re;
    p[17 + 2 * (j - 1)] = -im;
  }
  return p;
}

/** The real root nearest z (its hatted half conjugate to the rest), or null when z is not real. */
function realPart(z: Float64Array): Float64Array | null {
  const tol = REAL_TOL * (1 + norm(z));
  const w = new Float64Array(2 * NV);
  for (const [k, kh] of [
    [X, XH],
    [A, AH],
    [Y, YH],
    [B, BH],
  ]) {
    const re = z[2 * k],
      im = z[2 * k + 1],
      reh = z[2 * kh],
      imh = z[2 * kh + 1];
    if (Math.hypot(re - reh, im + imh) > tol) return null;
    w[2 * k] = (re + reh) / 2;
    w[2 * k + 1] = (im - imh) / 2;
    w[2 * kh] = w[2 * k];
    w[2 * kh + 1] = -w[2 * k + 1];
  }
  return w;
}

/** The linkage of a real root in the user's plane, checked through all nine points; null when degenerate. */
function linkageOf(z: Float64Array, p: Float64Array, points: Point[], size: number): NinePointLinkage | null {
  const P0 = points[0];
  const at = (k: number): Point => ({ x: P0.x + size * z[2 * k], y: P0.y + size * z[2 * k + 1] });
  const c = (k: number) => [z[2 * k], z[2 * k + 1]];
  const dist = (u: number[], v: number[]) => Math.hypot(u[0] - v[0], u[1] - v[1]);
  if (
    !(dist(c(X), c(A)) > DEGENERATE) ||
    !(dist(c(Y), c(B)) > DEGENERATE) ||
    !(dist(c(X), c(Y)) > DEGENERATE) ||
    !(dist(c(A), c(B)) > DEGENERATE)
  )
    return null;
  const theta2: number[] = [];
  const branches: Branch[] = [];
  let base: PlacedFourBar | null = null;
  const rot = new Float64Array(2);
  for (let j = 0; j < 9; j++) {
    let tr = 1,
      ti = 0;
    if (j > 0) {
      rotation(z, p, j - 1, rot);
      [tr, ti] = [rot[0], rot[1]];
      if (!Number.isFinite(tr) || !Number.isFinite(ti)) return null;
    }
    // Moving pivots at pose j: P_j + θ_j x and P_j + θ_j y.
    const Pj = points[j];
    const move = (k: number): Point => ({
      x: Pj.x + size * (tr * z[2 * k] - ti * z[2 * k + 1]),
      y: Pj.y + size * (tr * z[2 * k + 1] + ti * z[2 * k]),
    });
    let pose;
    try {
      pose = fourBarFromJoints({ O2: at(A), A: move(X), B: move(Y), O4: at(B), P: Pj });
    } catch {
      return null;
    }
    base ??= pose.design;
    theta2.push(pose.theta2);
    branches.push(pose.design.branch);
  }
  const d: NinePointLinkage = { ...base!, theta2, branches };
  // The solver's own kinematics must put the coupler point on every target.
  for (let j = 0; j < 9; j++) {
    const q = placedCouplerPoint({ ...d, branch: branches[j] }, theta2[j]);
    if (!q || Math.hypot(q.x - points[j].x, q.y - points[j].y) > RECHECK_TOL * size) return null;
  }
  return d;
}

/**
 * The circuit of a Grashof linkage at a pose: the side of the joint angle at a joint not on the shortest link (those
 * joints never go flat on a Grashof linkage, so the sign is constant on a circuit and differs between the two).
 */
function circuitOf(d: PlacedFourBar, theta2: number, branch: Branch): number {
  const j = placedJoints({ ...d, branch }, theta2);
  if (!j) return 0;
  const { r1, r2, r3, r4 } = d.links;
  const shortest = Math.min(r1, r2, r3, r4);
  // joint (p) with neighbours (u, v): cross(u − p, v − p)
  const side = (u: Point, q: Point, v: Point) => Math.sign((u.x - q.x) * (v.y - q.y) - (u.y - q.y) * (v.x - q.x));
  if (shortest === r2) return side(j.A, j.B, j.O4);
  if (shortest === r3) return side(j.O2, j.O4, j.B);
  return side(j.O2, j.A, j.B);
}

/**
 * Defects of a linkage through the nine points (as pathSynthesis screens them): 'circuit' when a Grashof linkage meets
 * them on both of its circuits, 'order' when one turn of the input in one direction does not meet them in order,
 * 'branch' when the input is not a full crank and the motion between two points passes a dead centre.
 */
function defectsOf(d: NinePointLinkage): ('circuit' | 'order' | 'branch')[] {
  const out: ('circuit' | 'order' | 'branch')[] = [];
  if (classify(d.links).grashof) {
    const c = d.theta2.map((t, j) => circuitOf(d, t, d.branches[j]));
    if (c.some((v) => v !== c[0])) out.push('circuit');
  }
  const steps = d.theta2.slice(1).map((t, i) => wrapAngle(t - d.theta2[i]));
  const fwd = steps.map((s) => (s < 0 ? s + TWO_PI : s));
  const back = steps.map((s) => (s > 0 ? TWO_PI - s : -s));
  const sum = (v: number[]) => v.reduce((a, b) => a + b, 0);
  const dir = sum(fwd) <= sum(back) ? 1 : -1;
  const travel = dir > 0 ? fwd : back;
  if (sum(travel) >= TWO_PI) out.push('order');
  if (!out.includes('circuit') && !inputRange(d.links).full) {
    // Sampled along the way from each point to the next: the loop must close on one assembly throughout.
    const SAMPLES = 16;
    let broken = d.branches.some((b) => b !== d.branches[0]);
    for (let i = 0; i < 8 && !broken; i++) {
      for (let k = 1; k < SAMPLES && !broken; k++) {
        const t = d.theta2[i] + (dir * travel[i] * k) / SAMPLES;
        if (!solveClosedForm(d.links, t, d.branches[i])) broken = true;
      }
    }
    if (broken) out.push('branch');
  }
  return out;
}

/**
 * All real, non-degenerate four-bars whose coupler curves pass through nine points (length unit of the points), as
 * classes of three Roberts cognates. Throws for anything but nine finite distinct points, and for points on one line
 * or circle (the roots go to infinity). options.paths picks a slice of the start solutions (merge with mergeNinePoint).
 */
export async function ninePointSynthesis(points: Point[], options: NinePointOptions = {}): Promise<NinePointResult> {
  checkPoints(points);
  const size = Math.max(...points.map((q) => Math.hypot(q.x - points[0].x, q.y - points[0].y)));
  const target = targetParams(points, size);
  const start = await loadStartSystem();
  const n = start.roots.length;
  const from = Math.max(0, Math.min(n, Math.floor(options.paths?.start ?? 0)));
  const to = Math.max(from, Math.min(n, Math.floor(options.paths?.end ?? n)));
  const retrack = options.retrack;
  retrack?.forEach((i, k) => {
    if (!Number.isInteger(i) || i < 0 || i >= n) {
      throw new Error(`retrack[${k}] = ${i}: a start path index from 0 to ${n - 1} needed`);
    }
  });
  const indices = retrack ? [...new Set(retrack)] : Array.from({ length: to - from }, (_, k) => from + k);
  const tracker = new Tracker();
  tracker.setSegment(start.params, target, GAMMA[0], GAMMA[1]);
  const ends: { z: Float64Array; key: Float64Array; index: number }[] = [];
  let failed = 0;
  let finished = 0;
  let real = 0;
  const trackOne = (index: number, careful: boolean) => {
    const z = start.roots[index].slice();
    const r = careful
      ? tracker.track(z, { hMax: 0.01, h0: 1e-3, maxSteps: 40000, tol: 1e-10, eta: 1e-5 })
      : tracker.track(z, { hMax: 0.1 });
    return { z, status: r.status };
  };
  for (let done = 0; done < indices.length; done++) {
    const i = indices[done];
    // Cancelled: what is done so far, with finished + failed < total saying the rest was not tracked.
    if (options.signal?.aborted) break;
    let r = trackOne(i, !!retrack);
    if (r.status === 'failed' && !retrack) r = trackOne(i, true);
    if (r.status === 'failed') failed++;
    else {
      finished++;
      if (r.status === 'finished') {
        ends.push({ z: r.z, key: orbitKey(r.z), index: i });
        if (realPart(r.z)) real++;
      }
    }
    if (options.onProgress && (done % 16 === 15 || done === indices.length - 1)) {
      options.onProgress({ done: done + 1, total: indices.length, found: real });
      await Promise.resolve();
    }
  }
  // Two paths that end in one orbit mean one jumped: track them again, carefully; a duplicate that stays is failed.
  let retracked = retrack ? indices.length : 0;
  for (const group of duplicates(ends.map((e) => e.key))) {
    for (const k of group) {
      if (retrack) continue;
      retracked++;
      const r = trackOne(ends[k].index, true);
      if (r.status === 'finished') ends[k] = { z: r.z, key: orbitKey(r.z), index: ends[k].index };
    }
  }
  const drop = new Set<number>();
  for (const group of duplicates(ends.map((e) => e.key))) {
    for (const k of group.slice(1)) drop.add(k);
  }
  finished -= drop.size;
  failed += drop.size;
  const classes: NinePointClass[] = [];
  for (let k = 0; k < ends.length; k++) {
    const w = drop.has(k) ? null : realPart(ends[k].z);
    const cls = w && classOf(w, target, points, size);
    if (cls) classes.push({ ...cls, path: ends[k].index });
  }
  return {
    classes,
    paths: { total: indices.length, finished, failed, retracked },
    ends: ends.filter((_, k) => !drop.has(k)).map((e) => ({ path: e.index, key: Array.from(e.key) })),
    ...(retrack ? { redone: indices } : {}),
  };
}

/** Groups (two or more) of indices whose orbit keys agree. */
function duplicates(keys: ArrayLike<number>[]): number[][] {
  const order = keys.map((_, i) => i).sort((i, j) => keys[i][0] - keys[j][0]);
  const taken = new Set<number>();
  const groups: number[][] = [];
  for (let a = 0; a < order.length; a++) {
    if (taken.has(order[a])) continue;
    const group = [order[a]];
    for (let b = a + 1; b < order.length; b++) {
      const ka = keys[order[a]];
      const kb = keys[order[b]];
      if (kb[0] - ka[0] > 1e-6 * (1 + Math.abs(ka[0]))) break;
      if (sameKey(ka, kb, 1e-8)) group.push(order[b]);
    }
    if (group.length > 1) {
      group.forEach((k) => taken.add(k));
      groups.push(group);
    }
  }
  return groups;
}

function classOf(w: Float64Array, p: Float64Array, points: Point[], size: number): NinePointClass | null {
  const cognates: NinePointLinkage[] = [];
  for (const v of [w, ...cognateRoots(w)]) {
    let d = linkageOf(v, p, points, size);
    if (!d) return null;
    // Driven from the pivot that makes the input a crank when one does (the same linkage with the dyads swapped).
    if (!inputRange(d.links).full) {
      const other = linkageOf(swapDyads(v), p, points, size);
      if (other && inputRange(other.links).full) d = other;
    }
    cognates.push(d);
  }
  const first = cognates[0];
  return { cognates, grashof: classify(first.links).grashof, defects: defectsOf(first) };
}

/** Two classes are one when their three ground pivots agree to this (relative to the pivots' size). */
const SAME_CLASS = 1e-7;

/** The three ground pivots of a class (the cognates share them two by two), sorted by x then y. */
function classPivots(c: NinePointClass): Point[] {
  const out: Point[] = [];
  for (const d of c.cognates) {
    const g = d.groundAngle;
    const O4 = { x: d.O2.x + d.links.r1 * Math.cos(g), y: d.O2.y + d.links.r1 * Math.sin(g) };
    for (const p of [d.O2, O4]) {
      if (!out.some((q) => Math.hypot(q.x - p.x, q.y - p.y) <= SAME_CLASS * (1 + Math.hypot(p.x, p.y)))) out.push(p);
    }
  }
  return out.sort((a, b) => a.x - b.x || a.y - b.y);
}

/**
 * The start paths of slices' results that ended in one orbit with a path of another slice (one of them jumped; a
 * slice alone re-tracks its own): track them again with options.retrack and merge that result in too.
 */
export function ninePointJumps(parts: NinePointResult[]): number[] {
  const ends = liveEnds(parts);
  const out = new Set<number>();
  for (const g of duplicates(ends.map((e) => e.key))) {
    if (new Set(g.map((k) => ends[k].part)).size > 1) g.forEach((k) => out.add(ends[k].path));
  }
  return [...out].sort((a, b) => a - b);
}

/** Every part's ends, less those a later re-track (redone) replaces: with the part each is from. */
function liveEnds(parts: NinePointResult[]): (NinePointEnd & { part: number })[] {
  const out: (NinePointEnd & { part: number })[] = [];
  parts.forEach((r, part) => {
    const later = new Set(parts.slice(part + 1).flatMap((q) => q.redone ?? []));
    for (const e of r.ends ?? []) if (!later.has(e.path)) out.push({ ...e, part });
  });
  return out;
}

/**
 * The union of slices' results: path counts summed, classes concatenated. A re-track (a result with redone) replaces
 * the first ends and classes of its paths. Two paths of different slices still ending in one orbit (by the ends' keys,
 * or for results without ends by a class's three ground pivots to 1e-7) keep their class once and count the later
 * path failed, so a jump is said, not hidden.
 */
export function mergeNinePoint(parts: NinePointResult[]): NinePointResult {
  const paths = { total: 0, finished: 0, failed: 0, retracked: 0 };
  for (const r of parts) {
    paths.total += r.paths.total;
    paths.finished += r.paths.finished;
    paths.failed += r.paths.failed;
    paths.retracked += r.paths.retracked ?? 0;
  }
  // Paths a later part tracked again: their first ends were finished paths, now counted by the re-track.
  const replaced = new Set<string>();
  parts.forEach((r, part) => {
    const later = new Set(parts.slice(part + 1).flatMap((q) => q.redone ?? []));
    for (const e of r.ends ?? []) {
      if (!later.has(e.path)) continue;
      replaced.add(`${part}:${e.path}`);
      paths.total--;
      paths.finished--;
    }
  });
  const ends = liveEnds(parts);
  const jumped = new Set<string>();
  for (const g of duplicates(ends.map((e) => e.key))) {
    for (const k of g.slice(1)) {
      jumped.add(`${ends[k].part}:${ends[k].path}`);
      paths.finished--;
      paths.failed++;
    }
  }
  const classes: NinePointClass[] = [];
  const keys: Point[][] = [];
  parts.forEach((r, part) => {
    for (const c of r.classes) {
      const id = `${part}:${c.path}`;
      if (replaced.has(id) || jumped.has(id)) continue;
      const k = classPivots(c);
      const same = keys.some(
        (q) =>
          q.length === k.length &&
          q.every((p, i) => Math.hypot(p.x - k[i].x, p.y - k[i].y) <= SAME_CLASS * (1 + Math.hypot(p.x, p.y))),
      );
      if (same) {
        paths.finished--;
        paths.failed++;
      } else {
        classes.push(c);
        keys.push(k);
      }
    }
  });
  return { classes, paths, ends: ends.map(({ path, key }) => ({ path, key })) };
}
