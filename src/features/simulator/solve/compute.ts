import {
  DEFAULT_TOLERANCE,
  STATUS_CODE,
  SEED_TOLERANCE,
  classify,
  couplerPoint,
  degToRad,
  seedFirstGuess,
  solveClosedForm,
  solveNewton,
  sweep,
  sweepRates,
  couplerPointMotion,
  transmissionAngle,
  validateLinkage,
  velocityRatios,
} from '../../../solver';
import type { InputMotion } from '../../../solver';
import type { Angles, Branch, Linkage, NewtonOptions, NewtonResult } from '../../../solver/types';
import { couplerCurves } from './couplerCurves';
import { sweepOptions } from '../../../shared/charts/plotSeries';
import { encodeStatuses } from '../../../shared/pointStatusCodes';
import type {
  BranchCycle,
  CouplerSpec,
  CycleResponse,
  MethodChoice,
  NewtonSummary,
  TableMotion,
  PointResponse,
  PoseAngles,
  TableParams,
  TableResponse,
} from '../../../shared/solution';
import type { CycleParams, PointParams } from '../jobs';

/** Most intervals of the cycle's view grid (half a degree): enough for bounds and a smooth coupler curve on screen. */
export const VIEW_SAMPLES_MAX = 720;

/** Largest samples accepted (intervals per cycle); the UI allows 36 000. */
const SAMPLES_LIMIT = 1_000_000;

/** Throws unless samples is a whole number of intervals in [1, SAMPLES_LIMIT]. */
function checkSamples(samples: unknown): asserts samples is number {
  if (typeof samples !== 'number' || !Number.isInteger(samples) || samples < 1 || samples > SAMPLES_LIMIT) {
    throw new Error(`samples must be a whole number from 1 to ${SAMPLES_LIMIT}, got ${String(samples)}`);
  }
}

/** The uniform grid of n intervals from 0 to 360 degrees, in degrees and radians. */
function uniformGrid(n: number): { deg: Float64Array; rad: Float64Array } {
  const deg = new Float64Array(n + 1);
  const rad = new Float64Array(n + 1);
  for (let k = 0; k <= n; k++) {
    deg[k] = (360 * k) / n;
    rad[k] = degToRad(deg[k]);
  }
  return { deg, rad };
}

function sigmaOf(a: Angles): number {
  return Math.sin(a.theta4 - a.theta3) >= 0 ? 1 : -1;
}

function skippedCycle(n: number): BranchCycle {
  const nan = () => new Float64Array(n).fill(Number.NaN);
  return {
    theta3: nan(),
    theta4: nan(),
    iterations: new Int32Array(n),
    residual: nan(),
    statusCodes: new Uint8Array(n).fill(STATUS_CODE.unreachable),
    px: nan(),
    py: nan(),
    totalIterations: 0,
    branchCorrections: 0,
    okCount: 0,
    skipped: true,
  };
}

function branchCycle(
  l: Linkage,
  theta2Rad: Float64Array,
  branch: Branch,
  coupler: CycleParams['coupler'],
  solver: MethodChoice,
): BranchCycle {
  const r = sweep(l, theta2Rad, sweepOptions(branch, solver));
  const n = theta2Rad.length;
  const px = new Float64Array(n).fill(Number.NaN);
  const py = new Float64Array(n).fill(Number.NaN);
  let okCount = 0;
  for (let i = 0; i < n; i++) {
    if (r.status[i] !== 'ok') continue;
    okCount++;
    const p = couplerPoint(l, theta2Rad[i], r.theta3[i], coupler.distance, coupler.angleRad);
    px[i] = p.x;
    py[i] = p.y;
  }
  return {
    theta3: r.theta3,
    theta4: r.theta4,
    iterations: r.iterations,
    residual: r.residual,
    statusCodes: encodeStatuses(r.status),
    px,
    py,
    totalIterations: r.totalIterations,
    branchCorrections: r.branchCorrections,
    okCount,
    skipped: false,
  };
}

/**
 * Solves the cycle the view draws: the classification, the chosen branch (and the other when shown or
 * when the input rocks) on a uniform grid of min(samples, VIEW_SAMPLES_MAX) intervals, and the coupler
 * curves. The plots are solved on the main thread (plotSeries); the whole samples + 1 table is computeTable's.
 * Throws for bad params.
 */
export function computeCycle(req: CycleParams): CycleResponse {
  const t0 = performance.now();
  const classification = classify(req.linkage);
  checkSamples(req.samples);
  const n = Math.min(req.samples, VIEW_SAMPLES_MAX);
  const { deg: theta2Deg, rad: theta2Rad } = uniformGrid(n);
  // The other branch only when something shows it; a rocking input needs both (it changes branch at its limits).
  const rocking = !classification.inputRange.full;
  const want = (b: Branch) => b === req.branch || req.otherBranch || rocking;
  const open = want('open')
    ? branchCycle(req.linkage, theta2Rad, 'open', req.coupler, req.solver)
    : skippedCycle(n + 1);
  const crossed = want('crossed')
    ? branchCycle(req.linkage, theta2Rad, 'crossed', req.coupler, req.solver)
    : skippedCycle(n + 1);
  // The curves follow the screen, not the samples the user chose: always VIEW_SAMPLES_MAX per turn.
  const curves = req.curves ? couplerCurves(req.linkage, classification, req.coupler, VIEW_SAMPLES_MAX) : [];
  let points = 0;
  let iterations = 0;
  for (const b of [open, crossed]) {
    if (!b.skipped) points += n + 1;
    iterations += b.totalIterations;
  }
  for (const c of curves) points += c.x.length;
  return {
    linkage: { ...req.linkage },
    coupler: { ...req.coupler },
    classification,
    samples: req.samples,
    theta2Deg,
    open,
    crossed,
    curves,
    solver: { ...req.solver },
    work: { points, iterations },
    elapsedMs: performance.now() - t0,
  };
}

/** Rates, transmission angle and coupler point motion of every row of a swept table (NaN where not ok). */
function tableMotion(
  l: Linkage,
  theta2: Float64Array,
  r: { theta3: Float64Array; theta4: Float64Array; status: readonly string[] },
  input: InputMotion,
  coupler: CouplerSpec,
): TableMotion {
  const ok = (i: number) => r.status[i] === 'ok';
  const rates = sweepRates(l, theta2, r.theta3, r.theta4, ok, input);
  const n = theta2.length;
  const col = () => new Float64Array(n).fill(Number.NaN);
  const cols = { mu: col(), px: col(), py: col(), vpx: col(), vpy: col(), apx: col(), apy: col() };
  const m: TableMotion = { ...rates, input: { omega2: input.omega2, alpha2: input.alpha2 }, ...cols };
  for (let i = 0; i < n; i++) {
    if (!ok(i)) continue;
    const pose = { theta3: r.theta3[i], theta4: r.theta4[i] };
    m.mu[i] = transmissionAngle(pose);
    const p = couplerPointMotion(l, theta2[i], pose, input, coupler.distance, coupler.angleRad);
    m.px[i] = p.x;
    m.py[i] = p.y;
    m.vpx[i] = p.vx;
    m.vpy[i] = p.vy;
    m.apx[i] = p.ax;
    m.apy[i] = p.ay;
  }
  return m;
}

/**
 * The whole samples + 1 point sweep of one branch with the chosen method: the cycle CSV's columns, with the
 * rates, transmission angle and coupler point motion per row when req.motion asks. Throws for bad params.
 */
export function computeTable(req: TableParams): TableResponse {
  checkSamples(req.samples);
  const { deg, rad } = uniformGrid(req.samples);
  const r = sweep(req.linkage, rad, sweepOptions(req.branch, req.solver));
  let okCount = 0;
  for (const s of r.status) if (s === 'ok') okCount++;
  const motion = req.motion ? tableMotion(req.linkage, rad, r, req.motion.input, req.motion.coupler) : null;
  return {
    linkage: { ...req.linkage },
    branch: req.branch,
    samples: req.samples,
    solver: { ...req.solver },
    theta2Deg: deg,
    theta3Rad: r.theta3,
    theta4Rad: r.theta4,
    statusCodes: encodeStatuses(r.status),
    iterations: r.iterations,
    residual: r.residual,
    okCount,
    totalIterations: r.totalIterations,
    branchCorrections: r.branchCorrections,
    work: { points: req.samples + 1, iterations: r.totalIterations },
    motion,
  };
}

function pose(theta2: number, a: Angles | null): PoseAngles | null {
  if (!a) return null;
  return { theta2, theta3: a.theta3, theta4: a.theta4, mu: transmissionAngle(a) };
}

/** NR options for the chosen method: Algorithm 1 of the report (docs/report.md) for seed, the tolerance unpolished when one is chosen. */
function newtonOptions(solver: MethodChoice): NewtonOptions {
  if (solver.method === 'seed') return { seed: true, tol: solver.tol ?? undefined };
  if (solver.tol !== null && (solver.method === 'newton' || solver.method === 'newton-no-predictor')) {
    return { tol: solver.tol, polish: false };
  }
  return {};
}

/** The absolute residual tolerance NR stops at (length unit) under these options. */
function toleranceOf(opts: NewtonOptions, l: Linkage): number {
  if (opts.seed) return opts.tol ?? SEED_TOLERANCE;
  return (opts.tol ?? DEFAULT_TOLERANCE) * (l.r1 + l.r2 + l.r3 + l.r4);
}

function summary(
  start: NewtonSummary['start'],
  guess: Angles,
  r: NewtonResult,
  sigma: number,
  tolerance: number,
): NewtonSummary {
  return {
    start,
    guess,
    status: r.status,
    iterations: r.iterations,
    residual: r.residual,
    detJ: r.detJ,
    theta3: r.theta3,
    theta4: r.theta4,
    onBranch: r.status === 'converged' && sigmaOf(r) === sigma,
    tolerance,
    log: r.log,
  };
}

/**
 * Solves one pose: the closed form on the requested branch and, when drawn, on the other one (the ghost);
 * when a panel shows them, NR with the chosen method from the continuation start (the solution one
 * cycle step back, plus the velocity-ratio predictor for 'newton') and from the report's cold first guess.
 */
export function computePoint(req: PointParams): PointResponse {
  const { linkage: l, branch, theta2Rad, solver } = req;
  validateLinkage(l);
  if (!Number.isFinite(theta2Rad)) throw new Error(`theta2Rad must be a finite angle, got ${String(theta2Rad)}`);
  const other: Branch = branch === 'open' ? 'crossed' : 'open';
  const sigma = branch === 'open' ? 1 : -1;
  const main = solveClosedForm(l, theta2Rad, branch);
  const ghost = req.ghost ? solveClosedForm(l, theta2Rad, other) : null;
  let continuation: NewtonSummary | null = null;
  let cold: NewtonSummary | null = null;
  let points = req.ghost ? 2 : 1;
  let iterations = 0;
  if (main && req.newton) {
    const opts = newtonOptions(solver);
    const tolerance = toleranceOf(opts, l);
    const prevRad = theta2Rad - req.stepRad;
    const prev = solveClosedForm(l, prevRad, branch);
    if (prev) {
      let start: Angles = { theta3: prev.theta3, theta4: prev.theta4 };
      if (solver.method === 'newton') {
        const v = velocityRatios(l, prevRad, prev);
        if (Number.isFinite(v.dTheta3) && Number.isFinite(v.dTheta4)) {
          start = { theta3: prev.theta3 + v.dTheta3 * req.stepRad, theta4: prev.theta4 + v.dTheta4 * req.stepRad };
        }
      }
      const r = solveNewton(l, theta2Rad, start, opts);
      continuation = summary('continuation', start, r, sigma, tolerance);
      points += 2;
      iterations += r.iterations;
    }
    const guess = seedFirstGuess(branch);
    const rc = solveNewton(l, theta2Rad, guess, opts);
    cold = summary('cold', guess, rc, sigma, tolerance);
    points += 1;
    iterations += rc.iterations;
  }
  return {
    linkage: { r1: l.r1, r2: l.r2, r3: l.r3, r4: l.r4 },
    coupler: { distance: req.coupler.distance, angleRad: req.coupler.angleRad },
    theta2Rad,
    branch,
    pose: pose(theta2Rad, main),
    ghost: pose(theta2Rad, ghost),
    continuation,
    cold,
    solver: { ...solver },
    work: { points, iterations },
  };
}
