/**
 * The path-synthesis least-squares problem over one design's variables, in normalised units (pathTask.ts):
 * [O2x, O2y, ground angle (absent when the placement is fixed), r1, r2, r3, r4, ρ, φ, timing…] where ρ = |AP| and
 * φ its angle from AB (polar, so that the bound ρ ≤ coupler is a box face the active set can hold exactly) and the
 * timing variables are
 * - free: θ2 of the first target, then the advances δ2..δn ≥ 0 (Σδ ≤ 2π) in the run's turning direction;
 * - step: θ2 of the first target;
 * - given: none.
 * Residuals are the 2n coordinate differences P(θ2_i) − T_i with the exact Jacobian of pathModel.ts.
 */
import { TWO_PI, inputRange } from '../solver';
import type { LeastSquaresProblem } from './levenbergMarquardt';
import { MODEL_SIZE, couplerLocal } from './pathModel';
import type { NormalisedTask } from './pathTask';

/** Variable layout of a path problem: index of each group in x. */
export interface PathLayout {
  /** Index of O2x (O2y and the ground angle follow), or -1 when the placement is fixed. */
  place: number;
  /** Index of r1 (r2, r3, r4, ρ = |AP|, φ = angle of AP from AB follow). */
  links: number;
  /** Index of the first timing variable. */
  timing: number;
  /** Number of variables. */
  m: number;
}

/** A path problem for one branch and turning direction, with the helpers that read a design off x. */
export interface PathProblem {
  lsq: LeastSquaresProblem;
  layout: PathLayout;
  /** +1 open, −1 crossed. */
  sigma: number;
  /** Turning direction of free timing: +1 counter-clockwise, −1 clockwise. */
  dir: number;
  /** θ2 at every target (radians, unwrapped, in order of travel) for the variables x. */
  thetas(x: Float64Array, out: Float64Array): void;
  /** O2 (normalised) and ground angle of x. */
  placementOf(x: Float64Array): { x: number; y: number; angle: number };
}

/** The layout of a task's variables. */
export function pathLayout(t: NormalisedTask): PathLayout {
  const place = t.placement ? -1 : 0;
  const links = t.placement ? 0 : 3;
  const timing = links + 6;
  const nt = t.timing === 'free' ? t.n : t.timing === 'step' ? 1 : 0;
  return { place, links, timing, m: timing + nt };
}

/** Relative margin kept from the Grashof equality (a change point is not a crank: it can flip branch). */
const CRANK_MARGIN = 1e-9;

/** True when the input of r1..r4 turns fully with a margin (no limit position: Grashof, r1 or r2 shortest). */
export function turnsFully(r1: number, r2: number, r3: number, r4: number): boolean {
  const e = CRANK_MARGIN * (r1 + r2 + r3 + r4);
  const t3 = r3 + r4 - r1 - r2;
  const t1 = r1 + r3 - r2 - r4;
  const t2 = r1 + r4 - r2 - r3;
  return t3 > e && ((t1 > e && t2 > e) || (t1 < -e && t2 < -e));
}

/**
 * True when every input angle from lo to hi (radians, lo ≤ hi) lies strictly inside one reachable interval of the
 * input of r1..r4, so the motion through them meets no limit position (always true for a full turn).
 */
export function sweepWithinRange(r1: number, r2: number, r3: number, r4: number, lo: number, hi: number): boolean {
  const range = inputRange({ r1, r2, r3, r4 });
  if (range.full) return true;
  for (const iv of range.intervals) {
    if (!(iv.hi > iv.lo)) continue;
    const k = Math.floor((lo - iv.lo) / TWO_PI);
    for (const kk of [k - 1, k, k + 1]) {
      const a = iv.lo + kk * TWO_PI;
      const b = iv.hi + kk * TWO_PI;
      if (lo > a && hi < b) return true;
    }
  }
  return false;
}

/** The path problem of task t on branch sigma (+1 open, −1 crossed), free timing turning dir (±1). */
export function createPathProblem(t: NormalisedTask, sigma: number, dir: number): PathProblem {
  const layout = pathLayout(t);
  const { m, links: L, timing: T, place } = layout;
  const n = t.n;
  const k = 2 * n;
  const lo = new Float64Array(m).fill(-Infinity);
  const hi = new Float64Array(m).fill(Infinity);
  if (place >= 0) {
    lo[place] = t.pivotMin.x;
    hi[place] = t.pivotMax.x;
    lo[place + 1] = t.pivotMin.y;
    hi[place + 1] = t.pivotMax.y;
  }
  for (let j = 0; j < 4; j++) {
    lo[L + j] = t.lenMin;
    hi[L + j] = t.lenMax;
  }
  lo[L + 4] = 0;
  hi[L + 4] = t.coupler;
  if (t.timing === 'free') {
    for (let i = 1; i < n; i++) {
      lo[T + i] = 0;
      hi[T + i] = TWO_PI;
    }
  }
  const placementOf = (x: Float64Array) =>
    t.placement ? t.placement : { x: x[place], y: x[place + 1], angle: x[place + 2] };
  const thetas = (x: Float64Array, out: Float64Array): void => {
    if (t.timing === 'given') out.set(t.given);
    else if (t.timing === 'step') for (let i = 0; i < n; i++) out[i] = x[T] + i * t.step;
    else {
      let a = x[T];
      out[0] = a;
      for (let i = 1; i < n; i++) out[i] = a += dir * x[T + i];
    }
  };
  const th = new Float64Array(n);
  const model = new Float64Array(MODEL_SIZE);
  const evaluate = (x: Float64Array, r: Float64Array, J: Float64Array | null): boolean => {
    const pl = placementOf(x);
    const cg = Math.cos(pl.angle);
    const sg = Math.sin(pl.angle);
    const r1 = x[L];
    const r2 = x[L + 1];
    const r3 = x[L + 2];
    const r4 = x[L + 3];
    const rho = x[L + 4];
    const cphi = Math.cos(x[L + 5]);
    const sphi = Math.sin(x[L + 5]);
    const u = rho * cphi;
    const v = rho * sphi;
    thetas(x, th);
    if (J) J.fill(0);
    for (let i = 0; i < n; i++) {
      if (!couplerLocal(r1, r2, r3, r4, u, v, th[i], sigma, model)) return false;
      const px = model[0];
      const py = model[1];
      r[2 * i] = pl.x + cg * px - sg * py - t.tx[i];
      r[2 * i + 1] = pl.y + sg * px + cg * py - t.ty[i];
      if (!J) continue;
      const ox = 2 * i * m;
      const oy = ox + m;
      if (place >= 0) {
        J[ox + place] = 1;
        J[oy + place + 1] = 1;
        J[ox + place + 2] = -sg * px - cg * py;
        J[oy + place + 2] = cg * px - sg * py;
      }
      for (let j = 0; j < 4; j++) {
        const dx = model[2 + 2 * j];
        const dy = model[3 + 2 * j];
        J[ox + L + j] = cg * dx - sg * dy;
        J[oy + L + j] = sg * dx + cg * dy;
      }
      // (u, v) = ρ (cos φ, sin φ): ∂/∂ρ = cos φ ∂/∂u + sin φ ∂/∂v, ∂/∂φ = −v ∂/∂u + u ∂/∂v.
      const drx = cphi * model[10] + sphi * model[12];
      const dry = cphi * model[11] + sphi * model[13];
      const dfx = -v * model[10] + u * model[12];
      const dfy = -v * model[11] + u * model[13];
      J[ox + L + 4] = cg * drx - sg * dry;
      J[oy + L + 4] = sg * drx + cg * dry;
      J[ox + L + 5] = cg * dfx - sg * dfy;
      J[oy + L + 5] = sg * dfx + cg * dfy;
      const dthx = cg * model[14] - sg * model[15];
      const dthy = sg * model[14] + cg * model[15];
      if (t.timing === 'step') {
        J[ox + T] = dthx;
        J[oy + T] = dthy;
      } else if (t.timing === 'free') {
        // θ_i = θ_1 + dir Σ_{j ≤ i} δ_j.
        J[ox + T] = dthx;
        J[oy + T] = dthy;
        for (let j = 1; j <= i; j++) {
          J[ox + T + j] = dir * dthx;
          J[oy + T + j] = dir * dthy;
        }
      }
    }
    return true;
  };
  const project = (x: Float64Array): void => {
    if (t.timing === 'free' && n > 1) projectCappedSimplex(x, T + 1, n - 1, TWO_PI);
    if (t.crank) projectCrank(x, L, t.lenMin, t.lenMax);
  };
  const feasible = (x: Float64Array): boolean => {
    const r1 = x[L];
    const r2 = x[L + 1];
    const r3 = x[L + 2];
    const r4 = x[L + 3];
    if (t.crank) return turnsFully(r1, r2, r3, r4);
    if (t.timing === 'given') {
      thetas(x, th);
      let a = Infinity;
      let b = -Infinity;
      for (const v of th) {
        a = Math.min(a, v);
        b = Math.max(b, v);
      }
      return sweepWithinRange(r1, r2, r3, r4, a, b);
    }
    thetas(x, th);
    return sweepWithinRange(r1, r2, r3, r4, Math.min(th[0], th[n - 1]), Math.max(th[0], th[n - 1]));
  };
  const faces = t.crank ? crankFaces(L, m) : undefined;
  return { lsq: { m, k, evaluate, lo, hi, project, feasible, faces }, layout, sigma, dir, thetas, placementOf };
}

/**
 * The two cones of lengths whose input turns fully (turnsFully): a crank-rocker or double crank with r2 the
 * shortest (t3, t1, t2 ≥ 0) and a drag link with r1 the shortest (t3, −t1, −t2 ≥ 0); each row is a normal a with
 * a · (r1, r2, r3, r4) ≥ 0 (t3 = r3 + r4 − r1 − r2, t1 = r1 + r3 − r2 − r4, t2 = r1 + r4 − r2 − r3).
 */
const CRANK_CONES: readonly (readonly (readonly number[])[])[] = [
  [
    [-1, -1, 1, 1],
    [1, -1, 1, -1],
    [1, -1, -1, 1],
  ],
  [
    [-1, -1, 1, 1],
    [-1, 1, -1, 1],
    [-1, 1, 1, -1],
  ],
];
/** Sweeps of alternating projections onto a cone's faces and the length box. */
const CRANK_SWEEPS = 30;

/**
 * Moves the lengths x[L .. L+4) onto the nearer cone of full-turning inputs (a little inside its faces), staying in
 * [lo, hi], in place; no change when they already turn fully. Without it a best fit that lies on the Grashof face (a
 * crank at its change point) is met only by shortened steps that stop short of it: with it the step slides along
 * the face, as the active set does on a box face (issue 34 item 6).
 */
export function projectCrank(x: Float64Array, L: number, lo: number, hi: number): void {
  const r0 = [x[L], x[L + 1], x[L + 2], x[L + 3]];
  if (turnsFully(r0[0], r0[1], r0[2], r0[3])) return;
  let best: number[] | null = null;
  let bestD = Infinity;
  for (const cone of CRANK_CONES) {
    const r = r0.slice();
    for (let sweep = 0; sweep < CRANK_SWEEPS; sweep++) {
      const e = 4 * CRANK_MARGIN * (r[0] + r[1] + r[2] + r[3]);
      for (const a of cone) {
        const g = a[0] * r[0] + a[1] * r[1] + a[2] * r[2] + a[3] * r[3] - e;
        if (g < 0) for (let j = 0; j < 4; j++) r[j] -= (g * a[j]) / 4;
      }
      for (let j = 0; j < 4; j++) r[j] = Math.min(hi, Math.max(lo, r[j]));
      if (turnsFully(r[0], r[1], r[2], r[3])) break;
    }
    if (!turnsFully(r[0], r[1], r[2], r[3])) continue;
    const d = Math.hypot(r[0] - r0[0], r[1] - r0[1], r[2] - r0[2], r[3] - r0[3]);
    if (d < bestD) {
      bestD = d;
      best = r;
    }
  }
  if (best) for (let j = 0; j < 4; j++) x[L + j] = best[j];
}

/**
 * The faces of the cone of full-turning inputs that the lengths x[L .. L+4) lie in (margin included), as linear
 * constraints on all m variables; [] when they lie in neither cone. Returns a function that reuses its arrays (it is
 * called at every damping trial of a local solve).
 */
export function crankFaces(L: number, m: number): (x: Float64Array) => { a: Float64Array; c: number }[] {
  const faces = CRANK_CONES.map((cone) =>
    cone.map((a) => {
      const v = new Float64Array(m);
      for (let j = 0; j < 4; j++) v[L + j] = a[j];
      return { a: v, c: 0 };
    }),
  );
  return (x) => {
    const r1 = x[L];
    const r2 = x[L + 1];
    const r3 = x[L + 2];
    const r4 = x[L + 3];
    const e = 2 * CRANK_MARGIN * (r1 + r2 + r3 + r4);
    for (let k = 0; k < CRANK_CONES.length; k++) {
      const cone = CRANK_CONES[k];
      if (!cone.every((a) => a[0] * r1 + a[1] * r2 + a[2] * r3 + a[3] * r4 > 0)) continue;
      for (const f of faces[k]) f.c = e;
      return faces[k];
    }
    return [];
  };
}

/** Projects x[from .. from+count) (each already in [0, cap]) onto { δ ≥ 0, Σδ ≤ cap } (Euclidean), in place. */
export function projectCappedSimplex(x: Float64Array, from: number, count: number, cap: number): void {
  let sum = 0;
  for (let i = 0; i < count; i++) sum += Math.max(0, x[from + i]);
  if (sum <= cap) {
    for (let i = 0; i < count; i++) x[from + i] = Math.max(0, x[from + i]);
    return;
  }
  // The projection onto the simplex Σδ = cap: δ_i = max(0, x_i − τ) with τ from the sorted values.
  const v = Array.from(x.subarray(from, from + count)).sort((a, b) => b - a);
  let acc = 0;
  let tau = 0;
  for (let i = 0; i < count; i++) {
    acc += v[i];
    const tt = (acc - cap) / (i + 1);
    if (i === count - 1 || v[i + 1] <= tt) {
      tau = tt;
      break;
    }
  }
  for (let i = 0; i < count; i++) x[from + i] = Math.max(0, x[from + i] - tau);
}
