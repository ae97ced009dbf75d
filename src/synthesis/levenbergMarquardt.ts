/**
 * A bounded, projected Levenberg–Marquardt method for small dense least-squares problems (tens of variables).
 * Box bounds are handled by an active set: a variable at a bound whose descent direction points out of the box
 * is frozen for the step, so the method converges quadratically on a face of the box as well as inside it. Other
 * convex constraints are a projection the problem supplies; nonlinear ones are a feasibility test that rejects a
 * trial point (the step is then shortened, then the damping raised). Marquardt's diagonal scaling makes the
 * method invariant to the variables' units.
 */

/** A least-squares problem: minimise Σ r_i(x)² over x in a box, a convex set (project) and a feasible set. */
export interface LeastSquaresProblem {
  /** Number of variables. */
  m: number;
  /** Number of residuals. */
  k: number;
  /** Writes r(x) and, when J is given, the Jacobian (row-major, k × m); false where r is undefined. */
  evaluate(x: Float64Array, r: Float64Array, J: Float64Array | null): boolean;
  /** Box bounds per variable (±Infinity for none). */
  lo: Float64Array;
  hi: Float64Array;
  /** Projects x (already inside the box) onto the problem's other convex constraints, in place. */
  project?: (x: Float64Array) => void;
  /** Nonlinear constraints: false rejects x. */
  feasible?: (x: Float64Array) => boolean;
  /**
   * Linear constraints a · x ≥ c near x (those of the convex piece project keeps x in): a step that would cross one
   * is solved again with it as an equality, so the method moves along the face instead of being cut short by the
   * projection (a length m each).
   */
  faces?: (x: Float64Array) => { a: Float64Array; c: number }[];
}

/** Options of levenbergMarquardt. */
export interface LevenbergMarquardtOptions {
  /** Iteration cap (default 200). */
  maxIterations?: number;
  /** Stop once Σr² is at or below this (default 0: iterate until no progress). */
  fTarget?: number;
  /** Stop after the iteration that passes this time (Date.now(), ms; default never). */
  deadline?: number;
  /** Stop after the iteration during which this is aborted (an AbortSignal fits). */
  signal?: { readonly aborted: boolean };
}

/** Result of levenbergMarquardt: the last accepted point, its Σr², and the work done. */
export interface LevenbergMarquardtResult {
  x: Float64Array;
  f: number;
  iterations: number;
  /** Residual evaluations (Jacobians included). */
  evaluations: number;
}

/** Cholesky factor of the m × m SPD matrix M in place (lower triangle); false when M is not positive definite. */
function choleskyFactor(M: Float64Array, m: number): boolean {
  for (let j = 0; j < m; j++) {
    let d = M[j * m + j];
    for (let k = 0; k < j; k++) d -= M[j * m + k] * M[j * m + k];
    if (!(d > 0)) return false;
    const l = Math.sqrt(d);
    M[j * m + j] = l;
    for (let i = j + 1; i < m; i++) {
      let s = M[i * m + j];
      for (let k = 0; k < j; k++) s -= M[i * m + k] * M[j * m + k];
      M[i * m + j] = s / l;
    }
  }
  return true;
}

/** Solves L Lᵀ y = b in place (b becomes y) with the factor of choleskyFactor. */
function choleskySubst(M: Float64Array, b: Float64Array, m: number): void {
  for (let i = 0; i < m; i++) {
    let s = b[i];
    for (let k = 0; k < i; k++) s -= M[i * m + k] * b[k];
    b[i] = s / M[i * m + i];
  }
  for (let i = m - 1; i >= 0; i--) {
    let s = b[i];
    for (let k = i + 1; k < m; k++) s -= M[k * m + i] * b[k];
    b[i] = s / M[i * m + i];
  }
}

/** Largest number of faces held as equalities in one step. */
const MAX_FACES = 4;

/**
 * Corrects the step s (free variables free[0 … nf)) so that the faces it would cross hold as equalities:
 * s ← s + M⁻¹ N λ with (Nᵀ M⁻¹ N) λ = c − N ᵀ(x + s), M the factored damped normal matrix (the minimiser of the
 * model on those faces). Faces whose normal has no free component are left to the projection.
 */
function holdFaces(
  faces: { a: Float64Array; c: number }[],
  x: Float64Array,
  s: Float64Array,
  free: number[],
  M: Float64Array,
): void {
  const nf = free.length;
  const held: { a: Float64Array; c: number; w: Float64Array }[] = [];
  const slack = (f: { a: Float64Array; c: number }) => {
    let v = -f.c;
    for (let i = 0; i < x.length; i++) v += f.a[i] * x[i];
    for (let q = 0; q < nf; q++) v += f.a[free[q]] * s[q];
    return v;
  };
  if (!faces.some((f) => slack(f) < 0)) return;
  const s0 = Float64Array.from(s.subarray(0, nf));
  for (let pass = 0; pass < MAX_FACES; pass++) {
    let worst: { a: Float64Array; c: number } | null = null;
    let worstV = 0;
    for (const f of faces) {
      if (held.some((h) => h.a === f.a)) continue;
      const v = slack(f);
      if (v < worstV) {
        worstV = v;
        worst = f;
      }
    }
    if (!worst) return;
    const w = new Float64Array(nf);
    let any = false;
    for (let q = 0; q < nf; q++) {
      w[q] = worst.a[free[q]];
      if (w[q] !== 0) any = true;
    }
    if (!any) return;
    choleskySubst(M, w, nf);
    held.push({ ...worst, w });
    // Solve the k × k system (Nᵀ M⁻¹ N) λ = c − Nᵀ(x + s0) by Gaussian elimination (k ≤ MAX_FACES).
    const k = held.length;
    const G = new Float64Array(k * k);
    const rhs = new Float64Array(k);
    for (let i = 0; i < k; i++) {
      let v = held[i].c;
      for (let j = 0; j < x.length; j++) v -= held[i].a[j] * x[j];
      for (let q = 0; q < nf; q++) v -= held[i].a[free[q]] * s0[q];
      rhs[i] = v;
      for (let j = 0; j < k; j++) {
        let g = 0;
        for (let q = 0; q < nf; q++) g += held[i].a[free[q]] * held[j].w[q];
        G[i * k + j] = g;
      }
    }
    if (!solveSmall(G, rhs, k)) return;
    for (let q = 0; q < nf; q++) {
      let v = s0[q];
      for (let j = 0; j < k; j++) v += held[j].w[q] * rhs[j];
      s[q] = v;
    }
  }
}

/** Gaussian elimination with partial pivoting of a k × k system in place (b becomes the solution). */
function solveSmall(G: Float64Array, b: Float64Array, k: number): boolean {
  for (let c = 0; c < k; c++) {
    let p = c;
    for (let r = c + 1; r < k; r++) if (Math.abs(G[r * k + c]) > Math.abs(G[p * k + c])) p = r;
    if (!(Math.abs(G[p * k + c]) > 0)) return false;
    if (p !== c) {
      for (let j = 0; j < k; j++) [G[c * k + j], G[p * k + j]] = [G[p * k + j], G[c * k + j]];
      [b[c], b[p]] = [b[p], b[c]];
    }
    for (let r = c + 1; r < k; r++) {
      const f = G[r * k + c] / G[c * k + c];
      for (let j = c; j < k; j++) G[r * k + j] -= f * G[c * k + j];
      b[r] -= f * b[c];
    }
  }
  for (let c = k - 1; c >= 0; c--) {
    let v = b[c];
    for (let j = c + 1; j < k; j++) v -= G[c * k + j] * b[j];
    b[c] = v / G[c * k + c];
  }
  return true;
}

function sumSquares(r: Float64Array): number {
  let f = 0;
  for (let i = 0; i < r.length; i++) f += r[i] * r[i];
  return f;
}

/**
 * Minimises Σ r(x)² from x0 (projected onto the constraints first). Returns the best feasible point found;
 * f is Infinity when x0 itself cannot be evaluated. Never throws for an expected outcome.
 */
export function levenbergMarquardt(
  p: LeastSquaresProblem,
  x0: Float64Array,
  options: LevenbergMarquardtOptions = {},
): LevenbergMarquardtResult {
  const steps = levenbergMarquardtSteps(p, x0, options);
  for (;;) {
    const next = steps.next();
    if (next.done) return next.value;
  }
}

/**
 * levenbergMarquardt as a generator that pauses before each iteration, so a caller can yield to the event loop
 * between iterations of a large problem (one iteration of 200 free-timing targets is tens of milliseconds).
 */
export function* levenbergMarquardtSteps(
  p: LeastSquaresProblem,
  x0: Float64Array,
  options: LevenbergMarquardtOptions = {},
): Generator<void, LevenbergMarquardtResult, void> {
  const { m, k, lo, hi } = p;
  const maxIterations = options.maxIterations ?? 200;
  const fTarget = options.fTarget ?? 0;
  const deadline = options.deadline ?? Infinity;
  const x = Float64Array.from(x0);
  const place = (y: Float64Array): void => {
    for (let i = 0; i < m; i++) y[i] = Math.min(hi[i], Math.max(lo[i], y[i]));
    p.project?.(y);
  };
  place(x);
  let r = new Float64Array(k);
  const J = new Float64Array(k * m);
  let evaluations = 1;
  if ((p.feasible && !p.feasible(x)) || !p.evaluate(x, r, J)) return { x, f: Infinity, iterations: 0, evaluations };
  let f = sumSquares(r);
  if (!Number.isFinite(f)) return { x, f: Infinity, iterations: 0, evaluations };
  let rt = new Float64Array(k);
  const xt = new Float64Array(m);
  const g = new Float64Array(m);
  const A = new Float64Array(m * m);
  const M = new Float64Array(m * m);
  const step = new Float64Array(m);
  const free: number[] = [];
  let lambda = 1e-3;
  let stalls = 0;
  let iterations = 0;
  for (; iterations < maxIterations && f > fTarget; iterations++) {
    yield;
    if ((deadline < Infinity && Date.now() > deadline) || options.signal?.aborted) break;
    g.fill(0);
    A.fill(0);
    for (let row = 0; row < k; row++) {
      const o = row * m;
      const ri = r[row];
      for (let i = 0; i < m; i++) {
        const ji = J[o + i];
        if (ji === 0) continue;
        g[i] += ji * ri;
        for (let j = i; j < m; j++) A[i * m + j] += ji * J[o + j];
      }
    }
    if (!g.every(Number.isFinite) || !A.every(Number.isFinite)) break;
    free.length = 0;
    let dMax = 0;
    for (let i = 0; i < m; i++) {
      const atLo = x[i] <= lo[i] && g[i] > 0;
      const atHi = x[i] >= hi[i] && g[i] < 0;
      if (!atLo && !atHi) free.push(i);
      dMax = Math.max(dMax, A[i * m + i]);
    }
    const nf = free.length;
    if (nf === 0 || dMax === 0) break;
    const floor = 1e-14 * dMax;
    let accepted = false;
    const fOld = f;
    while (lambda < 1e16) {
      yield;
      for (let a = 0; a < nf; a++) {
        const i = free[a];
        for (let b = a; b < nf; b++) {
          const j = free[b];
          const v = i <= j ? A[i * m + j] : A[j * m + i];
          M[a * nf + b] = v;
          M[b * nf + a] = v;
        }
        M[a * nf + a] += lambda * Math.max(A[i * m + i], floor) + floor;
        step[a] = -g[i];
      }
      if (!choleskyFactor(M, nf)) {
        lambda *= 4;
        continue;
      }
      choleskySubst(M, step, nf);
      if (p.faces) holdFaces(p.faces(x), x, step, free, M);
      // Full step first; where it leaves the feasible set, shorter steps along it.
      for (let t = 1; t >= 0.1; t *= 0.5) {
        xt.set(x);
        for (let a = 0; a < nf; a++) xt[free[a]] += t * step[a];
        place(xt);
        evaluations++;
        if (p.feasible && !p.feasible(xt)) continue;
        if (!p.evaluate(xt, rt, null)) continue;
        const ft = sumSquares(rt);
        if (ft < f) {
          accepted = true;
          f = ft;
          break;
        }
        break;
      }
      if (accepted) break;
      lambda *= 4;
    }
    if (!accepted) break;
    x.set(xt);
    [r, rt] = [rt, r];
    evaluations++;
    if (!p.evaluate(x, r, J)) break;
    f = sumSquares(r);
    lambda = Math.max(lambda / 5, 1e-15);
    if (fOld - f <= 1e-12 * fOld) {
      if (++stalls >= 4) break;
    } else stalls = 0;
  }
  return { x, f, iterations, evaluations };
}
