import { angleDiff, radToDeg } from '../solver/angles';
export { distanceToNearestLimitDeg } from './limits';
import { LAB_TOLERANCES } from './options';
import { classify } from '../solver/classify';
import { sweep, theta2Grid } from '../solver/sweep';
import type { Angles, Branch, Linkage, SweepMethod, SweepResult } from '../solver/types';

export { LAB_TOLERANCES } from './options';

/** An angle error this large is not rounding: the point is on the wrong branch or not a solution (rad). */
export const GROSS_ERROR_RAD = 1e-6;

/** One method of the lab, traced over tolerances when `traced`. */
export interface LabMethod {
  method: SweepMethod;
  label: string;
  traced: boolean;
}

/** The lab's methods: at least the five of the benchmark. */
export const LAB_METHODS: readonly LabMethod[] = [
  { method: 'closed-form', label: 'Closed form', traced: false },
  { method: 'closed-form-polish', label: 'Closed form + NR polish', traced: false },
  { method: 'newton', label: 'NR + predictor', traced: true },
  { method: 'newton-no-predictor', label: 'NR, no predictor', traced: true },
  { method: 'seed', label: "Report's NR (seed)", traced: true },
];

/** Accuracy of one sweep against a reference. Errors in radians. */
export interface SweepScore {
  maxError: number;
  p99Error: number;
  /** Reference assembles but the sweep did not report 'ok'. */
  failures: number;
  /** 'ok' points off by more than GROSS_ERROR_RAD and nearer the other branch's reference. */
  wrongBranch: number;
  /** 'ok' points where the loop cannot close at all. */
  falseConvergence: number;
}

/** Scores sweep r against per-point references of the requested and the other branch (null: no assembly). */
export function scoreSweep(
  r: SweepResult,
  wanted: ReadonlyArray<Angles | null>,
  other: ReadonlyArray<Angles | null>,
): SweepScore {
  const errors: number[] = [];
  let failures = 0;
  let wrongBranch = 0;
  let falseConvergence = 0;
  const err = (i: number, a: Angles) =>
    Math.max(Math.abs(angleDiff(r.theta3[i], a.theta3)), Math.abs(angleDiff(r.theta4[i], a.theta4)));
  for (let i = 0; i < r.status.length; i++) {
    const want = wanted[i];
    if (r.status[i] !== 'ok') {
      if (want) failures++;
      continue;
    }
    if (!want) {
      falseConvergence++;
      continue;
    }
    const e = err(i, want);
    const o = other[i];
    if (e > GROSS_ERROR_RAD && o && err(i, o) < e) {
      wrongBranch++;
      continue;
    }
    errors.push(e);
  }
  errors.sort((a, b) => a - b);
  const n = errors.length;
  return {
    maxError: n ? errors[n - 1] : NaN,
    p99Error: n ? errors[Math.min(n - 1, Math.floor(0.99 * n))] : NaN,
    failures,
    wrongBranch,
    falseConvergence,
  };
}

/** One point of a work-precision curve. */
export interface LabPoint extends SweepScore {
  /** NR tolerance, null for a method's default (closed form, or polished NR). */
  tol: number | null;
  nsPerPoint: number;
  itersPerPoint: number;
}

/** One method's curve. */
export interface LabSeries {
  method: SweepMethod;
  label: string;
  points: LabPoint[];
}

/** Everything the lab view shows for one linkage and branch. */
export interface LabResult {
  linkage: Linkage;
  branch: Branch;
  stepDeg: number;
  theta2Deg: Float64Array;
  series: LabSeries[];
  /** |det J| = r3 r4 |sin(theta3 - theta4)| along the cycle (length unit squared), NaN where not assembled. */
  detJ: Float64Array;
  /** Iterations per point along the cycle for each traced method at its default settings. */
  iterations: Array<{ method: SweepMethod; label: string; iterations: Int32Array }>;
  /** Input limit angles (degrees) of the reachable range; empty for a full-turn crank. */
  limitsDeg: number[];
  /** Smallest |sin(transmission angle)| on the cycle and where (degrees). */
  minSinMu: { value: number; theta2Deg: number };
}

/** Options of runWorkPrecision. */
export interface LabOptions {
  branch: Branch;
  /** Input step of the cycle in degrees (default 1: 361 points). */
  stepDeg?: number;
  /** Clock in milliseconds (performance.now in a worker). */
  now: () => number;
  /** Minimum time spent timing one configuration, ms (default 25). */
  minTimeMs?: number;
  /** Reference solver: a high-precision pose or null when the loop cannot close. */
  reference: (l: Linkage, theta2Rad: number, sigma: number) => Angles | null;
  onProgress?: (fraction: number, stage: string) => void;
  /** Lets the caller's event loop run (so a cancel message can arrive); called between stages. */
  pause?: () => Promise<void>;
  isCancelled?: () => boolean;
}

/** Timing passes per configuration (the fastest pass is kept). */
const TIMING_PASSES = 3;

function sweepOptions(branch: Branch, method: SweepMethod, tol: number | null) {
  return { branch, method, tol: tol ?? undefined, polish: tol === null };
}

function median(xs: number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
}

/** Shortest batch that is timed (ms): browsers coarsen performance.now() to 0.1 ms without cross-origin isolation. */
const MIN_BATCH_MS = 2;

/**
 * Median wall time (ms) of one run: runs are timed in batches long enough for a coarse clock
 * (the batch size doubles until a batch takes MIN_BATCH_MS), for at least minMs and 5 batches.
 */
export function medianTime(run: () => void, now: () => number, minMs: number): number {
  run();
  let reps = 1;
  for (;;) {
    const a = now();
    for (let i = 0; i < reps; i++) run();
    if (now() - a >= MIN_BATCH_MS || reps >= 1 << 16) break;
    reps *= 2;
  }
  const times: number[] = [];
  const t0 = now();
  while (times.length < 5 || now() - t0 < minMs) {
    const a = now();
    for (let i = 0; i < reps; i++) run();
    times.push((now() - a) / reps);
    if (times.length > 500) break;
  }
  return median(times);
}

/**
 * The lab's work-precision study of one linkage: each method (traced over LAB_TOLERANCES where it
 * has a tolerance) timed and scored against the high-precision reference, plus conditioning
 * along the cycle. Resolves to null when cancelled. Throws for a bad linkage.
 */
export async function runWorkPrecision(l: Linkage, opts: LabOptions): Promise<LabResult | null> {
  const stepDeg = opts.stepDeg ?? 1;
  const grid = theta2Grid(0, 360, stepDeg);
  const sigma = opts.branch === 'open' ? 1 : -1;
  const minMs = opts.minTimeMs ?? 25;
  const configs: Array<{ m: LabMethod; tol: number | null }> = [];
  for (const m of LAB_METHODS) {
    configs.push({ m, tol: null });
    if (m.traced) for (const tol of LAB_TOLERANCES) configs.push({ m, tol });
  }
  const refSteps = 4;
  const total = refSteps + configs.length * (1 + TIMING_PASSES);
  let done = 0;
  const progress = async (stage: string): Promise<boolean> => {
    opts.onProgress?.(done / total, stage);
    if (opts.pause) await opts.pause();
    return opts.isCancelled?.() === true;
  };

  const wanted: Array<Angles | null> = [];
  const other: Array<Angles | null> = [];
  const chunk = Math.ceil(grid.length / refSteps);
  for (let c = 0; c < refSteps; c++) {
    if (await progress('reference')) return null;
    for (let i = c * chunk; i < Math.min(grid.length, (c + 1) * chunk); i++) {
      wanted.push(opts.reference(l, grid[i], sigma));
      other.push(opts.reference(l, grid[i], -sigma));
    }
    done++;
  }

  const series: LabSeries[] = LAB_METHODS.map((m) => ({ method: m.method, label: m.label, points: [] }));
  const iterations: LabResult['iterations'] = [];
  const points: LabPoint[] = [];
  for (const { m, tol } of configs) {
    if (await progress(tol === null ? m.label : `${m.label}, tol ${tol}`)) return null;
    const r = sweep(l, grid, sweepOptions(opts.branch, m.method, tol));
    const point: LabPoint = {
      tol,
      nsPerPoint: Infinity,
      itersPerPoint: r.totalIterations / grid.length,
      ...scoreSweep(r, wanted, other),
    };
    points.push(point);
    series.find((s) => s.method === m.method)!.points.push(point);
    if (tol === null && m.traced) iterations.push({ method: m.method, label: m.label, iterations: r.iterations });
    done++;
  }
  // Timing in interleaved passes, keeping each configuration's fastest pass: a noisy moment (or the JIT
  // settling on a method) then costs one pass of several configurations, not one configuration's figure.
  for (let pass = 0; pass < TIMING_PASSES; pass++) {
    for (let k = 0; k < configs.length; k++) {
      const { m, tol } = configs[k];
      if (await progress(`timing ${pass + 1}/${TIMING_PASSES}: ${m.label}${tol === null ? '' : `, tol ${tol}`}`))
        return null;
      const so = sweepOptions(opts.branch, m.method, tol);
      const ms = medianTime(() => sweep(l, grid, so), opts.now, minMs / TIMING_PASSES);
      points[k].nsPerPoint = Math.min(points[k].nsPerPoint, (ms * 1e6) / grid.length);
      done++;
    }
  }
  opts.onProgress?.(1, 'done');

  const cf = sweep(l, grid, { branch: opts.branch, method: 'closed-form' });
  const detJ = new Float64Array(grid.length);
  let minSin = Infinity;
  let minAt = NaN;
  for (let i = 0; i < grid.length; i++) {
    const s = Math.abs(Math.sin(cf.theta3[i] - cf.theta4[i]));
    detJ[i] = l.r3 * l.r4 * s;
    if (s < minSin) {
      minSin = s;
      minAt = radToDeg(grid[i]);
    }
  }
  const range = classify(l).inputRange;
  const limitsDeg = range.full ? [] : range.intervals.flatMap((iv) => [radToDeg(iv.lo), radToDeg(iv.hi)]);
  return {
    linkage: { ...l },
    branch: opts.branch,
    stepDeg,
    theta2Deg: grid.map(radToDeg),
    series,
    detJ,
    iterations,
    limitsDeg,
    minSinMu: { value: minSin, theta2Deg: minAt },
  };
}
