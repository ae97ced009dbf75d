/**
 * Published path-synthesis designs in the papers' own variables, and what the bench and the tests need to recompute
 * a published Σd² from its design instead of quoting the paper's number (issue 34 item 6). Data and double-precision
 * helpers only: the 50-digit recomputation is in literatureDesign.test.ts.
 *
 * The papers' coupler point (Cabrera et al. 2002; Acharyya & Mandal 2009):
 *   C(θ2) = (x0, y0) + R(θ0) [r2 e(θ2) + rcx e(θ3) + rcy e⊥(θ3)],
 * θ2 measured from the ground link, θ3 the coupler's angle on the assembly drawn. So (x0, y0) is our O2, θ0 our
 * groundAngle, and (rcx, rcy) = |AP| (cos pAngle, sin pAngle) in the coupler's frame (A to B along x).
 */
import { classify } from '../../src/solver';
import { placedCouplerPoint } from '../../src/synthesis';
import type { PathTask, PlacedFourBar } from '../../src/synthesis';

/** A published design: lengths, coupler point and placement (the papers' names), and its crank angles. */
export interface LiteratureDesign {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
  rcx: number;
  rcy: number;
  /** Ground-link angle (radians). */
  theta0: number;
  x0: number;
  y0: number;
  /**
   * θ2 at each target (radians, from the ground link) as published, for free timing; for step timing the first
   * target's θ2 alone is enough. A given-timing case uses the task's θ2.
   */
  theta2?: number[];
  /** The assembly the paper draws; when it does not say, the better of the two is taken (and reported). */
  branch?: 'open' | 'crossed';
}

/** The design as our PlacedFourBar on a branch. */
export function placedFromLiterature(d: LiteratureDesign, branch: 'open' | 'crossed'): PlacedFourBar {
  return {
    links: { r1: d.r1, r2: d.r2, r3: d.r3, r4: d.r4 },
    branch,
    O2: { x: d.x0, y: d.y0 },
    groundAngle: d.theta0,
    pDist: Math.hypot(d.rcx, d.rcy),
    pAngle: Math.atan2(d.rcy, d.rcx),
  };
}

/** The design's θ2 at every target under the task's timing (radians), or null when the paper gave none. */
export function literatureTheta2(d: LiteratureDesign, task: PathTask): number[] | null {
  const n = task.targets.length;
  const t = task.timing;
  if (t.kind === 'given') return t.theta2.slice();
  if (!d.theta2?.length) return null;
  if (t.kind === 'step') return Array.from({ length: n }, (_, i) => d.theta2![0] + i * t.step);
  return d.theta2.length === n ? d.theta2.slice() : null;
}

/** Σd² of a placed design at the θ2 given, in doubles by the product's own kinematics; Infinity where it cannot assemble. */
export function designError(design: PlacedFourBar, theta2: number[], targets: { x: number; y: number }[]): number {
  let f = 0;
  for (let i = 0; i < targets.length; i++) {
    const p = placedCouplerPoint(design, theta2[i]);
    if (!p) return Infinity;
    f += (p.x - targets[i].x) ** 2 + (p.y - targets[i].y) ** 2;
  }
  return f;
}

/** A published design's Σd² recomputed from its parameters, with the branch and θ2 used and the task's constraints it breaks. */
export interface RecomputedDesign {
  f: number;
  branch: 'open' | 'crossed';
  theta2: number[];
  violations: string[];
}

/**
 * Recomputes a published design's Σd² for the task (on its stated branch, else the better one), or returns null
 * when the design lacks the θ2 the task's timing needs.
 */
export function recomputePublished(d: LiteratureDesign, task: PathTask): RecomputedDesign | null {
  const theta2 = literatureTheta2(d, task);
  if (!theta2) return null;
  const branches: ('open' | 'crossed')[] = d.branch ? [d.branch] : ['open', 'crossed'];
  let best: RecomputedDesign | null = null;
  for (const branch of branches) {
    const design = placedFromLiterature(d, branch);
    const f = designError(design, theta2, task.targets);
    if (!best || f < best.f) best = { f, branch, theta2, violations: taskViolations(design, theta2, task) };
  }
  return best;
}

/**
 * What a design breaks of the task: length, coupler and pivot bounds, a crank input (unless the task allows any),
 * assembly at each θ2, and for free timing the targets' order within one turn. Empty when it meets them all.
 */
export function taskViolations(design: PlacedFourBar, theta2: number[], task: PathTask): string[] {
  const out: string[] = [];
  const b = task.bounds;
  const l = design.links;
  if (b?.length) {
    for (const [k, r] of Object.entries(l)) {
      if (r < b.length[0] || r > b.length[1]) out.push(`${k} = ${r} outside [${b.length[0]}, ${b.length[1]}]`);
    }
  }
  if (b?.coupler !== undefined && design.pDist > b.coupler) out.push(`|AP| = ${design.pDist} above ${b.coupler}`);
  const pv = b?.pivot;
  if (pv && (design.O2.x < pv.min.x || design.O2.x > pv.max.x || design.O2.y < pv.min.y || design.O2.y > pv.max.y)) {
    out.push(`O2 = (${design.O2.x}, ${design.O2.y}) outside the pivot box`);
  }
  if ((task.input ?? 'crank') === 'crank' && !classify(l).inputIsCrank) out.push('the input is not a crank');
  theta2.forEach((t, i) => {
    if (!placedCouplerPoint(design, t)) out.push(`does not assemble at target ${i + 1}`);
  });
  if (task.timing.kind === 'free' && !inOrder(theta2)) out.push('targets not reached in order within one turn');
  return out;
}

/** True when the angles advance one way (either) and span less than a turn: the targets are met in order. */
function inOrder(theta2: number[]): boolean {
  const turn = 2 * Math.PI;
  const steps = theta2.slice(1).map((t, i) => (((t - theta2[i]) % turn) + turn) % turn);
  const up = steps.reduce((a, s) => a + s, 0);
  const down = steps.reduce((a, s) => a + (s === 0 ? 0 : turn - s), 0);
  return Math.min(up, down) < turn;
}

/**
 * True when a recomputed Σd² rounds to the claim at the claim's own significant digits (as printed: 1.21622 has six),
 * i.e. the design reproduces what its paper says of it.
 */
export function reproducesClaim(claim: number, f: number): boolean {
  if (claim === 0) return f === 0;
  const mantissa = claim.toExponential().split('e')[0].replace('-', '').replace('.', '');
  return Number(f.toPrecision(mantissa.length)) === claim;
}
