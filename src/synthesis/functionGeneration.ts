/**
 * Function generation: a four-bar whose output angle θ4 follows its input angle θ2 as y = f(x).
 *
 * Freudenstein's equation (Freudenstein 1955) in the app's conventions (O2 at the origin, O4 at (r1, 0), θ2 and
 * θ4 from the ground line): the loop r2 e^{iθ2} + r3 e^{iθ3} = r1 + r4 e^{iθ4} gives
 * r3² = |r1 + r4 e^{iθ4} − r2 e^{iθ2}|², which divided by 2 r2 r4 reads
 *   K1 cos θ4 − K2 cos θ2 + K3 = cos(θ2 − θ4),  K1 = r1/r2, K2 = r1/r4, K3 = (r1² + r2² − r3² + r4²) / (2 r2 r4).
 * It is linear in K1, K2, K3: three pairs fix them, more are fitted by least squares.
 */
import { PI, angleDiff, inputRange, solveClosedForm } from '../solver';
import type { Branch, Linkage } from '../solver';
import { leastSquares } from './dense';
import { triangleAngle } from '../solver/triangle';
import { normalizeLinkage } from '../solver/validate';
import { checkArray, checkFiniteNumber, checkPositive, show } from './validate';

/** A prescribed input/output angle pair (radians, from the ground line O2→O4). */
export interface AnglePair {
  theta2: number;
  theta4: number;
}

/** A function-generator design: lengths with r1 as asked, the branch reproducing the pairs, the equation's residual. */
export interface FreudensteinDesign {
  links: Linkage;
  branch: Branch;
  /** ‖K1 cos θ4 − K2 cos θ2 + K3 − cos(θ2 − θ4)‖₂ over the pairs (dimensionless); 0 to rounding for three pairs. */
  residual: number;
}

/**
 * Why no real linkage fits: the crank (r2) or the rocker (r4) would point opposite its angle, the coupler's r3² is
 * not a positive real, or the equations are singular (the pairs do not determine the K's).
 */
export type NoLinkageReason = 'crank' | 'rocker' | 'coupler' | 'singular';

/**
 * What freudenstein and functionGenerator throw when no real linkage fits the pairs: the reason and the length
 * that came out wrong in units of r1 (r2 or r4; r3² for 'coupler'; NaN for 'singular'), so a page can say it in
 * its own words.
 */
export class NoLinkageError extends Error {
  readonly reason: NoLinkageReason;
  readonly value: number;
  constructor(reason: NoLinkageReason, value: number, message: string) {
    super(message);
    this.name = 'NoLinkageError';
    this.reason = reason;
    this.value = value;
  }
}

/** Most pairs freudenstein accepts (a least-squares fit of more is no better conditioned). */
export const MAX_PAIRS = 10000;

/**
 * The four-bar whose θ4 meets each pair's θ4 at its θ2 (radians): exact for three pairs, least squares on
 * Freudenstein's equation for more; lengths scaled so r1 = options.r1 (default 1). Throws for bad pairs, for
 * pairs that do not determine the K's (repeated or degenerate pairs) and when no real linkage fits (a length
 * that would be negative, zero, infinite or imaginary): those two as a NoLinkageError.
 */
export function freudenstein(pairs: readonly AnglePair[], options: { r1?: number } = {}): FreudensteinDesign {
  checkArray('pairs', pairs, 3, MAX_PAIRS);
  // An index loop, not forEach: a sparse array's holes are pairs too, and must be named.
  for (let i = 0; i < pairs.length; i++) {
    const p: unknown = pairs[i];
    if (typeof p !== 'object' || p === null) throw new Error(`pairs[${i}] must be {theta2, theta4}, got ${show(p)}`);
    const q = p as Record<string, unknown>;
    checkFiniteNumber(`pairs[${i}].theta2`, q.theta2, 'angle in radians');
    checkFiniteNumber(`pairs[${i}].theta4`, q.theta4, 'angle in radians');
  }
  if (typeof options !== 'object' || options === null)
    throw new Error(`options must be an object, got ${show(options)}`);
  const r1 = options.r1 ?? 1;
  checkPositive('options.r1', r1, 'length');
  const rows = pairs.map((p) => [Math.cos(p.theta4), -Math.cos(p.theta2), 1]);
  // cos(θ2 − θ4) from the wrapped difference: exact for huge angles, where cos(θ2) cos(θ4) + … would not be.
  const rhs = pairs.map((p) => Math.cos(angleDiff(p.theta2, p.theta4)));
  const fit = leastSquares(rows, rhs);
  if (!fit) {
    throw new NoLinkageError(
      'singular',
      NaN,
      'pairs do not determine a linkage: Freudenstein’s equations are singular (repeated pairs, or all θ2 or all θ4 with the same cosine)',
    );
  }
  const [K1, K2, K3] = fit.x;
  // The lengths are ratios of r1: formed with r1 = 1 (no r1² to overflow past 1.3e154 or to go subnormal below
  // 1e-154), then scaled; the branch, which does not depend on the scale, is read on the unit linkage.
  const unit = linksFromK(K1, K2, K3, 1);
  const links = { r1, r2: unit.r2 * r1, r3: unit.r3 * r1, r4: unit.r4 * r1 };
  for (const k of ['r2', 'r3', 'r4'] as const) {
    if (!(links[k] > 0) || !Number.isFinite(links[k])) {
      throw new Error(
        `options.r1 = ${show(r1)} puts ${k} = ${show(unit[k])} r1 outside the double range (${show(links[k])}); choose a smaller or larger r1`,
      );
    }
  }
  return { links, branch: bestBranch(unit, pairs), residual: fit.residual };
}

/** Link lengths from Freudenstein's K's with ground r1; throws naming the length when it is not a positive real. */
function linksFromK(K1: number, K2: number, K3: number, r1: number): Linkage {
  const r2 = r1 / K1;
  const r4 = r1 / K2;
  // A negative r2 (or r4) is a crank (rocker) pointing opposite the prescribed angle: it fits only with θ2 (θ4)
  // shifted by π, which is another set of pairs, so no linkage with the prescribed angles exists.
  const bad = (reason: NoLinkageReason, name: string, v: number, why: string): never => {
    throw new NoLinkageError(reason, v, `no real linkage fits these pairs: ${name} would be ${show(v)} (${why})`);
  };
  if (!(r2 > 0) || !Number.isFinite(r2)) bad('crank', 'r2', r2, 'the crank would have to point opposite θ2');
  if (!(r4 > 0) || !Number.isFinite(r4)) bad('rocker', 'r4', r4, 'the rocker would have to point opposite θ4');
  const r3sq = r1 * r1 + r2 * r2 + r4 * r4 - 2 * r2 * r4 * K3;
  if (!(r3sq > 0) || !Number.isFinite(r3sq)) bad('coupler', 'r3²', r3sq, 'the coupler length is not a positive real');
  return { r1, r2, r3: Math.sqrt(r3sq), r4 };
}

/** Per pair, |θ4 error| (radians) on each branch: Infinity where the loop cannot close. */
export function branchErrors(links: Linkage, pairs: readonly AnglePair[]): { open: number; crossed: number }[] {
  return pairs.map((p) => {
    const err = (b: Branch) => {
      const a = solveClosedForm(links, p.theta2, b);
      return a ? Math.abs(angleDiff(a.theta4, p.theta4)) : Infinity;
    };
    return { open: err('open'), crossed: err('crossed') };
  });
}

/** The branch nearer more pairs' θ4 (ties: the smaller summed squared error; then open). */
function bestBranch(links: Linkage, pairs: readonly AnglePair[]): Branch {
  let votes = 0;
  let open = 0;
  let crossed = 0;
  for (const e of branchErrors(links, pairs)) {
    votes += e.open < e.crossed ? 1 : e.open > e.crossed ? -1 : 0;
    open += e.open * e.open;
    crossed += e.crossed * e.crossed;
  }
  if (votes !== 0) return votes > 0 ? 'open' : 'crossed';
  return crossed < open ? 'crossed' : 'open';
}

/** What functionGenerator is asked for: f on [x0, x1] mapped linearly onto the θ2 and θ4 ranges (radians). */
export interface FunctionTask {
  f: (x: number) => number;
  x: [number, number];
  theta2: [number, number];
  theta4: [number, number];
  /** Precision points, an integer from 3 to MAX_PRECISION_POINTS; three are exact, more are fitted by least squares. */
  points: number;
  /** Ground length (default 1). */
  r1?: number;
  /** Evenly spaced samples of the structural error, both ends included: an integer from 50 to 10001 (default 101). */
  samples?: number;
}

/** Defects of a function generator (see functionGenerator). */
export type FunctionDefect = 'limit' | 'branch' | 'not-assemblable';

/** A function-generator design with its precision points, structural error and defects. */
export interface FunctionGeneratorResult extends FreudensteinDesign {
  precision: { x: number; theta2: number; theta4: number }[];
  /** y generated − f(x) at evenly spaced x; NaN where the loop cannot close. */
  structuralError: { x: number; error: number }[];
  /** Largest |error| over the samples; Infinity when some sample cannot be assembled. */
  maxError: number;
  defects: FunctionDefect[];
}

/** Most precision points functionGenerator accepts. */
export const MAX_PRECISION_POINTS = 50;

/** Chebyshev spacing of n points on [x0, x1], ascending: x_j = (x0+x1)/2 − (x1−x0)/2 · cos((2j−1)π/(2n)). */
export function chebyshevPoints(x0: number, x1: number, n: number): number[] {
  // Halves first: no overflow for any finite x0, x1.
  const mid = x0 / 2 + x1 / 2;
  const half = x1 / 2 - x0 / 2;
  return Array.from({ length: n }, (_, k) => mid - half * Math.cos(((2 * k + 1) * PI) / (2 * n)));
}

/**
 * A four-bar generating y = f(x) on [x0, x1]: x maps linearly onto θ2 (x0 → theta2[0], x1 → theta2[1]) and y onto
 * θ4 (f(x0) → theta4[0], f(x1) → theta4[1]), radians from the ground line; Freudenstein at Chebyshev-spaced
 * precision points. Returns the design, the precision points, the structural error y generated − f(x) on the
 * design's branch (by the solver's closed form) and the defects: 'not-assemblable' (some θ2 in the range cannot
 * close the loop), 'limit' (the output reaches a dead centre and turns back, or the input reaches the end of its
 * range, within the motion) and 'branch' (some precision pair lies on the other branch). Throws for bad input
 * (naming it) and, as freudenstein, when no real linkage fits.
 */
export function functionGenerator(task: FunctionTask): FunctionGeneratorResult {
  if (typeof task !== 'object' || task === null) throw new Error(`task must be an object, got ${show(task)}`);
  const { f, points } = task;
  if (typeof f !== 'function') throw new Error(`f must be a function of one number, got ${show(f)}`);
  const x = checkRange('x', task.x, '');
  const t2 = checkRange('theta2', task.theta2, 'angle in radians');
  const t4 = checkRange('theta4', task.theta4, 'angle in radians');
  if (!Number.isInteger(points) || points < 3 || points > MAX_PRECISION_POINTS) {
    throw new Error(`points must be an integer from 3 to ${MAX_PRECISION_POINTS}, got ${show(points)}`);
  }
  const samples = task.samples ?? 101;
  if (!Number.isInteger(samples) || samples < 50 || samples > 10001) {
    throw new Error(`samples must be an integer from 50 to 10001, got ${show(samples)}`);
  }
  const y = (v: number): number => {
    const out = f(v);
    if (typeof out !== 'number' || !Number.isFinite(out))
      throw new Error(`f(${v}) must be a finite number, got ${show(out)}`);
    return out;
  };
  const y0 = y(x[0]);
  const y1 = y(x[1]);
  if (y0 === y1) throw new Error(`f(x0) and f(x1) must differ to map y onto θ4, got f(${x[0]}) = f(${x[1]}) = ${y0}`);
  // Differences of x and of y are formed from halves, so a range as wide as the doubles (x from −1.7e308 to
  // 1.7e308, or f's values there) maps without overflow; halving is exact above the subnormals.
  const xHalf = x[1] / 2 - x[0] / 2;
  const yHalf = y1 / 2 - y0 / 2;
  const theta2Of = (v: number) => t2[0] + ((v / 2 - x[0] / 2) / xHalf) * (t2[1] - t2[0]);
  const theta4Of = (w: number) => t4[0] + ((w / 2 - y0 / 2) / yHalf) * (t4[1] - t4[0]);
  const precision = chebyshevPoints(x[0], x[1], points).map((v) => ({
    x: v,
    theta2: theta2Of(v),
    theta4: theta4Of(y(v)),
  }));
  const design = freudenstein(precision, { r1: task.r1 });

  // y generated − f(x) = (θ4 generated − θ4 wanted) (y1 − y0) / (θ4 end − θ4 start), the difference wrapped so
  // that a range crossing ±π reads right.
  const halfYPerRad = yHalf / (t4[1] - t4[0]);
  const structuralError: { x: number; error: number }[] = [];
  let maxError = 0;
  for (let k = 0; k < samples; k++) {
    const step = xHalf * (k / (samples - 1));
    const v = k === samples - 1 ? x[1] : x[0] + step + step;
    const a = solveClosedForm(design.links, theta2Of(v), design.branch);
    const error = a ? angleDiff(a.theta4, theta4Of(y(v))) * halfYPerRad * 2 : NaN;
    structuralError.push({ x: v, error });
    maxError = Number.isNaN(error) ? Infinity : Math.max(maxError, Math.abs(error));
  }

  const defects: FunctionDefect[] = [];
  const lo = Math.min(t2[0], t2[1]);
  const hi = Math.max(t2[0], t2[1]);
  const reach = inputMotion(design.links, lo, hi);
  if (!reach.assembles || structuralError.some((s) => Number.isNaN(s.error))) defects.push('not-assemblable');
  if (reach.inputLimit || outputTurnsBack(design.links, design.branch, lo, hi)) defects.push('limit');
  const wrong = design.branch === 'open' ? 'crossed' : 'open';
  if (branchErrors(design.links, precision).some((e) => e[wrong] < e[design.branch])) defects.push('branch');
  return { ...design, precision, structuralError, maxError, defects };
}

/** A finite, non-degenerate [start, end] pair; throws naming the parameter. */
function checkRange(name: string, v: unknown, what: string): [number, number] {
  if (!Array.isArray(v) || v.length !== 2) throw new Error(`${name} must be [start, end], got ${show(v)}`);
  checkFiniteNumber(`${name}[0]`, v[0], what || 'number');
  checkFiniteNumber(`${name}[1]`, v[1], what || 'number');
  if (v[0] === v[1]) throw new Error(`${name} must have start ≠ end, got ${show(v)}`);
  return [v[0], v[1]];
}

/**
 * Whether every θ2 in [lo, hi] (radians) closes the loop, and whether an end of the input's range (a limit where
 * coupler and rocker are collinear) lies in [lo, hi].
 */
export function inputMotion(links: Linkage, lo: number, hi: number): { assembles: boolean; inputLimit: boolean } {
  const range = inputRange(links);
  if (range.full) return { assembles: true, inputLimit: false };
  const turn = 2 * PI;
  const mod = (v: number) => v - turn * Math.floor(v / turn);
  let assembles = false;
  let inputLimit = false;
  for (const iv of range.intervals) {
    if (iv.lo + mod(lo - iv.lo) + (hi - lo) <= iv.hi) assembles = true;
    for (const end of [iv.lo, iv.hi]) if (lo + mod(end - lo) <= hi) inputLimit = true;
  }
  return { assembles, inputLimit };
}

/**
 * Whether the output turns back (crank and coupler collinear, dθ4/dθ2 = 0) at some θ2 strictly inside (lo, hi) on
 * the branch. Those θ2 are the triangle O2 O4 B with |O2 B| = r2 + r3 (extended) or |r3 − r2| (folded): at each
 * candidate the branch's own pose decides whether it is the collinear one (|sin(θ3 − θ2)| small).
 */
export function outputTurnsBack(links: Linkage, branch: Branch, lo: number, hi: number): boolean {
  const { r1, r2, r3, r4 } = links;
  const turn = 2 * PI;
  const candidates: number[] = [];
  // The angle at O2 of the triangle O2 O4 B, by the solver's cancellation-free half-angle form (as its dead centres).
  const n = normalizeLinkage(links);
  for (const [d, flip] of [
    [[n.r2, n.r3], 0],
    [r3 > r2 ? [n.r3, -n.r2] : [n.r2, -n.r3], r3 > r2 ? PI : 0],
  ] as const) {
    if (!(d[0] + d[1] > 0)) continue;
    const alpha = triangleAngle([n.r1], d, [n.r4]);
    if (!alpha.closes) continue;
    candidates.push(alpha.angle + flip, -alpha.angle + flip);
  }
  const scale = Math.max(r1, r2, r3, r4);
  for (const t of candidates) {
    const inside = lo + (t - lo - turn * Math.floor((t - lo) / turn));
    if (!(inside > lo && inside < hi)) continue;
    const a = solveClosedForm(links, t, branch);
    // On the collinear branch sin(θ3 − θ2) vanishes to rounding (the closed form loses half the digits at a limit,
    // hence about the square root of ε); on the other branch it is of the order of the branch separation.
    if (a && Math.abs(Math.sin(a.theta3 - t)) <= 1e-6 * Math.max(1, scale / Math.min(r2, r3))) return true;
  }
  return false;
}
