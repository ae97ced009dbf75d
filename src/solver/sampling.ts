import { TWO_PI, angleDiff } from './angles';
import { classify } from './classify';
import { Assembly, branchSign, closedFormAt, newClosedFormPoint, planClosedForm } from './closedForm';
import { MAX_SWEEP_POINTS, SWEEP_METHODS, sweep } from './sweep';
import type { Branch, Linkage, SweepMethod, SweepResult } from './types';
import { checkFinite, checkObject, checkOptionalPositive, describe } from './validate';

/** Options of adaptiveGrid. Angles in radians. */
export interface AdaptiveGridOptions {
  /** Branches whose curves the grid must resolve: a non-empty array (default both). */
  branches?: readonly Branch[];
  /** Width of the plot in device pixels, positive: the base grid has about one sample per pixel, 8 to 100000 (default 360). */
  pixels?: number;
  /** Start of the input range, finite, |startRad| <= MAX_GRID_ANGLE_RAD (default 0). */
  startRad?: number;
  /** End of the input range, finite, above startRad, |endRad| <= MAX_GRID_ANGLE_RAD (default 2 pi). */
  endRad?: number;
  /** Largest change of theta3 or theta4 (radians, positive) between neighbours before a midpoint is added (default 2 deg). */
  maxJumpRad?: number;
  /** Cap on the number of samples, a positive integer; the base grid is always kept (default 8 x the base grid). */
  maxPoints?: number;
}

/**
 * Largest |startRad| and |endRad| adaptiveGrid takes (1e6 rad, about 160 000 turns): beyond it the
 * doubles are too coarse (ulp > 1e-10 rad) for the refinement towards limits to mean anything.
 */
export const MAX_GRID_ANGLE_RAD = 1e6;

/** Options of adaptiveSweep. */
export interface AdaptiveSweepOptions extends Omit<AdaptiveGridOptions, 'branches'> {
  branch: Branch;
  /** Sweep method for the final pass (default: the sweep default). */
  method?: SweepMethod;
}

/** adaptiveSweep's answer: the sweep on the chosen grid and how much refinement it took. */
export interface AdaptiveSweepResult extends SweepResult {
  /** Samples of the uniform base grid. */
  baseCount: number;
  /** Samples added near limits and where the curves turn fast. */
  refinedCount: number;
}

const MIN_SPACING = 1e-9;
const MAX_PASSES = 24;

/**
 * Input angles (radians, increasing) that sample the cycle as densely as a plot needs and no more:
 * one sample per pixel, plus the exact limit angles of the input's reachable range with geometric
 * refinement towards them (angles move like sqrt(distance) there), plus bisection wherever a curve
 * of one of the branches turns faster than maxJumpRad between neighbours (near-toggle positions).
 * The grid is chosen with the closed form. opts may be omitted (all defaults). Throws an Error naming
 * the option for a bad linkage, opts not an object, bad branches, pixels, startRad, endRad (finite,
 * within MAX_GRID_ANGLE_RAD, endRad > startRad), maxJumpRad or maxPoints.
 */
export function adaptiveGrid(l: Linkage, opts: AdaptiveGridOptions = {}): Float64Array {
  const plan = planClosedForm(l);
  checkObject('opts', opts);
  const branches = opts.branches === undefined ? (['open', 'crossed'] as const) : opts.branches;
  if (!Array.isArray(branches) || branches.length === 0) {
    throw new Error(`branches must be a non-empty array of 'open' and 'crossed', got ${describe(branches)}`);
  }
  const sigmas = branches.map(branchSign);
  const start = opts.startRad === undefined ? 0 : opts.startRad;
  const end = opts.endRad === undefined ? TWO_PI : opts.endRad;
  checkFinite('startRad', start, 'angle in radians');
  checkFinite('endRad', end, 'angle in radians');
  for (const [name, v] of [
    ['startRad', start],
    ['endRad', end],
  ] as const) {
    if (Math.abs(v) > MAX_GRID_ANGLE_RAD)
      throw new Error(`${name} must be within +-${MAX_GRID_ANGLE_RAD} rad, got ${v}`);
  }
  if (!(end > start)) throw new Error(`endRad must exceed startRad (${start}), got ${end}`);
  const base = baseCount(opts.pixels);
  checkOptionalPositive('maxJumpRad', opts.maxJumpRad);
  const maxJump = opts.maxJumpRad ?? TWO_PI / 180;
  const mp = opts.maxPoints;
  if (mp !== undefined && (typeof mp !== 'number' || !Number.isInteger(mp) || mp < 1 || mp > MAX_SWEEP_POINTS)) {
    throw new Error(`maxPoints must be an integer from 1 to ${MAX_SWEEP_POINTS}, got ${describe(mp)}`);
  }
  const maxPoints = mp ?? 8 * (base + 1);
  const step = (end - start) / base;
  const grid = new Set<number>();
  for (let i = 0; i <= base; i++) grid.add(i === base ? end : start + i * step);

  const { inputRange } = classify(l);
  if (!inputRange.full) {
    // The limit angles in every turn of [start, end], each with geometric refinement towards it,
    // until the sample budget is spent.
    for (const iv of inputRange.intervals) {
      for (const lim of [iv.lo, iv.hi]) {
        const kFirst = Math.ceil((start - lim) / TWO_PI);
        const kLast = Math.floor((end - lim) / TWO_PI);
        for (let k = kFirst; k <= kLast && grid.size < maxPoints; k++) {
          const t = lim + TWO_PI * k;
          if (t < start || t > end) continue;
          grid.add(t);
          for (let d = step / 2; d > MIN_SPACING; d /= 4) {
            if (t - d >= start) grid.add(t - d);
            if (t + d <= end) grid.add(t + d);
          }
        }
      }
    }
  }

  const p = newClosedFormPoint();
  type Pose = Array<{ t3: number; t4: number } | null>;
  const solve = (t: number): Pose =>
    sigmas.map((sigma) => {
      const a = closedFormAt(plan, t, sigma, p);
      return a === Assembly.Ok || a === Assembly.Limit ? { t3: p.theta3, t4: p.theta4 } : null;
    });
  const fastOrEdge = (a: Pose, b: Pose, gap: number): boolean =>
    a.some((pa, k) => {
      const pb = b[k];
      if (pa !== null && pb !== null) {
        return Math.max(Math.abs(angleDiff(pb.t3, pa.t3)), Math.abs(angleDiff(pb.t4, pa.t4))) > maxJump;
      }
      return (pa === null) !== (pb === null) && gap > step * 1e-6;
    });
  let xs = [...grid].sort((a, b) => a - b);
  let poses = xs.map(solve);
  for (let pass = 0; pass < MAX_PASSES && xs.length < maxPoints; pass++) {
    const nx: number[] = [];
    const np: Pose[] = [];
    let added = 0;
    for (let i = 0; i < xs.length; i++) {
      nx.push(xs[i]);
      np.push(poses[i]);
      if (i + 1 === xs.length) break;
      const gap = xs[i + 1] - xs[i];
      if (gap < 2 * MIN_SPACING || xs.length + added >= maxPoints) continue;
      if (fastOrEdge(poses[i], poses[i + 1], gap)) {
        const mid = xs[i] + gap / 2;
        nx.push(mid);
        np.push(solve(mid));
        added++;
      }
    }
    xs = nx;
    poses = np;
    if (added === 0) break;
  }
  return Float64Array.from(xs);
}

/** Intervals of the base grid for a plot `pixels` wide (validated: a positive finite number). */
function baseCount(pixels: unknown): number {
  checkOptionalPositive('pixels', pixels);
  return Math.max(8, Math.min(100_000, Math.round(pixels ?? 360)));
}

/**
 * adaptiveGrid for one branch, then the requested sweep method over that grid. Throws an Error naming
 * the option for a bad linkage, branch, method or any adaptiveGrid option.
 */
export function adaptiveSweep(l: Linkage, opts: AdaptiveSweepOptions): AdaptiveSweepResult {
  checkObject('opts', opts);
  if (opts.method !== undefined && !SWEEP_METHODS.includes(opts.method)) {
    throw new Error(`method must be one of ${SWEEP_METHODS.join(', ')}, got ${describe(opts.method)}`);
  }
  const grid = adaptiveGrid(l, { ...opts, branches: [opts.branch] });
  const result = sweep(l, grid, { branch: opts.branch, method: opts.method });
  const base = baseCount(opts.pixels);
  return Object.assign(result, { baseCount: base + 1, refinedCount: grid.length - (base + 1) });
}
