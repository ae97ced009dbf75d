import { PI, TWO_PI, degToRad, wrapAngle } from './angles';
import {
  Assembly,
  assemblyFactors,
  branchSign,
  closedFormAt,
  closedFormSweep,
  newAssemblyFactors,
  newClosedFormPoint,
  planClosedForm,
} from './closedForm';
import type { ClosedFormPlan } from './closedForm';
import { SWEEP_METHODS } from './methods';
import { sweepRates } from './rates';
import { newNewtonState, newtonCore, newtonSettings } from './newton';
import type { NewtonProblem, NewtonState } from './newton';
import { POINT_STATUSES, STATUS_CODE } from './pointStatus';
import type { Angles, Branch, Linkage, PointStatus, SweepMethod, SweepOptions, SweepResult } from './types';
import {
  checkFinite,
  checkObject,
  checkOptionalBoolean,
  checkOptionalPositive,
  describe,
  scaleByPow2,
} from './validate';

// Module-local copies of the units module's constants, read in per-point loops: loaders that turn
// imports into getters (vite-node) would otherwise call a getter on every read.
const HALF_TURN = PI;
const FULL_TURN = TWO_PI;
const { ok: OK, unreachable: UNREACHABLE, singular: SINGULAR, failed: FAILED } = STATUS_CODE;

export { SWEEP_METHODS } from './methods';

// The per-point loops below call these through local constants: a module loader that rewrites
// imports into property reads of a module object (vite-node, some bundlers' dev modes) would
// otherwise pay a lookup on every call and keep the engine from inlining them.
const cfAt = closedFormAt;
const factorsAt = assemblyFactors;
const nrCore = newtonCore;
const wrap = wrapAngle;

/** Default sweep method: the stable closed form (full precision, fastest; see npm run bench). */
export const DEFAULT_SWEEP_METHOD: SweepMethod = 'closed-form';

/** Most points one sweep or theta2Grid accepts (2^28: 2 GiB of Float64 output per array). */
export const MAX_SWEEP_POINTS = 2 ** 28;

/**
 * The report's first guess for Algorithm 2 (its text says only "from geometric analysis"):
 * theta3 = 30 deg, theta4 = 90 deg on the open branch, mirrored for crossed. Throws for a bad branch.
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
/**
 * After a point with |sin mu| below this, the next point is not started from it: next to a fold the
 * Jacobian there is nearly singular and the first NR step would be about 1/|sin mu| long.
 */
const FOLD_SIN = 2e-2;
/** Largest predicted change of an angle per point (radians) before the predictor is distrusted. */
const MAX_PREDICTED_STEP = 0.5;
/** Iteration cap of one continuation step before the point is re-seeded from the closed form. */
const CONTINUATION_MAX_ITERATIONS = 25;

/**
 * The sweep's arrays, all views of one buffer (one allocation per sweep), with the status kept as one
 * byte a point; `status` is decoded from the codes on first read.
 */
class SweepArrays implements SweepResult {
  theta2: Float64Array;
  theta3: Float64Array;
  theta4: Float64Array;
  residual: Float64Array;
  iterations: Int32Array;
  statusCodes: Uint8Array;
  totalIterations = 0;
  branchCorrections = 0;
  private decoded: PointStatus[] | null = null;

  constructor(n: number) {
    const buffer = new ArrayBuffer(n * 37);
    this.theta2 = new Float64Array(buffer, 0, n);
    this.theta3 = new Float64Array(buffer, 8 * n, n);
    this.theta4 = new Float64Array(buffer, 16 * n, n);
    this.residual = new Float64Array(buffer, 24 * n, n);
    this.iterations = new Int32Array(buffer, 32 * n, n);
    this.statusCodes = new Uint8Array(buffer, 36 * n, n);
  }

  get status(): PointStatus[] {
    if (this.decoded === null) {
      const codes = this.statusCodes;
      const out: PointStatus[] = [];
      for (let i = 0; i < codes.length; i++) out.push(POINT_STATUSES[codes[i]]);
      this.decoded = out;
    }
    return this.decoded;
  }
}

/** Throws unless theta2s is an array or typed array of finite numbers (radians). */
function checkTheta2s(theta2s: unknown): asserts theta2s is ArrayLike<number> {
  const isTyped = ArrayBuffer.isView(theta2s) && !(theta2s instanceof DataView);
  if (!Array.isArray(theta2s) && !isTyped) {
    const len = (theta2s as { length?: unknown } | null)?.length;
    if (typeof theta2s === 'object' && theta2s !== null && len !== undefined) {
      if (typeof len !== 'number' || !Number.isInteger(len) || len < 0) {
        throw new Error(`theta2s.length must be a non-negative integer, got ${describe(len)}`);
      }
    } else {
      throw new Error(`theta2s must be an array or typed array of angles in radians, got ${describe(theta2s)}`);
    }
  }
  const a = theta2s as ArrayLike<unknown>;
  if (a.length > MAX_SWEEP_POINTS) {
    throw new Error(`theta2s.length must be at most ${MAX_SWEEP_POINTS}, got ${a.length}`);
  }
  for (let i = 0; i < a.length; i++) {
    const t = a[i];
    if (typeof t !== 'number' || t - t !== 0) {
      throw new Error(`theta2s[${i}] must be a finite angle in radians, got ${describe(t)}`);
    }
  }
}

/** Marks point i as not solved: NaN angles and residual, the status code given. */
function unsolved(r: SweepResult, i: number, code: number): void {
  r.theta3[i] = NaN;
  r.theta4[i] = NaN;
  r.residual[i] = NaN;
  r.statusCodes[i] = code;
}

function sweepClosedForm(
  plan: ClosedFormPlan,
  theta2s: ArrayLike<number>,
  sigma: number,
  polish: boolean,
  r: SweepResult,
): void {
  const p = newClosedFormPoint();
  const { r1, r2, r3, r4 } = plan;
  // Residuals come out in normalised units; one multiplication (or an exact rescale) brings them back.
  const unscale = plan.unscale;
  const th2 = r.theta2;
  const th3 = r.theta3;
  const th4 = r.theta4;
  const res = r.residual;
  let polishSteps = 0;
  for (let i = 0; i < theta2s.length; i++) {
    const t2 = theta2s[i];
    th2[i] = t2;
    const a = cfAt(plan, t2, sigma, p);
    if (a === Assembly.Unreachable) {
      unsolved(r, i, UNREACHABLE);
      continue;
    }
    if (a === Assembly.Continuum) {
      unsolved(r, i, SINGULAR);
      continue;
    }
    let t3 = p.theta3;
    let t4 = p.theta4;
    let rn = p.residual;
    if (polish && a === Assembly.Ok) {
      // One NR step on the closed form's own cos/sin (Cramer's rule, det J = r3 r4 sin(t3 - t4)); the
      // new cos/sin follow by rotating through the tiny step (second order in it), so no trig call.
      const c2 = p.cos2;
      const s2 = p.sin2;
      const f1 = p.f1;
      const f2 = p.f2;
      const det = r3 * r4 * (p.sin3 * p.cos4 - p.cos3 * p.sin4);
      const d3 = (r4 * (f1 * p.cos4 + f2 * p.sin4)) / det;
      const d4 = (r3 * (f1 * p.cos3 + f2 * p.sin3)) / det;
      polishSteps++;
      if (Math.abs(d3) < 1e-6 && Math.abs(d4) < 1e-6) {
        const ca = 1 - 0.5 * d3 * d3;
        const cb = 1 - 0.5 * d4 * d4;
        const c3 = p.cos3 * ca - p.sin3 * d3;
        const s3 = p.sin3 * ca + p.cos3 * d3;
        const c4 = p.cos4 * cb - p.sin4 * d4;
        const s4 = p.sin4 * cb + p.cos4 * d4;
        const g1 = r2 * c2 + r3 * c3 - r4 * c4 - r1;
        const g2 = r2 * s2 + r3 * s3 - r4 * s4;
        const rp = Math.sqrt(g1 * g1 + g2 * g2);
        if (rp < rn) {
          t3 = wrap(t3 + d3);
          t4 = wrap(t4 + d4);
          rn = rp;
        }
      }
      r.iterations[i] = 1;
    }
    th3[i] = t3;
    th4[i] = t4;
    res[i] = unscale !== 0 ? rn * unscale : scaleByPow2(rn, plan.exponent);
    r.statusCodes[i] = OK;
  }
  r.totalIterations = polishSteps;
}

function sweepSeed(
  l: Linkage,
  theta2s: ArrayLike<number>,
  branch: Branch,
  tol: number | undefined,
  r: SweepResult,
): void {
  const settings = newtonSettings({ seed: true, tol }, 0);
  const problem: NewtonProblem = { r1: l.r1, r2: l.r2, r3: l.r3, r4: l.r4, cos2: 1, sin2: 0 };
  const guess = seedFirstGuess(branch);
  const st = newNewtonState();
  let total = 0;
  for (let i = 0; i < theta2s.length; i++) {
    const t2 = theta2s[i];
    r.theta2[i] = t2;
    problem.cos2 = Math.cos(t2);
    problem.sin2 = Math.sin(t2);
    st.theta3 = guess.theta3;
    st.theta4 = guess.theta4;
    nrCore(problem, settings, st, null);
    r.iterations[i] = st.iterations;
    total += st.iterations;
    if (st.status === 'converged') {
      r.statusCodes[i] = OK;
      const w3 = wrap(st.theta3);
      const w4 = wrap(st.theta4);
      r.theta3[i] = w3;
      r.theta4[i] = w4;
      r.residual[i] = st.residual;
      // The next start is the same angle reduced to one turn: identical cos/sin, no drift over many turns.
      guess.theta3 = w3;
      guess.theta4 = w4;
    } else {
      unsolved(r, i, st.status === 'singular' ? SINGULAR : FAILED);
    }
  }
  r.totalIterations = total;
}

/** The previous angle `old` moved by the whole turn that separates it from its successor `now` (both in (-pi, pi]). */
function reanchor(old: number, now: number): number {
  const d = now - old;
  return d > HALF_TURN ? old + FULL_TURN : d < -HALF_TURN ? old - FULL_TURN : old;
}

function sweepNewton(
  plan: ClosedFormPlan,
  theta2s: ArrayLike<number>,
  sigma: number,
  usePredictor: boolean,
  opts: SweepOptions,
  r: SweepResult,
): void {
  const { r1, r2, r3, r4 } = plan;
  const problem: NewtonProblem = { r1, r2, r3, r4, cos2: 1, sin2: 0 };
  const settings = newtonSettings(
    { tol: opts.tol, polish: opts.polish, maxIterations: CONTINUATION_MAX_ITERATIONS },
    r1 + r2 + r3 + r4,
  );
  settings.secondOrder = true;
  const factors = newAssemblyFactors();
  const cf = newClosedFormPoint();
  const st: NewtonState = newNewtonState();
  const unscale = plan.unscale;
  let total = 0;
  // Continuation memory: the last two solved points and their tangents. The newer angles (b3, b4) are
  // kept reduced to (-pi, pi]; the older (a3, a4) are re-anchored with them, so the predictor sees a
  // continuous curve while no stored angle grows with the distance travelled.
  let have = 0;
  let xa = 0,
    a3 = 0,
    a4 = 0,
    da3 = 0,
    da4 = 0;
  let xb = 0,
    b3 = 0,
    b4 = 0,
    db3 = 0,
    db4 = 0,
    sinB = 0;
  for (let i = 0; i < theta2s.length; i++) {
    const t2 = theta2s[i];
    r.theta2[i] = t2;
    // Reachability first: plain NR "converges" just past a limit when the tolerance is loose.
    const a = factorsAt(plan, t2, factors);
    if (a === Assembly.Unreachable || a === Assembly.Continuum) {
      unsolved(r, i, a === Assembly.Unreachable ? UNREACHABLE : SINGULAR);
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
    if (have > 0 && Math.abs(sinB) >= FOLD_SIN) {
      let g3 = b3;
      let g4 = b4;
      if (usePredictor) {
        // Cubic Hermite extrapolation through the last two points and their tangents (Euler after one).
        let p3: number;
        let p4: number;
        if (have > 1) {
          const h = xb - xa;
          const t = (t2 - xa) / h;
          const tt = t * t;
          const ttt = tt * t;
          const w0 = 2 * ttt - 3 * tt + 1;
          const v0 = (ttt - 2 * tt + t) * h;
          const w1 = 3 * tt - 2 * ttt;
          const v1 = (ttt - tt) * h;
          p3 = w0 * a3 + v0 * da3 + w1 * b3 + v1 * db3;
          p4 = w0 * a4 + v0 * da4 + w1 * b4 + v1 * db4;
        } else {
          p3 = b3 + db3 * (t2 - xb);
          p4 = b4 + db4 * (t2 - xb);
        }
        if (Math.abs(p3 - b3) < MAX_PREDICTED_STEP && Math.abs(p4 - b4) < MAX_PREDICTED_STEP) {
          g3 = p3;
          g4 = p4;
        }
      }
      st.theta3 = g3;
      st.theta4 = g4;
      nrCore(problem, settings, st, null);
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
      // (Re-)seed on the requested branch from the closed form: first point, after a gap, next to a
      // fold, after a branch jump or a failed step, and where the branches are too close to tell apart.
      cfAt(plan, t2, sigma, cf);
      t3 = cf.theta3;
      t4 = cf.theta4;
      c3 = cf.cos3;
      s3 = cf.sin3;
      c4 = cf.cos4;
      s4 = cf.sin4;
      res = cf.residual;
    }
    const w3 = t3 > -HALF_TURN && t3 <= HALF_TURN ? t3 : wrap(t3);
    const w4 = t4 > -HALF_TURN && t4 <= HALF_TURN ? t4 : wrap(t4);
    r.theta3[i] = w3;
    r.theta4[i] = w4;
    r.iterations[i] = iterations;
    total += iterations;
    r.residual[i] = unscale !== 0 ? res * unscale : scaleByPow2(res, plan.exponent);
    r.statusCodes[i] = OK;
    // Tangent of the solution curve (docs/hard-cases.md, "Conditioning"):
    // dt3/dt2 = r2 sin(t4 - t2) / (r3 sin(t3 - t4)), dt4/dt2 = r2 sin(t2 - t3) / (r4 sin(t4 - t3)).
    const c2 = factors.cos2;
    const s2 = factors.sin2;
    const k34 = r2 / (s3 * c4 - c3 * s4); // r2 / sin(t3 - t4)
    const sin34 = s3 * c4 - c3 * s4;
    const d3 = (s4 * c2 - c4 * s2) * k34 * plan.inv3;
    const d4 = -(s2 * c3 - c2 * s3) * k34 * plan.inv4;
    // Re-anchor: the previous point moves by the whole turns that reduce the new one.
    if (have > 0) {
      xa = xb;
      a3 = reanchor(b3, w3);
      a4 = reanchor(b4, w4);
      da3 = db3;
      da4 = db4;
    }
    xb = t2;
    b3 = w3;
    b4 = w4;
    db3 = d3;
    db4 = d4;
    sinB = sin34;
    const finite = Number.isFinite(d3) && Number.isFinite(d4);
    have = finite ? Math.min(have + 1, 2) : 0;
  }
  r.totalIterations = total;
}

/** Throws unless opts is a SweepOptions object with a valid branch, method, tol and polish. */
function checkSweepOptions(opts: unknown): asserts opts is SweepOptions {
  checkObject('opts', opts);
  branchSign(opts.branch as Branch);
  const m = opts.method;
  if (m !== undefined && !SWEEP_METHODS.includes(m as SweepMethod)) {
    throw new Error(`method must be one of ${SWEEP_METHODS.join(', ')}, got ${describe(m)}`);
  }
  checkOptionalPositive('tol', opts.tol);
  checkOptionalBoolean('polish', opts.polish);
  const rates = opts.rates;
  if (rates !== undefined) {
    checkObject('rates', rates);
    for (const k of ['omega2', 'alpha2'] as const) {
      if (typeof rates[k] !== 'number' || !Number.isFinite(rates[k])) {
        throw new Error(`rates.${k} must be a finite number, got ${describe(rates[k])}`);
      }
    }
  }
}

/**
 * Solves the linkage at every theta2 (radians, finite, an array or typed array of at most
 * MAX_SWEEP_POINTS) on one branch. Methods: 'closed-form' (default, full precision), 'closed-form-polish',
 * 'newton' (NR continuation with a Hermite predictor from the velocity ratios; re-seeds from the
 * closed form after a gap, next to a fold, after a failure or a branch jump), 'newton-no-predictor',
 * 'seed' (Algorithm 2 of the report, docs/report.md). Angles wrapped to (-pi, pi], NaN where status is not 'ok'.
 * Throws an Error naming the argument for a bad linkage, theta2s, branch, method, tol or polish.
 */
export function sweep(l: Linkage, theta2s: ArrayLike<number>, opts: SweepOptions): SweepResult {
  const plan = planClosedForm(l);
  checkTheta2s(theta2s);
  checkSweepOptions(opts);
  const sigma = branchSign(opts.branch);
  const method = opts.method ?? DEFAULT_SWEEP_METHOD;
  const r = new SweepArrays(theta2s.length);
  switch (method) {
    case 'closed-form':
      closedFormSweep(plan, theta2s, sigma, r);
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
  }
  if (opts.rates) {
    const codes = r.statusCodes;
    const ok = STATUS_CODE.ok;
    Object.assign(
      r,
      sweepRates(l, r.theta2, r.theta3, r.theta4, (i) => codes[i] === ok, opts.rates),
    );
  }
  return r;
}

/**
 * theta2 samples in radians from startDeg to endDeg inclusive with stepDeg spacing (0..360 by 1: 361
 * points). Throws unless all three are finite, stepDeg > 0, endDeg >= startDeg and the grid has at
 * most MAX_SWEEP_POINTS points.
 */
export function theta2Grid(startDeg: number, endDeg: number, stepDeg: number): Float64Array {
  checkFinite('startDeg', startDeg, 'angle in degrees');
  checkFinite('endDeg', endDeg, 'angle in degrees');
  checkFinite('stepDeg', stepDeg, 'step in degrees');
  if (!(stepDeg > 0)) throw new Error(`stepDeg must be positive, got ${stepDeg}`);
  if (!(endDeg >= startDeg)) throw new Error(`endDeg must be at least startDeg (${startDeg}), got ${endDeg}`);
  const count = Math.floor((endDeg - startDeg) / stepDeg + 1e-9) + 1;
  if (!(count <= MAX_SWEEP_POINTS)) {
    throw new Error(
      `stepDeg ${stepDeg} gives ${count} points from ${startDeg} to ${endDeg}, more than ${MAX_SWEEP_POINTS}`,
    );
  }
  const out = new Float64Array(count);
  for (let i = 0; i < count; i++) out[i] = degToRad(startDeg + i * stepDeg);
  return out;
}
