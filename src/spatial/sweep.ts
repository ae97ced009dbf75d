import { TWO_PI } from '../solver';
import { kernelOf } from './kernel';
import { Closure, newPoint } from './point';
import type { SpatialBranch, SpatialModel, SphericalLinkage } from './types';
import { branchSigma, checkFinite, describe } from './validate';

/** Columns of a sweep, one entry per input angle; NaN (and valid 0) where the loop cannot close. */
export interface SpatialSweep {
  /** Input angles, radians, start + 2 pi k / steps (not wrapped). */
  theta2: Float64Array;
  /** Output angle (radians, wrapped to (-pi, pi]), its rate (rad/s) and acceleration (rad/s^2). */
  theta4: Float64Array;
  omega4: Float64Array;
  alpha4: Float64Array;
  /** Transmission angle analogue (radians, [0, pi]). */
  mu: Float64Array;
  /** Pins, x y z interleaved (3 per input angle), in the linkage's length unit (unit sphere for spherical). */
  A: Float64Array;
  B: Float64Array;
  /** The coupler point, x y z interleaved (spherical with pDist only). */
  P?: Float64Array;
  /** 1 where the loop closes, 0 where not. */
  valid: Uint8Array;
}

/** Options of sweepSpatial: steps per turn (integer 1..1e7, default 360), start (radians, 0), omega2 (1 rad/s), alpha2 (0). */
export interface SweepSpatialOptions {
  steps?: number;
  start?: number;
  omega2?: number;
  alpha2?: number;
}

/** Most steps a sweep takes (its arrays are allocated up front). */
export const MAX_SPATIAL_STEPS = 10_000_000;

/**
 * Solves the model over one turn of the input (steps + 1 angles from start) on the branch, with rates for the input's
 * omega2 and alpha2: typed columns for plots and the 3D view. Throws an Error naming the field for bad input.
 */
export function sweepSpatial(
  model: SpatialModel,
  branch: SpatialBranch,
  options: SweepSpatialOptions = {},
): SpatialSweep {
  const k = kernelOf(model);
  const sigma = branchSigma(branch);
  const steps = options.steps ?? 360;
  if (!Number.isInteger(steps) || steps < 1 || steps > MAX_SPATIAL_STEPS) {
    throw new Error(`steps must be an integer from 1 to ${MAX_SPATIAL_STEPS}, got ${describe(steps)}`);
  }
  const start = options.start ?? 0;
  const omega2 = options.omega2 ?? 1;
  const alpha2 = options.alpha2 ?? 0;
  checkFinite('start', start, 'angle in radians');
  checkFinite('omega2', omega2, 'angular velocity in rad/s');
  checkFinite('alpha2', alpha2, 'angular acceleration in rad/s^2');
  const n = steps + 1;
  const out: SpatialSweep = {
    theta2: new Float64Array(n),
    theta4: new Float64Array(n),
    omega4: new Float64Array(n),
    alpha4: new Float64Array(n),
    mu: new Float64Array(n),
    A: new Float64Array(3 * n),
    B: new Float64Array(3 * n),
    valid: new Uint8Array(n),
  };
  const P = k.coupler ? new Float64Array(3 * n) : null;
  if (P) out.P = P;
  const p = newPoint();
  const u = k.unit;
  for (let i = 0; i < n; i++) {
    const t2 = start + (TWO_PI * i) / steps;
    out.theta2[i] = t2;
    const status = k.at(t2, sigma, p);
    if (status === Closure.Unreachable) {
      out.theta4[i] = out.omega4[i] = out.alpha4[i] = out.mu[i] = NaN;
      out.A.fill(NaN, 3 * i, 3 * i + 3);
      out.B.fill(NaN, 3 * i, 3 * i + 3);
      P?.fill(NaN, 3 * i, 3 * i + 3);
      continue;
    }
    k.rates(p, omega2, alpha2);
    out.valid[i] = 1;
    out.theta4[i] = p.theta4;
    out.omega4[i] = p.omega4;
    out.alpha4[i] = p.alpha4;
    out.mu[i] = p.mu;
    out.A[3 * i] = p.ax * u;
    out.A[3 * i + 1] = p.ay * u;
    out.A[3 * i + 2] = p.az * u;
    out.B[3 * i] = p.bx * u;
    out.B[3 * i + 1] = p.by * u;
    out.B[3 * i + 2] = p.bz * u;
    if (P && k.coupler) k.coupler(p, P, 3 * i);
  }
  return out;
}

/**
 * The spherical coupler curve: P over one turn of the input on the branch (steps + 1 points, x y z interleaved on the
 * unit sphere, NaN where the loop cannot close). Throws unless the linkage has a coupler point (pDist).
 */
export function sphericalCouplerCurve(l: SphericalLinkage, branch: SpatialBranch, steps = 360): Float64Array {
  if (l?.pDist === undefined) throw new Error(`pDist must be set for a coupler curve, got ${describe(l?.pDist)}`);
  return sweepSpatial({ kind: 'spherical', linkage: l }, branch, { steps }).P!;
}
