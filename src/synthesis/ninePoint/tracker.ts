import { NV, evaluate } from './equations';
import { luFactor, luSolve, norm } from './linear';

/** How a tracked path ended: at a finite regular root, lost (step underflow, singular end), or off to infinity. */
export type PathStatus = 'finished' | 'failed' | 'diverged';

/** Step control of the path tracker; s runs from 0 (start parameters) to 1 (target). */
export interface TrackOptions {
  /** Largest step in s (default 0.1). */
  hMax?: number;
  /** First step in s (default 0.02). */
  h0?: number;
  /** Give up after this many steps (default 4000). */
  maxSteps?: number;
  /** The corrector's tolerance along the path, relative to |z| (default 1e-8; the end is polished to 1e-12). */
  tol?: number;
  /**
   * The prediction error aimed at, relative to |z| (default 1e-3): each step's size is set from the corrector's first
   * update as for an order-5 local error (RK4), so the corrector converges in two or three iterations.
   */
  eta?: number;
}

/** |z| beyond this (in units of the normalised points) counts as a path going to infinity. */
export const DIVERGED_NORM = 1e7;
// Not looser: at 1e-6 or 1e-7, 4–5 of Problem 3's 1442 paths jumped to another path's orbit (0 at 1e-8), which a
// worker pool splitting the paths cannot see.
const TRACK_TOL = 1e-8;
const ETA = 1e-3;
const END_TOL = 1e-12;
const END_FLOOR = 1e-9;

/**
 * A predictor–corrector tracker for the parameter homotopy p(s) = w p0 + (1 − w) p1, w = (1 − s)γ / ((1 − s)γ + s)
 * (the γ trick keeps the path off the discriminant for almost every complex γ): RK4 predictor on J ż = −∂F/∂s, a
 * Newton corrector with a contraction test whose last Jacobian also gives the next step's first tangent (and a
 * rejected step keeps it: z has not moved), the step halved on failure and otherwise set from the size of the
 * corrector's first update (RK4's local error is of order 5). Owns its scratch.
 */
export class Tracker {
  private readonly p = new Float64Array(4 * NV);
  private readonly dp = new Float64Array(4 * NV);
  private readonly diff = new Float64Array(4 * NV);
  private readonly F = new Float64Array(2 * NV);
  private readonly Fp = new Float64Array(2 * NV);
  private readonly J = new Float64Array(2 * NV * NV);
  /** LU factors of the corrector's Jacobian, and the tangent it leaves for the next step. */
  private readonly JL = new Float64Array(2 * NV * NV);
  private readonly piv = new Int32Array(NV);
  /** Row swaps of J's factors (the tangent's and the polishing Newton's). */
  private readonly pivJ = new Int32Array(NV);
  private readonly kNext = new Float64Array(2 * NV);
  /** Size of the last corrector's first update, relative to 1 + |z|. */
  private first = 0;
  private readonly k = [0, 1, 2, 3].map(() => new Float64Array(2 * NV));
  private readonly zt = new Float64Array(2 * NV);
  private readonly zp = new Float64Array(2 * NV);
  private readonly dz = new Float64Array(2 * NV);
  private gr = 1;
  private gi = 0;
  private p0: Float64Array = new Float64Array(4 * NV);
  private p1: Float64Array = new Float64Array(4 * NV);
  /** Evaluations of E and its Jacobian so far (for the benchmark's evaluations per path). */
  evaluations = 0;
  /** Steps rejected so far (predictor singular or corrector not contracting). */
  rejected = 0;

  /** Sets the segment: from parameters p0 to p1 with γ = (gr, gi). */
  setSegment(p0: Float64Array, p1: Float64Array, gr: number, gi: number): void {
    this.p0 = p0;
    this.p1 = p1;
    this.gr = gr;
    this.gi = gi;
    for (let i = 0; i < this.diff.length; i++) this.diff[i] = p0[i] - p1[i];
  }

  /** Parameters at s into this.p, and dp/ds into this.dp. */
  private params(s: number): void {
    const { gr, gi } = this;
    // den = (1 − s)γ + s; w = (1 − s)γ / den; dw/ds = −γ / den²
    const denr = (1 - s) * gr + s;
    const deni = (1 - s) * gi;
    const m = denr * denr + deni * deni;
    const nr = (1 - s) * gr;
    const ni = (1 - s) * gi;
    const wr = (nr * denr + ni * deni) / m;
    const wi = (ni * denr - nr * deni) / m;
    const d2r = denr * denr - deni * deni;
    const d2i = 2 * denr * deni;
    const m2 = d2r * d2r + d2i * d2i;
    const vr = -(gr * d2r + gi * d2i) / m2;
    const vi = -(gi * d2r - gr * d2i) / m2;
    const { p, dp, p0, p1, diff } = this;
    for (let i = 0; i < p.length; i += 2) {
      const ar = p0[i],
        ai = p0[i + 1],
        br = p1[i],
        bi = p1[i + 1];
      p[i] = br + wr * (ar - br) - wi * (ai - bi);
      p[i + 1] = bi + wr * (ai - bi) + wi * (ar - br);
      dp[i] = vr * diff[i] - vi * diff[i + 1];
      dp[i + 1] = vr * diff[i + 1] + vi * diff[i];
    }
  }

  /** Tangent ż at (z, s) into out; false when the Jacobian is singular. */
  private tangent(z: Float64Array, s: number, out: Float64Array): boolean {
    this.params(s);
    evaluate(z, this.p, this.F, this.J, this.dp, this.Fp);
    this.evaluations++;
    for (let i = 0; i < out.length; i++) out[i] = -this.Fp[i];
    if (!luFactor(this.J, this.pivJ, NV)) return false;
    luSolve(this.J, this.pivJ, out, NV);
    return true;
  }

  /**
   * The corrector: Newton at s from z (in place), at most maxIt iterations, each evaluating ∂F/∂s too; returns the
   * iterations used, or −1 when it does not contract to tol·(1 + |z|). On success the tangent at the last iterate
   * (within tol of the new point) is left in kNext, so the next step's predictor starts without a new evaluation.
   * Records the first update's size relative to 1 + |z| (the prediction's error).
   */
  private correct(z: Float64Array, s: number, maxIt: number, tol: number): number {
    this.params(s);
    let last = Infinity;
    const { dz, JL, piv, F, Fp, kNext } = this;
    for (let it = 1; it <= maxIt; it++) {
      evaluate(z, this.p, F, JL, this.dp, Fp);
      this.evaluations++;
      if (!luFactor(JL, piv, NV)) return -1;
      for (let i = 0; i < dz.length; i++) dz[i] = -F[i];
      luSolve(JL, piv, dz, NV);
      const n = norm(dz);
      if (!Number.isFinite(n)) return -1;
      const scale = 1 + norm(z);
      if (it === 1) this.first = n / scale;
      if (n <= tol * scale) {
        for (let i = 0; i < z.length; i++) z[i] += dz[i];
        for (let i = 0; i < kNext.length; i++) kNext[i] = -Fp[i];
        luSolve(JL, piv, kNext, NV);
        return it;
      }
      if (it > 1 && n > 0.5 * last) return -1;
      for (let i = 0; i < z.length; i++) z[i] += dz[i];
      last = n;
    }
    return -1;
  }

  /**
   * Newton at s from z (in place), at most maxIt iterations; returns the iterations used, or −1 when it does not
   * contract to tol·(1 + |z|).
   */
  newton(z: Float64Array, s: number, maxIt: number, tol: number): number {
    this.params(s);
    let last = Infinity;
    for (let it = 1; it <= maxIt; it++) {
      evaluate(z, this.p, this.F, this.J);
      this.evaluations++;
      const dz = this.dz;
      for (let i = 0; i < dz.length; i++) dz[i] = -this.F[i];
      if (!luFactor(this.J, this.pivJ, NV)) return -1;
      luSolve(this.J, this.pivJ, dz, NV);
      const n = norm(dz);
      if (!Number.isFinite(n)) return -1;
      if (n <= tol * (1 + norm(z))) {
        for (let i = 0; i < z.length; i++) z[i] += dz[i];
        return it;
      }
      if (it > 1 && n > 0.5 * last) return -1;
      for (let i = 0; i < z.length; i++) z[i] += dz[i];
      last = n;
    }
    return -1;
  }

  /** Tracks root z (in place) from s = 0 to s = 1 on the current segment. */
  track(z: Float64Array, opts: TrackOptions = {}): { status: PathStatus; steps: number } {
    const hMax = opts.hMax ?? 0.1;
    const maxSteps = opts.maxSteps ?? 4000;
    const tol = opts.tol ?? TRACK_TOL;
    const eta = opts.eta ?? ETA;
    let h = Math.min(opts.h0 ?? 0.02, hMax);
    let s = 0;
    let steps = 0;
    const [k1, k2, k3, k4] = this.k;
    const { zt, zp } = this;
    const n = z.length;
    // k1 is the tangent at (z, s): kept through a rejected step, taken from the corrector after an accepted one.
    let k1Valid = false;
    while (s < 1) {
      if (++steps > maxSteps || h < 1e-13) return { status: 'failed', steps };
      if (s + h > 1) h = 1 - s;
      // RK4 predictor
      if (!k1Valid) k1Valid = this.tangent(z, s, k1);
      let ok = k1Valid;
      for (let i = 0; ok && i < n; i++) zt[i] = z[i] + 0.5 * h * k1[i];
      ok = ok && this.tangent(zt, s + 0.5 * h, k2);
      for (let i = 0; ok && i < n; i++) zt[i] = z[i] + 0.5 * h * k2[i];
      ok = ok && this.tangent(zt, s + 0.5 * h, k3);
      for (let i = 0; ok && i < n; i++) zt[i] = z[i] + h * k3[i];
      const sNew = s + h >= 1 - 1e-15 ? 1 : s + h;
      ok = ok && this.tangent(zt, sNew, k4);
      if (!ok) {
        this.rejected++;
        h *= 0.5;
        continue;
      }
      for (let i = 0; i < n; i++) zp[i] = z[i] + (h / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
      const it = this.correct(zp, sNew, 3, tol);
      if (it < 0) {
        this.rejected++;
        h *= 0.5;
        continue;
      }
      z.set(zp);
      s = sNew;
      k1.set(this.kNext);
      const size = norm(z);
      if (!Number.isFinite(size)) return { status: 'failed', steps };
      if (size > DIVERGED_NORM) return { status: 'diverged', steps };
      // RK4's local error goes as h⁵: aim the next prediction's error at eta, changing h by at most 2× either way.
      const grow = this.first > 0 ? 0.9 * Math.pow(eta / this.first, 0.2) : 2;
      h = Math.min(hMax, h * Math.min(2, Math.max(0.5, grow)));
    }
    // Polish at the target; a root that will not converge quadratically is singular (or the path jumped).
    const zEnd = z.slice();
    let it = this.newton(z, 1, 6, END_TOL);
    if (it < 0) {
      // An ill-conditioned root stalls at its rounding level above END_TOL: accept it at END_FLOOR.
      z.set(zEnd);
      it = this.newton(z, 1, 6, END_FLOOR);
    }
    if (it < 0) {
      const zz = norm(z);
      return { status: zz > 1e4 ? 'diverged' : 'failed', steps };
    }
    return { status: 'finished', steps };
  }
}
