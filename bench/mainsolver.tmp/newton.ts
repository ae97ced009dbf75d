import { wrapAngle } from './angles';
import type { Angles, IterationRecord, Linkage, NewtonOptions, NewtonResult, NewtonStatus } from './types';
import { normalizeLinkage, scaleByPow2, validateLinkage } from './validate';

const EPS = Number.EPSILON;

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
 * with det J = r3 r4 sin(theta3 - theta4) (the report's eq. 5 has the sign flipped). Seed mode is
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
  let prevResidual = Infinity;
  let prev = { t3, t4, c3: 1, s3: 0, c4: 1, s4: 0, det: 0 };
  st.iterations = 0;
  for (let k = 0; ; k++) {
    const c3 = Math.cos(t3);
    const s3 = Math.sin(t3);
    const c4 = Math.cos(t4);
    const s4 = Math.sin(t4);
    const f1 = r2 * cos2 + r3 * c3 - r4 * c4 - r1;
    const f2 = r2 * sin2 + r3 * s3 - r4 * s4;
    const res = Math.sqrt(f1 * f1 + f2 * f2);
    const sinMu = s3 * c4 - c3 * s4; // sin(theta3 - theta4)
    const det = r3 * r4 * sinMu;
    if (polishing && !(res < prevResidual)) {
      // The polish step did not help: we are at the rounding floor; keep the previous point.
      t3 = prev.t3;
      t4 = prev.t4;
      st.cos3 = prev.c3;
      st.sin3 = prev.s3;
      st.cos4 = prev.c4;
      st.sin4 = prev.s4;
      st.detJ = prev.det;
      st.residual = prevResidual;
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
    st.residual = res;
    st.iterations = k;
    const row: IterationRecord | null = log
      ? { iteration: k, theta3: wrapAngle(t3), theta4: wrapAngle(t4), f1, f2, residual: res, stepNorm: 0, detJ: det }
      : null;
    if (row) log!.push(row);
    let done: boolean;
    if (s.seed) {
      done = Math.abs(f1) < s.tolAbs && Math.abs(f2) < s.tolAbs;
    } else if (!polishing) {
      done = res <= s.tolAbs;
      if (done && s.polish) {
        const negligible = res <= s.floor || lastStep * lastStep <= EPS * Math.abs(sinMu);
        if (!negligible) {
          done = false;
          polishing = true;
        }
      }
    } else {
      done = res <= s.floor || lastStep * lastStep <= EPS * Math.abs(sinMu) || polishSteps >= 3;
    }
    if (done) {
      st.status = 'converged';
      break;
    }
    if (k >= s.maxIterations) {
      st.status = 'max-iterations';
      break;
    }
    const singular = s.seed ? Math.abs(det) < SEED_SINGULAR_DET : Math.abs(sinMu) < SINGULAR_SIN || det === 0;
    if (singular) {
      st.status = 'singular';
      break;
    }
    // Cramer's rule on J d = -f.
    const d3 = (r4 * (f1 * c4 + f2 * s4)) / det;
    const d4 = (r3 * (f1 * c3 + f2 * s3)) / det;
    lastStep = Math.sqrt(d3 * d3 + d4 * d4);
    if (row) row.stepNorm = lastStep;
    if (polishing) {
      polishSteps++;
      prev = { t3, t4, c3, s3, c4, s4, det };
      prevResidual = res;
    }
    t3 += d3;
    t4 += d4;
  }
  st.theta3 = t3;
  st.theta4 = t4;
}

/** Resolves NewtonOptions for a problem whose lengths sum to total (problem units). */
export function newtonSettings(opts: NewtonOptions, total: number): NewtonSettings {
  const seed = opts.seed === true;
  const tol = opts.tol ?? (seed ? SEED_TOLERANCE : DEFAULT_TOLERANCE);
  if (!(tol > 0) || !Number.isFinite(tol)) throw new Error(`tol must be a positive finite number, got ${tol}`);
  const maxIterations = opts.maxIterations ?? SEED_MAX_ITERATIONS;
  if (!Number.isInteger(maxIterations) || maxIterations < 0) {
    throw new Error(`maxIterations must be a non-negative integer, got ${maxIterations}`);
  }
  return {
    seed,
    tolAbs: seed ? tol : tol * total,
    maxIterations,
    polish: !seed && opts.polish !== false,
    floor: EPS * total,
  };
}

/**
 * Solves the loop equations at theta2 (radians) by Newton-Raphson from guess (radians).
 * Default: tolerance relative to r1 + r2 + r3 + r4 (1e-13), then polished to full double precision;
 * lengths are rescaled by a power of two so any unit works. opts.seed = true runs the report's
 * Algorithm 1 exactly. Returns wrapped angles in (-pi, pi], the status, iterations, the residual
 * norm and det J (user's units) and the iteration log. Throws for a bad linkage, theta2 or guess.
 */
export function solveNewton(l: Linkage, theta2: number, guess: Angles, opts: NewtonOptions = {}): NewtonResult {
  validateLinkage(l);
  if (!Number.isFinite(theta2)) throw new Error(`theta2 must be a finite angle in radians, got ${theta2}`);
  if (!guess || !Number.isFinite(guess.theta3))
    throw new Error(`guess.theta3 must be a finite angle, got ${guess?.theta3}`);
  if (!Number.isFinite(guess.theta4)) throw new Error(`guess.theta4 must be a finite angle, got ${guess.theta4}`);
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
  const st = newNewtonState(guess.theta3, guess.theta4);
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
