import { PI, wrapAngle } from './angles';
import type { Angles, IterationRecord, Linkage, NewtonOptions, NewtonResult, NewtonStatus } from './types';
import {
  checkAngles,
  checkFinite,
  checkObject,
  checkOptionalBoolean,
  checkOptionalPositive,
  describe,
  normalizeLinkage,
  scaleByPow2,
  validateLinkage,
} from './validate';

// Module-local copies of the units module's constants, read in per-point loops: loaders that turn
// imports into getters (vite-node) would otherwise call a getter on every read.
const HALF_TURN = PI;

const EPS = Number.EPSILON;

// "The report" below is the project's seed report (position analysis by Newton-Raphson, summarised in
// docs/hard-cases.md). Its Algorithm 1 is NR with Cramer's rule, stopping when |f1| and |f2| are both
// below 1e-9 (absolute), as singular when |det J| < 1e-9, after at most 100 iterations; its Algorithm 2
// sweeps theta2 over 0..360 deg starting each point from the previous solution.

/** The report's Algorithm 1 constants: absolute tolerance on |f1| and |f2|, singular threshold on |det J|. */
export const SEED_TOLERANCE = 1e-9;
/** The report's singular threshold on |det J| (absolute). */
export const SEED_SINGULAR_DET = 1e-9;
/** The report's iteration cap. */
export const SEED_MAX_ITERATIONS = 100;
/** Default relative tolerance: |f| <= tol * (r1 + r2 + r3 + r4) before polishing. */
export const DEFAULT_TOLERANCE = 1e-13;
/** |sin(theta3 - theta4)| below this is treated as singular by the project's NR. */
export const SINGULAR_SIN = 64 * EPS;
/**
 * Largest NR step (Euclidean norm, radians) the project's NR takes; a longer step is shortened to it.
 * Near a fold the full step is about |f| / (r |sin mu|), which can throw the angles many turns away
 * from any solution; no solution is ever more than a half turn away in either angle.
 */
export const MAX_STEP_RAD = 1;
/** Below this step (radians) the NR core updates cos/sin by rotation instead of calling cos and sin. */
const ROTATE_MAX_RAD = 1e-3;
/** Newton steps longer than this (radians, per angle) get no second-order term: far from a root it does not help. */
const CHEBYSHEV_MAX_RAD = 0.25;

/**
 * Whether a step of norm `step` left an error at the rounding level: about step^2 / |sin mu| after a
 * Newton step (so step^2 <= eps |sin mu|), about step^3 / sin^2 mu after a second-order one (within
 * a few eps: step^3 <= 16 eps sin^2 mu).
 */
function stepIsFinal(secondOrder: boolean, step: number, sinMu: number): boolean {
  if (secondOrder) return step * step * step <= 16 * EPS * sinMu * sinMu;
  return step * step <= EPS * Math.abs(sinMu);
}

/** Largest iteration cap solveNewton accepts. */
const MAX_ITERATIONS_LIMIT = 100_000;

/** Lengths and input trigonometry the NR core works on (any unit; normalised for the project's method). */
export interface NewtonProblem {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
  cos2: number;
  sin2: number;
}

/** Settings of the NR core, resolved from NewtonOptions. */
export interface NewtonSettings {
  seed: boolean;
  /** Absolute residual tolerance (problem units). */
  tolAbs: number;
  maxIterations: number;
  polish: boolean;
  /** Residual floor of double precision for this problem (problem units). */
  floor: number;
  /**
   * Add Chebyshev's second-order term to each small Newton step (cubic convergence, one more 2x2
   * solve with the same Jacobian, no extra evaluation). Continuation sweeps use it; solveNewton
   * does not (it shows plain Newton-Raphson).
   */
  secondOrder: boolean;
}

/** Mutable NR state; the core reads the start from theta3/theta4 and leaves the answer there. */
export interface NewtonState {
  theta3: number;
  theta4: number;
  cos3: number;
  sin3: number;
  cos4: number;
  sin4: number;
  status: NewtonStatus;
  iterations: number;
  residual: number;
  detJ: number;
}

/** Fresh NR state starting at (theta3, theta4) radians. */
export function newNewtonState(theta3 = 0, theta4 = 0): NewtonState {
  return {
    theta3,
    theta4,
    cos3: 1,
    sin3: 0,
    cos4: 1,
    sin4: 0,
    status: 'max-iterations',
    iterations: 0,
    residual: Infinity,
    detJ: 0,
  };
}

/**
 * Newton-Raphson on the loop equations f1 = r2 c2 + r3 c3 - r4 c4 - r1, f2 = r2 s2 + r3 s3 - r4 s4
 * with det J = r3 r4 sin(theta3 - theta4) (eq. 5 of the report, docs/report.md, has the sign flipped). Seed mode is
 * the report's Algorithm 1 verbatim. Otherwise: stop once |f| <= tolAbs, then polish while the
 * last step was not yet negligible (error after a step ~ step^2 / |sin mu|), reverting a polish
 * step that does not lower the residual. Angles stay unwrapped (continuous) in the state.
 */
export function newtonCore(p: NewtonProblem, s: NewtonSettings, st: NewtonState, log: IterationRecord[] | null): void {
  const { r1, r2, r3, r4, cos2, sin2 } = p;
  let t3 = st.theta3;
  let t4 = st.theta4;
  let lastStep = Infinity;
  let polishing = false;
  let polishSteps = 0;
  let prevResidualSq = Infinity;
  // The point before a polish step, restored when the step does not lower the residual.
  let pt3 = 0,
    pt4 = 0,
    pc3 = 1,
    ps3 = 0,
    pc4 = 1,
    ps4 = 0,
    pdet = 0;
  let c3 = 1,
    s3 = 0,
    c4 = 1,
    s4 = 0;
  let needTrig = true;
  st.iterations = 0;
  for (let k = 0; ; k++) {
    if (needTrig) {
      c3 = Math.cos(t3);
      s3 = Math.sin(t3);
      c4 = Math.cos(t4);
      s4 = Math.sin(t4);
    }
    const f1 = r2 * cos2 + r3 * c3 - r4 * c4 - r1;
    const f2 = r2 * sin2 + r3 * s3 - r4 * s4;
    // Squared norms in the tests (no square root per iteration); the root only for what is reported.
    const resSq = f1 * f1 + f2 * f2;
    const sinMu = s3 * c4 - c3 * s4; // sin(theta3 - theta4)
    const det = r3 * r4 * sinMu;
    if (polishing && !(resSq < prevResidualSq)) {
      // The polish step did not help: we are at the rounding floor; keep the previous point.
      t3 = pt3;
      t4 = pt4;
      st.cos3 = pc3;
      st.sin3 = ps3;
      st.cos4 = pc4;
      st.sin4 = ps4;
      st.detJ = pdet;
      st.residual = Math.sqrt(prevResidualSq);
      st.iterations = k - 1;
      st.status = 'converged';
      if (log) log.pop();
      break;
    }
    st.cos3 = c3;
    st.sin3 = s3;
    st.cos4 = c4;
    st.sin4 = s4;
    st.detJ = det;
    st.iterations = k;
    const row: IterationRecord | null = log
      ? {
          iteration: k,
          theta3: wrapAngle(t3),
          theta4: wrapAngle(t4),
          f1,
          f2,
          residual: Math.sqrt(resSq),
          stepNorm: 0,
          detJ: det,
        }
      : null;
    if (row) log!.push(row);
    let done: boolean;
    if (s.seed) {
      done = Math.abs(f1) < s.tolAbs && Math.abs(f2) < s.tolAbs;
    } else if (!polishing) {
      done = resSq <= s.tolAbs * s.tolAbs;
      if (done && s.polish) {
        const negligible = resSq <= s.floor * s.floor || stepIsFinal(s.secondOrder, lastStep, sinMu);
        if (!negligible) {
          done = false;
          polishing = true;
        }
      }
    } else {
      done = resSq <= s.floor * s.floor || stepIsFinal(s.secondOrder, lastStep, sinMu) || polishSteps >= 3;
    }
    if (done || k >= s.maxIterations) {
      st.status = done ? 'converged' : 'max-iterations';
      st.residual = Math.sqrt(resSq);
      break;
    }
    const singular = s.seed ? Math.abs(det) < SEED_SINGULAR_DET : Math.abs(sinMu) < SINGULAR_SIN || det === 0;
    if (singular) {
      st.status = 'singular';
      st.residual = Math.sqrt(resSq);
      break;
    }
    // Cramer's rule on J d = -f.
    // Cramer's rule; the project's NR multiplies by one reciprocal, seed mode divides as the report does.
    const inv = 1 / det;
    let d3 = s.seed ? (r4 * (f1 * c4 + f2 * s4)) / det : r4 * (f1 * c4 + f2 * s4) * inv;
    let d4 = s.seed ? (r3 * (f1 * c3 + f2 * s3)) / det : r3 * (f1 * c3 + f2 * s3) * inv;
    if (s.secondOrder && Math.abs(d3) < CHEBYSHEV_MAX_RAD && Math.abs(d4) < CHEBYSHEV_MAX_RAD) {
      // Chebyshev: x + d - J^-1 (f''(d, d) / 2), with f'' diagonal here: d^2 f / d t3^2 = -r3 (c3, s3),
      // d^2 f / d t4^2 = r4 (c4, s4). The same Cramer solve as the Newton step.
      const q3 = d3 * d3;
      const q4 = d4 * d4;
      const g1 = 0.5 * (r4 * c4 * q4 - r3 * c3 * q3);
      const g2 = 0.5 * (r4 * s4 * q4 - r3 * s3 * q3);
      d3 += r4 * (g1 * c4 + g2 * s4) * inv;
      d4 += r3 * (g1 * c3 + g2 * s3) * inv;
    }
    lastStep = Math.sqrt(d3 * d3 + d4 * d4);
    if (!s.seed && lastStep > MAX_STEP_RAD) {
      d3 *= MAX_STEP_RAD / lastStep;
      d4 *= MAX_STEP_RAD / lastStep;
      lastStep = MAX_STEP_RAD;
    }
    if (row) row.stepNorm = lastStep;
    if (polishing) {
      polishSteps++;
      pt3 = t3;
      pt4 = t4;
      pc3 = c3;
      ps3 = s3;
      pc4 = c4;
      ps4 = s4;
      pdet = det;
      prevResidualSq = resSq;
    }
    t3 += d3;
    t4 += d4;
    if (s.seed) continue; // the report's algorithm, verbatim: fresh trig every iteration, angles unwrapped
    // Keep the iterate within one turn, so its rounding stays that of an angle below pi.
    if (t3 > HALF_TURN || t3 <= -HALF_TURN) t3 = wrapAngle(t3);
    if (t4 > HALF_TURN || t4 <= -HALF_TURN) t4 = wrapAngle(t4);
    // A small step rotates (cos, sin) by the angle-addition formulas with a series for the step's own
    // cos and sin (exact to rounding below ROTATE_MAX_RAD): no trig call after the first evaluation.
    needTrig = !(Math.abs(d3) < ROTATE_MAX_RAD && Math.abs(d4) < ROTATE_MAX_RAD);
    if (!needTrig) {
      const q3 = d3 * d3;
      const q4 = d4 * d4;
      const ca = 1 - q3 * (0.5 - q3 / 24);
      const sa = d3 * (1 - q3 * (1 / 6 - q3 / 120));
      const cb = 1 - q4 * (0.5 - q4 / 24);
      const sb = d4 * (1 - q4 * (1 / 6 - q4 / 120));
      const n3 = c3 * ca - s3 * sa;
      s3 = s3 * ca + c3 * sa;
      c3 = n3;
      const n4 = c4 * cb - s4 * sb;
      s4 = s4 * cb + c4 * sb;
      c4 = n4;
    }
  }
  st.theta3 = t3;
  st.theta4 = t4;
}

/**
 * Resolves NewtonOptions for a problem whose lengths sum to total (problem units). Throws an Error
 * naming the option for tol not positive finite, maxIterations not an integer in [0, 100000], or
 * seed/polish/log not boolean.
 */
export function newtonSettings(opts: NewtonOptions, total: number): NewtonSettings {
  checkOptionalPositive('tol', opts.tol);
  checkOptionalBoolean('seed', opts.seed);
  checkOptionalBoolean('polish', opts.polish);
  checkOptionalBoolean('log', opts.log);
  const seed = opts.seed === true;
  const tol = opts.tol ?? (seed ? SEED_TOLERANCE : DEFAULT_TOLERANCE);
  const maxIterations = opts.maxIterations === undefined ? SEED_MAX_ITERATIONS : opts.maxIterations;
  if (!Number.isInteger(maxIterations) || maxIterations < 0 || maxIterations > MAX_ITERATIONS_LIMIT) {
    throw new Error(
      `maxIterations must be an integer from 0 to ${MAX_ITERATIONS_LIMIT}, got ${describe(maxIterations)}`,
    );
  }
  return {
    seed,
    tolAbs: seed ? tol : tol * total,
    maxIterations,
    polish: !seed && opts.polish !== false,
    floor: EPS * total,
    secondOrder: false,
  };
}

/**
 * Solves the loop equations at theta2 (radians) by Newton-Raphson from guess (radians, any finite
 * value: it is first reduced exactly to (-pi, pi]). Default: tolerance relative to r1 + r2 + r3 + r4
 * (1e-13), steps no longer than MAX_STEP_RAD, then polished to full double precision; lengths are
 * rescaled by a power of two so any unit works. opts.seed = true runs the report's Algorithm 1
 * exactly (docs/hard-cases.md). Returns wrapped angles in (-pi, pi], the status, iterations, the
 * residual norm and det J (user's units) and the iteration log. Throws an Error naming the argument
 * for a bad linkage, theta2 not finite, guess without finite theta3/theta4, or a bad option.
 */
export function solveNewton(l: Linkage, theta2: number, guess: Angles, opts: NewtonOptions = {}): NewtonResult {
  validateLinkage(l);
  checkFinite('theta2', theta2, 'angle in radians');
  checkAngles('guess', guess);
  checkObject('opts', opts);
  const seed = opts.seed === true;
  const n = seed ? { ...l, exponent: 0 } : normalizeLinkage(l);
  const problem: NewtonProblem = {
    r1: n.r1,
    r2: n.r2,
    r3: n.r3,
    r4: n.r4,
    cos2: Math.cos(theta2),
    sin2: Math.sin(theta2),
  };
  const settings = newtonSettings(opts, n.r1 + n.r2 + n.r3 + n.r4);
  const st = newNewtonState(wrapAngle(guess.theta3), wrapAngle(guess.theta4));
  const log: IterationRecord[] | null = opts.log === false ? null : [];
  newtonCore(problem, settings, st, log);
  const e = n.exponent;
  const unscale = (x: number) => scaleByPow2(x, e);
  if (log && e !== 0) {
    for (const row of log) {
      row.f1 = unscale(row.f1);
      row.f2 = unscale(row.f2);
      row.residual = unscale(row.residual);
      row.detJ = scaleByPow2(row.detJ, 2 * e);
    }
  }
  return {
    theta3: wrapAngle(st.theta3),
    theta4: wrapAngle(st.theta4),
    status: st.status,
    iterations: st.iterations,
    residual: unscale(st.residual),
    detJ: scaleByPow2(st.detJ, 2 * e),
    log: log ?? [],
  };
}
