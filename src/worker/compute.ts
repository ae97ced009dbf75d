import { DEFAULT_TOLERANCE, classify, couplerPoint, degToRad, seedFirstGuess, solveClosedForm, solveNewton, sweep, transmissionAngle } from '../solver';
import type { Angles, Branch, Linkage, NewtonResult } from '../solver/types';
import { couplerCurves } from './couplerCurves';
import { encodeStatuses } from './statusCodes';
import type {
  BranchCycle,
  CycleRequest,
  CycleResponse,
  NewtonSummary,
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

function branchCycle(l: Linkage, theta2Rad: Float64Array, branch: Branch, coupler: CycleRequest['coupler']): BranchCycle {
  const r = sweep(l, theta2Rad, { branch, method: 'newton' });
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
  };
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
  const open = branchCycle(req.linkage, theta2Rad, 'open', req.coupler);
  const crossed = branchCycle(req.linkage, theta2Rad, 'crossed', req.coupler);
  const curves = couplerCurves(req.linkage, classification, req.coupler, open, crossed, n);
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
    elapsedMs: performance.now() - t0,
  };
  const buffers: ArrayBufferLike[] = [theta2Deg.buffer];
  for (const b of [open, crossed]) {
    buffers.push(b.theta3.buffer, b.theta4.buffer, b.iterations.buffer, b.residual.buffer, b.statusCodes.buffer, b.px.buffer, b.py.buffer);
  }
  for (const c of curves) buffers.push(c.x.buffer, c.y.buffer);
  // Shared buffers cannot be transferred (and the sweep never makes one); each buffer may appear once.
  const transfer = [...new Set(buffers)].filter((b): b is ArrayBuffer => b instanceof ArrayBuffer);
  return { response, transfer };
}

function pose(theta2: number, a: Angles | null): PoseAngles | null {
  if (!a) return null;
  return { theta2, theta3: a.theta3, theta4: a.theta4, mu: transmissionAngle(a) };
}

function summary(start: NewtonSummary['start'], guess: Angles, r: NewtonResult, sigma: number, l: Linkage): NewtonSummary {
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
    tolerance: DEFAULT_TOLERANCE * (l.r1 + l.r2 + l.r3 + l.r4),
    log: r.log,
  };
}

/**
 * Solves one pose: the closed form on the requested branch and on the other one (the ghost), and NR
 * from the continuation start (the solution one cycle step back) and from the report's cold first guess.
 */
export function computePoint(req: PointRequest): ComputeResult {
  const { linkage: l, branch, theta2Rad } = req;
  const other: Branch = branch === 'open' ? 'crossed' : 'open';
  const sigma = branch === 'open' ? 1 : -1;
  const main = solveClosedForm(l, theta2Rad, branch);
  const ghost = solveClosedForm(l, theta2Rad, other);
  let continuation: NewtonSummary | null = null;
  let cold: NewtonSummary | null = null;
  if (main) {
    const prev = solveClosedForm(l, theta2Rad - req.stepRad, branch);
    if (prev) continuation = summary('continuation', prev, solveNewton(l, theta2Rad, prev), sigma, l);
    const guess = seedFirstGuess(branch);
    cold = summary('cold', guess, solveNewton(l, theta2Rad, guess), sigma, l);
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
