import {
  DEFAULT_TOLERANCE,
  SEED_TOLERANCE,
  adaptiveGrid,
  classify,
  couplerPoint,
  degToRad,
  radToDeg,
  seedFirstGuess,
  solveClosedForm,
  solveNewton,
  sweep,
  transmissionAngle,
  velocityRatios,
} from '../solver';
import type { Angles, Branch, Linkage, NewtonOptions, NewtonResult } from '../solver/types';
import { couplerCurves } from './couplerCurves';
import { encodeStatuses } from './statusCodes';
import type {
  BranchCycle,
  CycleRequest,
  CycleResponse,
  MethodChoice,
  NewtonSummary,
  PlotSeries,
  PointRequest,
  PointResponse,
  PoseAngles,
  SolverRequest,
  SolverResponse,
} from './protocol';

/** A response and the buffers to transfer with it. */
export interface ComputeResult {
  response: SolverResponse;
  transfer: ArrayBuffer[];
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
    statusCodes: new Uint8Array(n).fill(1),
    px: nan(),
    py: nan(),
    totalIterations: 0,
    branchCorrections: 0,
    okCount: 0,
    skipped: true,
  };
}

/** Sweep options for a method choice: an explicit tolerance turns polishing off, so the tolerance shows. */
function sweepOptions(branch: Branch, solver: MethodChoice) {
  return { branch, method: solver.method, tol: solver.tol ?? undefined, polish: solver.tol === null };
}

function branchCycle(
  l: Linkage,
  theta2Rad: Float64Array,
  branch: Branch,
  coupler: CycleRequest['coupler'],
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

function plotSeries(l: Linkage, pixels: number, branches: Branch[], solver: MethodChoice): PlotSeries {
  const grid = adaptiveGrid(l, { pixels, branches });
  const one = (b: Branch) => {
    if (!branches.includes(b)) return null;
    const r = sweep(l, grid, sweepOptions(b, solver));
    return { theta3: r.theta3, theta4: r.theta4 };
  };
  return { theta2Deg: grid.map(radToDeg), open: one('open'), crossed: one('crossed') };
}

/** Solves the whole cycle of a request (both branches, NR continuation sweeps) and its coupler curves. */
export function computeCycle(req: CycleRequest): ComputeResult {
  const t0 = performance.now();
  const classification = classify(req.linkage);
  const n = req.samples;
  const theta2Deg = new Float64Array(n + 1);
  const theta2Rad = new Float64Array(n + 1);
  for (let k = 0; k <= n; k++) {
    theta2Deg[k] = (360 * k) / n;
    theta2Rad[k] = degToRad(theta2Deg[k]);
  }
  // The other branch only when something shows it; a rocking input needs both (it changes branch at its limits).
  const rocking = !classification.inputRange.full;
  const want = (b: Branch) => b === req.branch || req.otherBranch || rocking;
  const open = want('open')
    ? branchCycle(req.linkage, theta2Rad, 'open', req.coupler, req.solver)
    : skippedCycle(n + 1);
  const crossed = want('crossed')
    ? branchCycle(req.linkage, theta2Rad, 'crossed', req.coupler, req.solver)
    : skippedCycle(n + 1);
  const curves = req.curves ? couplerCurves(req.linkage, classification, req.coupler, open, crossed, n) : [];
  const branches = (['open', 'crossed'] as const).filter((b) => b === req.branch || req.otherBranch);
  const plot = req.plotPixels > 0 ? plotSeries(req.linkage, req.plotPixels, branches, req.solver) : null;
  let points = 0;
  let iterations = 0;
  for (const b of [open, crossed]) {
    if (!b.skipped) points += n + 1;
    iterations += b.totalIterations;
  }
  for (const c of curves) if (c.rocking) points += c.x.length;
  if (plot) points += plot.theta2Deg.length * branches.length;
  const response: CycleResponse = {
    type: 'cycle',
    id: req.id,
    linkage: { ...req.linkage },
    coupler: { ...req.coupler },
    classification,
    samples: n,
    theta2Deg,
    open,
    crossed,
    curves,
    plot,
    solver: { ...req.solver },
    work: { points, iterations },
    elapsedMs: performance.now() - t0,
  };
  const buffers: ArrayBufferLike[] = [theta2Deg.buffer];
  for (const b of [open, crossed]) {
    buffers.push(
      b.theta3.buffer,
      b.theta4.buffer,
      b.iterations.buffer,
      b.residual.buffer,
      b.statusCodes.buffer,
      b.px.buffer,
      b.py.buffer,
    );
  }
  for (const c of curves) buffers.push(c.x.buffer, c.y.buffer);
  if (plot) {
    buffers.push(plot.theta2Deg.buffer);
    for (const b of [plot.open, plot.crossed]) if (b) buffers.push(b.theta3.buffer, b.theta4.buffer);
  }
  // Shared buffers cannot be transferred (and the sweep never makes one); each buffer may appear once.
  const transfer = [...new Set(buffers)].filter((b): b is ArrayBuffer => b instanceof ArrayBuffer);
  return { response, transfer };
}

function pose(theta2: number, a: Angles | null): PoseAngles | null {
  if (!a) return null;
  return { theta2, theta3: a.theta3, theta4: a.theta4, mu: transmissionAngle(a) };
}

/** NR options for the chosen method: the report's Algorithm 1 for seed, the tolerance unpolished when one is chosen. */
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
export function computePoint(req: PointRequest): ComputeResult {
  const { linkage: l, branch, theta2Rad, solver } = req;
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
  const response: PointResponse = {
    type: 'point',
    id: req.id,
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
  return { response, transfer: [] };
}

/** Answers any request; never throws: a failure becomes an ErrorResponse naming what went wrong. */
export function handleRequest(req: SolverRequest): ComputeResult {
  try {
    switch (req.type) {
      case 'cycle':
        return computeCycle(req);
      case 'point':
        return computePoint(req);
      case 'lab':
      case 'cancel':
        throw new Error(`${req.type} requests are handled by the worker's lab runner`);
      default: {
        const unknown = req as { type?: unknown; id?: unknown };
        throw new Error(`unknown request type ${JSON.stringify(unknown.type)}`);
      }
    }
  } catch (e) {
    const message = e instanceof Error ? e.message : String(e);
    const id = typeof req?.id === 'number' ? req.id : -1;
    return { response: { type: 'error', id, requestType: req?.type ?? 'point', message }, transfer: [] };
  }
}
