import { PI, TWO_PI } from '../solver';
import { kernelOf } from './kernel';
import type { Kernel } from './kernel';
import { Closure, newPoint } from './point';
import type { SpatialPoint } from './point';
import type { SpatialBranch, SpatialModel } from './types';
import { branchSigma, checkFinite, describe } from './validate';

/**
 * The transmission angle analogue at theta2 (radians, [0, pi]): the angle at B between the coupler (towards A) and the
 * rocker's inward radius, measured in the rocker's plane of motion (for RSSR the coupler's component along the output
 * axis does no work on the rocker); 90 degrees transmits best. The planar transmission angle in the planar limit.
 * Null where the loop cannot close; throws an Error naming the field for bad input.
 */
export function transmissionAngle(model: SpatialModel, theta2: number, branch: SpatialBranch): number | null {
  const k = kernelOf(model);
  checkFinite('theta2', theta2, 'angle in radians');
  const p = newPoint();
  return k.at(theta2, branchSigma(branch), p) === Closure.Unreachable ? null : p.mu;
}

/** A dead centre: the output at an extreme (omega4 = 0, crank and coupler in one plane with the input axis). */
export interface SpatialDeadCentre {
  theta2: number;
  theta4: number;
  kind: 'min' | 'max';
}

/** The output's travel over one interval of the input's range on one branch. */
export interface OutputSwing {
  /** The input interval (radians). */
  theta2Lo: number;
  theta2Hi: number;
  /** True when the output turns a whole turn over the interval (a crank output). */
  full: boolean;
  /** Least output angle (radians, in (-pi, pi]) and greatest, theta4Max = theta4Min + swing (may pass pi). */
  theta4Min: number;
  theta4Max: number;
  swing: number;
}

/** Output swing, dead centres and the transmission angle's extremes over the input's range on one branch. */
export interface OutputMotion {
  swings: OutputSwing[];
  deadCentres: SpatialDeadCentre[];
  /** Least and greatest transmission angle analogue (radians) over the samples and dead centres; null if none. */
  transmission: { min: number; max: number } | null;
}

/** Default samples per input interval for outputMotion (dead centres between samples are bisected to the double). */
export const MOTION_SAMPLES = 720;

function wrapTo(x: number): number {
  const r = x - TWO_PI * Math.round(x / TWO_PI);
  return r <= -PI ? r + TWO_PI : r;
}

/** theta2 in (lo, hi) where F2 (the sign of omega4 on the branch) changes sign, bisected to the double. */
function bisectF2(k: Kernel, sigma: number, lo: number, hi: number, p: SpatialPoint): number {
  k.at(lo, sigma, p);
  const sLo = Math.sign(p.f2);
  let a = lo;
  let b = hi;
  for (let i = 0; i < 100; i++) {
    const m = a + (b - a) / 2;
    if (m <= a || m >= b) break;
    if (k.at(m, sigma, p) === Closure.Unreachable) break;
    if (Math.sign(p.f2) === sLo) a = m;
    else b = m;
  }
  return Math.abs(a - lo) < Math.abs(b - hi) ? b : a;
}

/**
 * The output's swing per input interval, its dead centres (where F2 = dA/dtheta2 . (B - A) terms vanish, so omega4 = 0)
 * and the transmission angle's extremes on the branch, from `samples` angles per interval (integer 8..1e6) and bisection.
 * Throws an Error naming the field for bad input.
 */
export function outputMotion(model: SpatialModel, branch: SpatialBranch, samples = MOTION_SAMPLES): OutputMotion {
  const k = kernelOf(model);
  const sigma = branchSigma(branch);
  if (!Number.isInteger(samples) || samples < 8 || samples > 1e6) {
    throw new Error(`samples must be an integer from 8 to 1000000, got ${describe(samples)}`);
  }
  const range = k.inputRange();
  const p = newPoint();
  const q = newPoint();
  const swings: OutputSwing[] = [];
  const deadCentres: SpatialDeadCentre[] = [];
  let muMin = Infinity;
  let muMax = -Infinity;
  for (const iv of range.intervals) {
    const lo = range.full ? 0 : iv.lo;
    const hi = range.full ? TWO_PI : iv.hi;
    let first = NaN;
    let prevT4 = NaN;
    let unwrapped = 0;
    let min = Infinity;
    let max = -Infinity;
    let prevT2 = NaN;
    let prevRate = 0;
    for (let i = 0; i <= samples; i++) {
      const t2 = i === samples ? hi : lo + ((hi - lo) * i) / samples;
      if (k.at(t2, sigma, p) === Closure.Unreachable) continue;
      muMin = Math.min(muMin, p.mu);
      muMax = Math.max(muMax, p.mu);
      if (Number.isNaN(first)) {
        first = p.theta4;
        unwrapped = p.theta4;
      } else {
        unwrapped += wrapTo(p.theta4 - prevT4);
      }
      prevT4 = p.theta4;
      min = Math.min(min, unwrapped);
      max = Math.max(max, unwrapped);
      // omega4 / omega2 = -F2 / F4: its sign change between samples brackets a dead centre.
      const rate = p.f4 === 0 ? 0 : -Math.sign(p.f2) * Math.sign(p.f4);
      if (rate !== 0 && prevRate !== 0 && rate !== prevRate) {
        const t = bisectF2(k, sigma, prevT2, t2, q);
        if (k.at(t, sigma, q) !== Closure.Unreachable) {
          const base = unwrapped - wrapTo(p.theta4 - q.theta4);
          min = Math.min(min, base);
          max = Math.max(max, base);
          muMin = Math.min(muMin, q.mu);
          muMax = Math.max(muMax, q.mu);
          deadCentres.push({ theta2: wrapTo(t), theta4: q.theta4, kind: prevRate > 0 ? 'max' : 'min' });
        }
      }
      if (rate !== 0) prevRate = rate;
      prevT2 = t2;
    }
    if (Number.isNaN(first)) continue;
    const full = range.full && Math.abs(unwrapped - first) > PI;
    const theta4Min = full ? -PI : wrapTo(min);
    swings.push({
      theta2Lo: lo,
      theta2Hi: hi,
      full,
      theta4Min: full ? -PI : theta4Min,
      theta4Max: full ? PI : theta4Min + (max - min),
      swing: full ? TWO_PI : max - min,
    });
  }
  return {
    swings,
    deadCentres,
    transmission: muMin <= muMax ? { min: muMin, max: muMax } : null,
  };
}
