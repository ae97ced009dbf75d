/**
 * From the global stage's local minima to answers: polish the best, read each off as a placed four-bar in the
 * user's units, and keep only designs that honestly do the job. Each is checked with the solver itself (it
 * assembles at every θ2 on its branch; the input turns fully when asked, or else the motion through the targets
 * stays inside one reachable interval), held to the bounds, and its error recomputed from the design with
 * placedCouplerPoint. Answers come best first, distinct, at most MAX_SOLUTIONS.
 */
import { classify, wrapAngle } from '../solver';
import type { Point } from '../solver';
import type { PathCandidate } from './globalSearch';
import { EXACT_F } from './globalSearch';
import { levenbergMarquardt } from './levenbergMarquardt';
import { placedCouplerPoint } from './placed';
import { createPathProblem, pathLayout, sweepWithinRange } from './pathProblem';
import type { NormalisedTask } from './pathTask';
import type { PathSolution, PathTask, PlacedFourBar } from './types';

/** Most answers returned. */
export const MAX_SOLUTIONS = 10;
/** Candidates polished with a longer local solve before screening, at least. */
const POLISHED = 24;
/**
 * Candidates polished at most: past POLISHED, polishing goes on down the list while fewer than MAX_SOLUTIONS
 * distinct answers have been found, so that "up to ten" means ten different linkages where the rounds found them.
 */
const POLISHED_MAX = 64;
/** Iteration cap of the first polish of a candidate. */
const POLISH_ITERATIONS = 300;
/**
 * Iteration cap of the long polish of the best POLISH_LONG candidates: the best fit often lies along a flat valley
 * (a solve that converges stops long before the cap).
 */
const POLISH_LONG_ITERATIONS = 4000;
const POLISH_LONG = 4;
/** Iteration cap of the polish every other answer listed gets, so that each is at its basin's optimum. */
const POLISH_ANSWER_ITERATIONS = 1500;
/** Fresh starts of the long polish from where it stalled, at most (along a flat valley the damping grows until the steps stall). */
const POLISH_RESTARTS = 1;
/**
 * Two designs whose pivots, links and coupler point all agree to this share of the target size are one linkage: the
 * flat valleys of an overdetermined fit leave copies that differ far above rounding (issue 34 item 2).
 */
export const SAME_DESIGN = 1e-3;

/** The user-unit design and θ2 (radians, unwrapped) of a candidate. */
function designOf(t: NormalisedTask, task: PathTask, c: PathCandidate): { design: PlacedFourBar; theta2: number[] } {
  const problem = createPathProblem(t, c.sigma, c.dir);
  const x = Float64Array.from(c.x);
  const L = problem.layout.links;
  const pl = problem.placementOf(x);
  const s = t.scale;
  const b = task.bounds;
  // A length a unit conversion rounded past a bound is put back on it; one further out fails the check below.
  const clampLen = (v: number) =>
    b?.length && v <= b.length[1] * (1 + 1e-12) && v >= b.length[0] * (1 - 1e-12)
      ? Math.min(b.length[1], Math.max(b.length[0], v))
      : v;
  const links = {
    r1: clampLen(s * x[L]),
    r2: clampLen(s * x[L + 1]),
    r3: clampLen(s * x[L + 2]),
    r4: clampLen(s * x[L + 3]),
  };
  let pDist = s * x[L + 4];
  if (b?.coupler !== undefined) pDist = Math.min(pDist, b.coupler);
  let O2: Point = task.placement
    ? { x: task.placement.O2.x, y: task.placement.O2.y }
    : { x: t.centre.x + s * pl.x, y: t.centre.y + s * pl.y };
  if (b?.pivot && !task.placement) {
    O2 = {
      x: Math.min(b.pivot.max.x, Math.max(b.pivot.min.x, O2.x)),
      y: Math.min(b.pivot.max.y, Math.max(b.pivot.min.y, O2.y)),
    };
  }
  const th = new Float64Array(t.n);
  problem.thetas(x, th);
  const design: PlacedFourBar = {
    links,
    branch: c.sigma > 0 ? 'open' : 'crossed',
    O2,
    groundAngle: task.placement ? task.placement.groundAngle : wrapAngle(pl.angle),
    pDist,
    pAngle: pDist === 0 ? 0 : wrapAngle(x[L + 5]),
  };
  return { design, theta2: Array.from(th) };
}

/** The solution of a candidate, or null when the design fails a check (bounds, input, assembly). */
function solutionOf(t: NormalisedTask, task: PathTask, c: PathCandidate): PathSolution | null {
  const { design, theta2 } = designOf(t, task, c);
  const { r1, r2, r3, r4 } = design.links;
  if (![r1, r2, r3, r4, design.pDist, design.O2.x, design.O2.y].every(Number.isFinite)) return null;
  if (!(r1 > 0 && r2 > 0 && r3 > 0 && r4 > 0)) return null;
  const lb = task.bounds?.length;
  if (lb && ![r1, r2, r3, r4].every((r) => r >= lb[0] && r <= lb[1])) return null;
  if (t.crank) {
    if (!classify(design.links).inputIsCrank) return null;
  } else if (!sweepWithinRange(r1, r2, r3, r4, Math.min(...theta2), Math.max(...theta2))) return null;
  let error = 0;
  let maxDistance = 0;
  // The error of the θ2 returned (wrapped), so that a caller recomputing it gets the same sum.
  const wrapped = theta2.map((a) => wrapAngle(a));
  for (let i = 0; i < t.n; i++) {
    const P = placedCouplerPoint(design, wrapped[i]);
    if (!P) return null;
    const d = Math.hypot(P.x - task.targets[i].x, P.y - task.targets[i].y);
    error += d * d;
    maxDistance = Math.max(maxDistance, d);
  }
  return { design, theta2: wrapped, error, maxDistance };
}

/** O4 of a placed design, and its coupler point's offset from A in the frame of AB (length unit). */
function pivotAndOffset(d: PlacedFourBar): { O4: Point; offset: Point } {
  return {
    O4: { x: d.O2.x + d.links.r1 * Math.cos(d.groundAngle), y: d.O2.y + d.links.r1 * Math.sin(d.groundAngle) },
    offset: { x: d.pDist * Math.cos(d.pAngle), y: d.pDist * Math.sin(d.pAngle) },
  };
}

/**
 * True when a and b are one linkage: the same branch, and O2, O4, r2, r3, r4 and the coupler point's offset all
 * within SAME_DESIGN of size (the target set's size in the user's unit). Cognates (other pivots) are not the same.
 */
export function sameDesign(a: PlacedFourBar, b: PlacedFourBar, size: number): boolean {
  if (a.branch !== b.branch) return false;
  const tol = SAME_DESIGN * size;
  const close = (p: number, q: number) => Math.abs(p - q) <= tol;
  const near = (p: Point, q: Point) => Math.hypot(p.x - q.x, p.y - q.y) <= tol;
  const pa = pivotAndOffset(a);
  const pb = pivotAndOffset(b);
  return (
    near(a.O2, b.O2) &&
    near(pa.O4, pb.O4) &&
    close(a.links.r2, b.links.r2) &&
    close(a.links.r3, b.links.r3) &&
    close(a.links.r4, b.links.r4) &&
    near(pa.offset, pb.offset)
  );
}

/** A candidate's design in normalised units, as sameDesign compares designs: branch, O2, O4, r2, r3, r4, offset. */
export interface DesignKey {
  sigma: number;
  k: Float64Array;
}

/** The design key of a candidate (normalised units: the size of the targets is 1). */
export function designKey(t: NormalisedTask, c: PathCandidate): DesignKey {
  const lay = pathLayout(t);
  const L = lay.links;
  const x = c.x;
  const o = t.placement ?? { x: x[lay.place], y: x[lay.place + 1], angle: x[lay.place + 2] };
  const [r1, r2, r3, r4, rho, phi] = [x[L], x[L + 1], x[L + 2], x[L + 3], x[L + 4], x[L + 5]];
  return {
    sigma: c.sigma,
    k: Float64Array.from([
      o.x,
      o.y,
      o.x + r1 * Math.cos(o.angle),
      o.y + r1 * Math.sin(o.angle),
      r2,
      r3,
      r4,
      rho * Math.cos(phi),
      rho * Math.sin(phi),
    ]),
  };
}

/** True when two keys are one design by sameDesign's rule (SAME_DESIGN of the size, which is 1 here). */
export function sameKey(a: DesignKey, b: DesignKey): boolean {
  if (a.sigma !== b.sigma) return false;
  const k = a.k;
  const q = b.k;
  const near = (i: number) => Math.hypot(k[i] - q[i], k[i + 1] - q[i + 1]) <= SAME_DESIGN;
  const close = (i: number) => Math.abs(k[i] - q[i]) <= SAME_DESIGN;
  return near(0) && near(2) && close(4) && close(5) && close(6) && near(7);
}

/**
 * Merges candidate lists (from one run or from several workers' slices), polishes the best, and returns the
 * checked, distinct answers best first (at most MAX_SOLUTIONS). At least POLISHED candidates are polished; past
 * them, polishing goes on (to POLISHED_MAX) while fewer than MAX_SOLUTIONS distinct answers are in hand, skipping
 * candidates that are already, unpolished, the same design as an answer. Deterministic in its input unless the
 * deadline (Date.now(), ms) or the signal cuts the polishing short.
 */
export function screenCandidates(
  t: NormalisedTask,
  task: PathTask,
  lists: PathCandidate[][],
  deadline = Infinity,
  signal?: { readonly aborted: boolean },
): PathSolution[] {
  const all = lists.flat().filter((c) => Number.isFinite(c.f));
  all.sort((a, b) => a.f - b.f || a.sigma - b.sigma || a.dir - b.dir);
  const m = pathLayout(t).m;
  const polish = (c: PathCandidate, long: boolean, maxIterations: number): PathCandidate => {
    const problem = createPathProblem(t, c.sigma, c.dir);
    const options = { maxIterations, fTarget: EXACT_F, deadline, signal };
    let r = levenbergMarquardt(problem.lsq, Float64Array.from(c.x), options);
    for (let restart = 0; long && restart < POLISH_RESTARTS; restart++) {
      const again = levenbergMarquardt(problem.lsq, r.x, options);
      if (!(again.f < r.f * (1 - 1e-12))) break;
      r = again;
    }
    return r.f <= c.f ? { ...c, x: Array.from(r.x), f: r.f } : c;
  };
  const polished: PathCandidate[] = [];
  let answers: { sol: PathSolution; c: PathCandidate; key: DesignKey; long: boolean }[] = [];
  /** Adds an answer, or keeps the better of two that are one linkage. */
  const offer = (c: PathCandidate, long: boolean, list: typeof answers) => {
    const sol = solutionOf(t, task, c);
    if (!sol || !Number.isFinite(sol.error)) return;
    const same = list.findIndex((o) => sameDesign(o.sol.design, sol.design, t.scale));
    const entry = { sol, c, key: designKey(t, c), long };
    if (same < 0) list.push(entry);
    else if (sol.error < list[same].sol.error) list[same] = entry;
  };
  for (const c of all) {
    if (polished.length >= POLISHED_MAX) break;
    if (polished.length >= POLISHED && answers.length >= MAX_SOLUTIONS) break;
    if (c.x.length !== m) continue;
    // Skip near-copies before spending a polish on them.
    if (polished.some((p) => p.sigma === c.sigma && p.x.every((v, i) => Math.abs(v - c.x[i]) <= 1e-6))) continue;
    if (polished.length >= POLISHED && answers.some((a) => sameKey(a.key, designKey(t, c)))) continue;
    const long = polished.length < POLISH_LONG;
    const p = polish(c, long, long ? POLISH_LONG_ITERATIONS : POLISH_ITERATIONS);
    polished.push(p);
    offer(p, long, answers);
  }
  // Every answer listed gets a longer polish (the best ten only: the rest are not shown).
  answers.sort((a, b) => a.sol.error - b.sol.error);
  const final: typeof answers = [];
  for (const a of answers.slice(0, MAX_SOLUTIONS))
    offer(a.long ? a.c : polish(a.c, true, POLISH_ANSWER_ITERATIONS), true, final);
  answers = final;
  const out = answers.map((a) => a.sol);
  out.sort((a, b) => a.error - b.error);
  return out.slice(0, MAX_SOLUTIONS);
}
