import { TWO_PI, angleDiff } from './angles';
import { classify } from './classify';
import { Assembly, branchSign, closedFormAt, newClosedFormPoint, planClosedForm } from './closedForm';
import { sweep } from './sweep';
import type { Branch, Linkage, SweepMethod, SweepResult } from './types';

/** Options of adaptiveGrid. Angles in radians. */
export interface AdaptiveGridOptions {
  /** Branches whose curves the grid must resolve (default both). */
  branches?: readonly Branch[];
  /** Width of the plot in device pixels: the base grid has about one sample per pixel (default 360). */
  pixels?: number;
  /** Start of the input range (default 0). */
  startRad?: number;
  /** End of the input range (default 2 pi). */
  endRad?: number;
  /** Largest change of theta3 or theta4 (radians) between neighbours before a midpoint is added (default 2 deg). */
  maxJumpRad?: number;
  /** Hard cap on the number of samples (default 8 x the base grid). */
  maxPoints?: number;
}

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
 * The grid is chosen with the closed form. Throws for a bad linkage.
 */
export function adaptiveGrid(l: Linkage, opts: AdaptiveGridOptions): Float64Array {
  const plan = planClosedForm(l);
  const sigmas = (opts.branches ?? ['open', 'crossed']).map(branchSign);
  const start = opts.startRad ?? 0;
  const end = opts.endRad ?? TWO_PI;
  if (!(end > start)) throw new Error(`endRad must exceed startRad, got ${start}..${end}`);
  const base = Math.max(8, Math.min(100_000, Math.round(opts.pixels ?? 360)));
  const maxJump = opts.maxJumpRad ?? TWO_PI / 180;
  const maxPoints = opts.maxPoints ?? 8 * (base + 1);
  const step = (end - start) / base;
  const grid = new Set<number>();
  for (let i = 0; i <= base; i++) grid.add(i === base ? end : start + i * step);

  const { inputRange } = classify(l);
  if (!inputRange.full) {
    for (const iv of inputRange.intervals) {
      for (const lim of [iv.lo, iv.hi]) {
        for (let k = -2; k <= 2; k++) {
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

/**
 * adaptiveGrid for one branch, then the requested sweep method over that grid. Throws for a bad linkage.
 */
export function adaptiveSweep(l: Linkage, opts: AdaptiveSweepOptions): AdaptiveSweepResult {
  const grid = adaptiveGrid(l, { ...opts, branches: [opts.branch] });
  const result = sweep(l, grid, { branch: opts.branch, method: opts.method });
  const base = Math.max(8, Math.min(100_000, Math.round(opts.pixels ?? 360)));
  return { ...result, baseCount: base + 1, refinedCount: grid.length - (base + 1) };
}
