import { degToRad, wrapAngle } from './angles';
import {
  Assembly,
  assemblyFactors,
  branchSign,
  closedFormAt,
  newAssemblyFactors,
  newClosedFormPoint,
  planClosedForm,
} from './closedForm';
import type { ClosedFormPlan } from './closedForm';
import { newNewtonState, newtonCore, newtonSettings } from './newton';
import type { NewtonProblem, NewtonState } from './newton';
import type { Angles, Branch, Linkage, PointStatus, SweepMethod, SweepOptions, SweepResult } from './types';
import { SWEEP_METHODS } from './methods';
import { scaleByPow2 } from './validate';

export { SWEEP_METHODS } from './methods';

/** Default sweep method: the stable closed form (full precision, fastest; see npm run bench). */
export const DEFAULT_SWEEP_METHOD: SweepMethod = 'closed-form';

/**
 * The report's first guess for Algorithm 2 (its text says only "from geometric analysis"):
 * theta3 = 30 deg, theta4 = 90 deg on the open branch, mirrored for crossed.
 */
export function seedFirstGuess(branch: Branch): Angles {
  const s = branchSign(branch);
  return { theta3: s * degToRad(30), theta4: s * degToRad(90) };
}

/**
 * Below this |sin(theta4 - theta3)| NR is near a fold or change point: its answer is only as good as
 * eps / |sin mu| and the branches are too close for a sign test, so the closed form (exact to rounding
 * of cos/sin theta2) is taken instead.
 */
const AMBIGUOUS_SIN = 1e-3;
/** Largest predicted change of an angle per point (radians) before the predictor is distrusted. */
const MAX_PREDICTED_STEP = 0.5;
/** Iteration cap of one continuation step before the point is re-seeded from the closed form. */
const CONTINUATION_MAX_ITERATIONS = 25;

type SweepArrays = SweepResult;

function unscale(plan: ClosedFormPlan, x: number): number {
  return plan.unscale !== 0 ? x * plan.unscale : scaleByPow2(x, plan.exponent);
}

function allocate(n: number): SweepArrays {
  return {
    theta2: new Float64Array(n),
    theta3: new Float64Array(n).fill(NaN),
    theta4: new Float64Array(n).fill(NaN),
    iterations: new Int32Array(n),
    residual: new Float64Array(n).fill(NaN),
    status: new Array<PointStatus>(n),
    totalIterations: 0,
    branchCorrections: 0,
  };
}

function checkTheta2s(theta2s: ArrayLike<number>): void {
  for (let i = 0; i < theta2s.length; i++) {
    if (!Number.isFinite(theta2s[i])) {
      throw new Error(`theta2s[${i}] must be a finite angle in radians, got ${theta2s[i]}`);
    }
  }
}

function sweepClosedForm(
  plan: ClosedFormPlan,
  theta2s: ArrayLike<number>,
  sigma: number,
  polish: boolean,
  r: SweepArrays,
): void {
  const p = newClosedFormPoint();
  const problem: NewtonProblem = { r1: plan.r1, r2: plan.r2, r3: plan.r3, r4: plan.r4, cos2: 1, sin2: 0 };
  const settings = newtonSettings({ maxIterations: 1, polish: true }, plan.r1 + plan.r2 + plan.r3 + plan.r4);
  settings.tolAbs = 0; // one unconditional polish step, kept only if it lowers the residual
  const st = newNewtonState();
  for (let i = 0; i < theta2s.length; i++) {
    const t2 = theta2s[i];
    r.theta2[i] = t2;
    const a = closedFormAt(plan, t2, sigma, p);
    if (a === Assembly.Unreachable) {
      r.status[i] = 'unreachable';
      continue;
    }
    if (a === Assembly.Continuum) {
      r.status[i] = 'singular';
      continue;
    }
    let t3 = p.theta3;
    let t4 = p.theta4;
    let res = p.residual;
    if (polish && a === Assembly.Ok) {
      problem.cos2 = Math.cos(t2);
      problem.sin2 = Math.sin(t2);
      st.theta3 = t3;
      st.theta4 = t4;
      newtonCore(problem, settings, st, null);
      r.iterations[i] = 1;
      r.totalIterations += 1;
      const keepsBranch = Math.sign(st.sin4 * st.cos3 - st.cos4 * st.sin3) === sigma;
      if (st.residual < res && keepsBranch) {
        t3 = wrapAngle(st.theta3);
        t4 = wrapAngle(st.theta4);
        res = st.residual;
      }
    }
    r.theta3[i] = t3;
    r.theta4[i] = t4;
    r.residual[i] = unscale(plan, res);
    r.status[i] = 'ok';
  }
}

function sweepSeed(
  l: Linkage,
  theta2s: ArrayLike<number>,
  branch: Branch,
  tol: number | undefined,
  r: SweepArrays,
): void {
  const settings = newtonSettings({ seed: true, tol }, 0);
  const problem: NewtonProblem = { ...l, cos2: 1, sin2: 0 };
  const guess = seedFirstGuess(branch);
  const st = newNewtonState();
  for (let i = 0; i < theta2s.length; i++) {
    const t2 = theta2s[i];
    r.theta2[i] = t2;
    problem.cos2 = Math.cos(t2);
    problem.sin2 = Math.sin(t2);
    st.theta3 = guess.theta3;
    st.theta4 = guess.theta4;
    newtonCore(problem, settings, st, null);
    r.iterations[i] = st.iterations;
    r.totalIterations += st.iterations;
    if (st.status === 'converged') {
      r.status[i] = 'ok';
      r.theta3[i] = wrapAngle(st.theta3);
      r.theta4[i] = wrapAngle(st.theta4);
      r.residual[i] = st.residual;
      guess.theta3 = st.theta3;
      guess.theta4 = st.theta4;
    } else {
      r.status[i] = st.status === 'singular' ? 'singular' : 'failed';
    }
  }
}

/** Cubic Hermite extrapolation of y at x from (x0, y0, d0) and (x1, y1, d1); Euler when x0 is absent. */
function predict(
  x: number,
  x1: number,
  y1: number,
  d1: number,
  x0: number,
  y0: number,
  d0: number,
  hermite: boolean,
): number {
  const h1 = x - x1;
  if (!hermite) return y1 + d1 * h1;
  const h = x1 - x0;
  const t = (x - x0) / h;
  const t2 = t * t;
  const t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * h * d0 + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * h * d1;
}

function sweepNewton(
  plan: ClosedFormPlan,
  theta2s: ArrayLike<number>,
  sigma: number,
  usePredictor: boolean,
  opts: SweepOptions & { polish?: boolean },
  r: SweepArrays,
): void {
  const { r1, r2, r3, r4 } = plan;
  const problem: NewtonProblem = { r1, r2, r3, r4, cos2: 1, sin2: 0 };
  const settings = newtonSettings(
    { tol: opts.tol, polish: opts.polish, maxIterations: CONTINUATION_MAX_ITERATIONS },
    r1 + r2 + r3 + r4,
  );
  const factors = newAssemblyFactors();
  const cf = newClosedFormPoint();
  const st: NewtonState = newNewtonState();
  // Continuation memory: the last two solved points (unwrapped angles) and their tangents.
  let have = 0;
  let xa = 0,
    a3 = 0,
    a4 = 0,
    da3 = 0,
    da4 = 0; // older
  let xb = 0,
    b3 = 0,
    b4 = 0,
    db3 = 0,
    db4 = 0; // newer
  for (let i = 0; i < theta2s.length; i++) {
    const t2 = theta2s[i];
    r.theta2[i] = t2;
    // Reachability first: plain NR "converges" just past a limit when the tolerance is loose.
    const a = assemblyFactors(plan, t2, factors);
    if (a === Assembly.Unreachable || a === Assembly.Continuum) {
      r.status[i] = a === Assembly.Unreachable ? 'unreachable' : 'singular';
      have = 0;
      continue;
    }
    problem.cos2 = factors.cos2;
    problem.sin2 = factors.sin2;
    let iterations = 0;
    let solved = false;
    let t3 = 0;
    let t4 = 0;
    let c3 = 1,
      s3 = 0,
      c4 = 1,
      s4 = 0,
      res = 0;
    if (have > 0) {
      let g3 = b3;
      let g4 = b4;
      if (usePredictor) {
        const p3 = predict(t2, xb, b3, db3, xa, a3, da3, have > 1);
        const p4 = predict(t2, xb, b4, db4, xa, a4, da4, have > 1);
        if (Math.abs(p3 - b3) < MAX_PREDICTED_STEP && Math.abs(p4 - b4) < MAX_PREDICTED_STEP) {
          g3 = p3;
          g4 = p4;
        }
      }
      st.theta3 = g3;
      st.theta4 = g4;
      newtonCore(problem, settings, st, null);
      iterations = st.iterations;
      if (st.status === 'converged') {
        const sinMu = st.sin4 * st.cos3 - st.cos4 * st.sin3; // sin(theta4 - theta3)
        if (Math.abs(sinMu) >= AMBIGUOUS_SIN && Math.sign(sinMu) === sigma) {
          solved = true;
          t3 = st.theta3;
          t4 = st.theta4;
          c3 = st.cos3;
          s3 = st.sin3;
          c4 = st.cos4;
          s4 = st.sin4;
          res = st.residual;
        } else if (Math.abs(sinMu) >= AMBIGUOUS_SIN) {
          r.branchCorrections++;
        }
        // else: near a fold, fall through to the closed form below.
      }
    }
    if (!solved) {
      // (Re-)seed on the requested branch from the closed form: first point, after a gap,
      // after a branch jump or a failed step, and where the branches are too close to tell apart.
      closedFormAt(plan, t2, sigma, cf);
      t3 = cf.theta3;
      t4 = cf.theta4;
      if (have > 0) {
        // Keep the unwrapped angles continuous with the previous point.
        t3 = b3 + wrapAngle(t3 - b3);
        t4 = b4 + wrapAngle(t4 - b4);
      }
      c3 = cf.cos3;
      s3 = cf.sin3;
      c4 = cf.cos4;
      s4 = cf.sin4;
      res = cf.residual;
    }
    r.theta3[i] = wrapAngle(t3);
    r.theta4[i] = wrapAngle(t4);
    r.iterations[i] = iterations;
    r.totalIterations += iterations;
    r.residual[i] = unscale(plan, res);
    r.status[i] = 'ok';
    // Tangent of the solution curve (hard-cases.md, "Conditioning"):
    // dt3/dt2 = r2 sin(t4 - t2) / (r3 sin(t3 - t4)), dt4/dt2 = r2 sin(t2 - t3) / (r4 sin(t4 - t3)).
    const c2 = factors.cos2;
    const s2 = factors.sin2;
    const sin34 = s3 * c4 - c3 * s4;
    const d3 = (r2 * (s4 * c2 - c4 * s2)) / (r3 * sin34);
    const d4 = (r2 * (s2 * c3 - c2 * s3)) / (-r4 * sin34);
    xa = xb;
    a3 = b3;
    a4 = b4;
    da3 = db3;
    da4 = db4;
    xb = t2;
    b3 = t3;
    b4 = t4;
    db3 = d3;
    db4 = d4;
    const finite = Number.isFinite(d3) && Number.isFinite(d4);
    have = finite ? Math.min(have + 1, 2) : 0;
  }
}

/**
 * Solves the linkage at every theta2 (radians) on one branch. Methods: 'closed-form' (default,
 * full precision), 'closed-form-polish', 'newton' (NR continuation with a Hermite predictor from
 * the velocity ratios; re-seeds from the closed form after a gap, a failure or a branch jump),
 * 'newton-no-predictor', 'seed' (the report's Algorithm 2). Angles wrapped to (-pi, pi], NaN
 * where status is not 'ok'. Throws for a bad linkage, theta2 or option.
 */
export function sweep(l: Linkage, theta2s: ArrayLike<number>, opts: SweepOptions & { polish?: boolean }): SweepResult {
  const plan = planClosedForm(l);
  checkTheta2s(theta2s);
  const sigma = branchSign(opts.branch);
  const method = opts.method ?? DEFAULT_SWEEP_METHOD;
  const r = allocate(theta2s.length);
  switch (method) {
    case 'closed-form':
      sweepClosedForm(plan, theta2s, sigma, false, r);
      break;
    case 'closed-form-polish':
      sweepClosedForm(plan, theta2s, sigma, true, r);
      break;
    case 'newton':
      sweepNewton(plan, theta2s, sigma, true, opts, r);
      break;
    case 'newton-no-predictor':
      sweepNewton(plan, theta2s, sigma, false, opts, r);
      break;
    case 'seed':
      sweepSeed(l, theta2s, opts.branch, opts.tol, r);
      break;
    default:
      throw new Error(`method must be one of ${SWEEP_METHODS.join(', ')}, got ${JSON.stringify(method)}`);
  }
  return r;
}

/** theta2 samples in radians from startDeg to endDeg inclusive with stepDeg spacing (0..360 by 1: 361 points). */
export function theta2Grid(startDeg: number, endDeg: number, stepDeg: number): Float64Array {
  const n = Math.floor((endDeg - startDeg) / stepDeg + 1e-9) + 1;
  const out = new Float64Array(n);
  for (let i = 0; i < n; i++) out[i] = degToRad(startDeg + i * stepDeg);
  return out;
}
