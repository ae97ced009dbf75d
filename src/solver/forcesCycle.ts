/**
 * Cycle quantities of the input torque: mean, RMS and peak, the energy fluctuation and the flywheel
 * inertia for a coefficient of speed fluctuation (Norton, Design of Machinery, chapter 11: flywheels).
 *
 * The mean and RMS are trapezoid integrals over the grid: on a uniform grid over a turn of a smooth
 * periodic torque they are spectrally accurate (the trapezoid rule's error falls faster than any power of
 * the step). The running energy E(theta2) = ∫ (T - mean) dtheta2 is exact for the piecewise-linear
 * interpolant of the samples: integrated interval by interval, with its extremes inside an interval (where
 * the interpolant crosses the mean) taken at the crossing. Against the true torque E is off by at most
 * about (h^2 / 12) times the integral of |T''| up to theta2, O(h^2) in the step h (docs/forces.md has the
 * measured figures).
 */
import { TWO_PI } from './angles';
import { branchSign } from './closedForm';
import { classify } from './classify';
import type { LinkInertias, Loads, SweepForces } from './forces';
import { sweepForces } from './forces';
import type { InputMotion } from './rates';
import { LIMIT_SIN_MU } from './rates';
import { STATUS_CODE } from './pointStatus';
import { sweep } from './sweep';
import type { Branch, Linkage } from './types';
import { checkFinite, checkObject, describe } from './validate';

/** Why a cycle's statistics are missing: the grid is not one full turn, or a sample is not finite. */
export type TorqueCycleStatus = 'ok' | 'not-a-full-turn' | 'missing-points' | 'overflow';

/** Input torque over one crank turn (N·m), its energy fluctuation (J) and flywheel inertia (kg·m²); NaN unless ok. */
export interface TorqueCycleStats {
  status: TorqueCycleStatus;
  mean: number;
  rms: number;
  min: number;
  max: number;
  /** Largest |T|. */
  peak: number;
  /** ΔE = max - min of ∫ (T - mean) dtheta2 over the turn. */
  energyFluctuation: number;
  /** ΔE / (k omega2^2) for the coefficient of speed fluctuation k; NaN when omega2 is 0. */
  flywheelInertia: number;
}

/** A turn with its samples closing within this many radians of 2 pi counts as full (a grid built in degrees rounds). */
const FULL_TURN_SLACK = 1e-9;

function missing(status: TorqueCycleStatus): TorqueCycleStats {
  const x = NaN;
  return { status, mean: x, rms: x, min: x, max: x, peak: x, energyFluctuation: x, flywheelInertia: x };
}

/** Throws unless v is an array or typed array of numbers, of length n when n is given. */
function checkNumbers(name: string, v: unknown, n?: number): asserts v is ArrayLike<number> {
  const len = typeof v === 'object' && v !== null ? (v as { length?: unknown }).length : undefined;
  if (typeof len !== 'number' || !Number.isInteger(len) || len < 0) {
    throw new Error(`${name} must be an array or Float64Array of numbers, got ${describe(v)}`);
  }
  if (n !== undefined && len !== n) throw new Error(`${name} must have the length of theta2 (${n}), got ${len}`);
  const a = v as ArrayLike<unknown>;
  for (let i = 0; i < len; i++) {
    if (typeof a[i] !== 'number') throw new Error(`${name}[${i}] must be a number, got ${describe(a[i])}`);
  }
}

/** 'ok' when theta2 runs strictly one way through exactly one turn and every torque is finite. */
function cycleStatus(theta2: ArrayLike<number>, torque: ArrayLike<number>): TorqueCycleStatus {
  const n = theta2.length;
  if (n < 3) return 'not-a-full-turn';
  const dir = Math.sign(theta2[n - 1] - theta2[0]);
  if (!(Math.abs(Math.abs(theta2[n - 1] - theta2[0]) - TWO_PI) <= FULL_TURN_SLACK)) return 'not-a-full-turn';
  for (let i = 0; i + 1 < n; i++) {
    if (!(dir * (theta2[i + 1] - theta2[i]) > 0)) return 'not-a-full-turn';
  }
  for (let i = 0; i < n; i++) if (!Number.isFinite(torque[i])) return 'missing-points';
  return 'ok';
}

/**
 * Mean, RMS, min, max and peak of the input torque (N·m) over one turn sampled at theta2 (radians, strictly
 * monotone from theta0 to theta0 ± 2 pi inclusive), the energy fluctuation ΔE (J) and the flywheel inertia
 * ΔE / (k omega2^2) (kg·m²) for the coefficient of speed fluctuation k (> 0) at mean speed omega2 (rad/s).
 * A grid that is not one turn, or a torque that is not finite (a limit position, an unreachable point),
 * gives NaN statistics with the reason in status. Throws an Error naming the argument for bad input.
 */
export function torqueCycleStats(
  theta2: ArrayLike<number>,
  torque: ArrayLike<number>,
  omega2: number,
  k: number,
): TorqueCycleStats {
  checkNumbers('theta2', theta2);
  checkNumbers('torque', torque, theta2.length);
  checkFinite('omega2', omega2, 'angular velocity in rad/s');
  if (typeof k !== 'number' || !Number.isFinite(k) || !(k > 0)) {
    throw new Error(`k must be a positive finite coefficient of speed fluctuation, got ${describe(k)}`);
  }
  const status = cycleStatus(theta2, torque);
  if (status !== 'ok') return missing(status);
  const n = theta2.length;
  let min = Infinity;
  let max = -Infinity;
  for (let i = 0; i < n; i++) {
    min = Math.min(min, torque[i]);
    max = Math.max(max, torque[i]);
  }
  const peak = Math.max(-min, max);
  // Scale before squaring: T / peak is at most 1, so neither the sum nor its square root overflows.
  const scale = peak > 0 ? peak : 1;
  let sum = 0;
  let sumSq = 0;
  for (let i = 0; i + 1 < n; i++) {
    const h = theta2[i + 1] - theta2[i];
    const u = torque[i] / scale;
    const v = torque[i + 1] / scale;
    sum += 0.5 * h * (u + v);
    sumSq += 0.5 * h * (u * u + v * v);
  }
  const span = theta2[n - 1] - theta2[0];
  const mean = (sum / span) * scale;
  const rms = Math.sqrt(sumSq / span) * scale;
  // ΔE is found on the scaled torque too (T − mean can overflow where T is near the double range), then scaled.
  const swing = energySwing(theta2, torque, mean / scale, scale);
  const energyFluctuation = swing * scale;
  // A statistic past the double range (ΔE of torques near 1e308 over a turn) is an overflow, said as such.
  if (![mean, rms, energyFluctuation].every(Number.isFinite)) return missing('overflow');
  const w = Math.abs(omega2);
  // Divided while scaled when ΔE / k alone passes the doubles but the inertia itself may not.
  let flywheelInertia = w > 0 ? energyFluctuation / k / w / w : NaN;
  if (w > 0 && !Number.isFinite(flywheelInertia)) flywheelInertia = (swing / k / w / w) * scale;
  if (w > 0 && !Number.isFinite(flywheelInertia)) return missing('overflow');
  return { status, mean, rms, min, max, peak, energyFluctuation, flywheelInertia };
}

/**
 * max - min of E(theta) = ∫ (T/scale - mean) dtheta for the linear interpolant of the samples (J / scale; mean is
 * the scaled mean). Inside an
 * interval where T - mean changes sign, E has an extreme at the crossing: that value is included too.
 */
function energySwing(theta2: ArrayLike<number>, torque: ArrayLike<number>, mean: number, scale: number): number {
  let e = 0;
  let lo = 0;
  let hi = 0;
  for (let i = 0; i + 1 < theta2.length; i++) {
    const h = theta2[i + 1] - theta2[i];
    const d0 = torque[i] / scale - mean;
    const d1 = torque[i + 1] / scale - mean;
    if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0)) {
      // The interpolant crosses the mean at the fraction t of the interval; E there is e + d0 t h / 2.
      const t = d0 / (d0 - d1);
      const at = e + 0.5 * d0 * t * h;
      lo = Math.min(lo, at);
      hi = Math.max(hi, at);
    }
    e += 0.5 * h * (d0 + d1);
    lo = Math.min(lo, e);
    hi = Math.max(hi, e);
  }
  return hi - lo;
}

/** Why forceCycle has no statistics: the crank cannot turn, or the turn passes a limit position. */
export type ForceCycleStatus = 'ok' | 'crank-does-not-turn' | 'limit-position' | 'overflow';

/** Options of forceCycle. */
export interface ForceCycleOptions {
  /** Samples per turn, an integer from 3 to 1e7 (default 360): the grid has points + 1 angles, 0 to 2 pi. */
  points?: number;
  /** Coefficient of speed fluctuation, > 0 (default 0.05). */
  k?: number;
}

/** One turn of the crank: the grid and pose (radians), the forces over it and the torque's statistics. */
export interface ForceCycle {
  status: ForceCycleStatus;
  theta2: Float64Array;
  theta3: Float64Array;
  theta4: Float64Array;
  forces: SweepForces;
  stats: TorqueCycleStats;
}

/** Default samples per turn and coefficient of speed fluctuation of forceCycle. */
export const DEFAULT_CYCLE_POINTS = 360;
export const DEFAULT_SPEED_FLUCTUATION = 0.05;

function checkCycleOptions(opts: unknown): { points: number; k: number } {
  checkObject('opts', opts);
  const points = opts.points ?? DEFAULT_CYCLE_POINTS;
  const k = opts.k ?? DEFAULT_SPEED_FLUCTUATION;
  if (typeof points !== 'number' || !Number.isInteger(points) || points < 3 || points > 1e7) {
    throw new Error(`opts.points must be an integer from 3 to 1e7, got ${describe(points)}`);
  }
  if (typeof k !== 'number' || !Number.isFinite(k) || !(k > 0)) {
    throw new Error(`opts.k must be a positive finite coefficient of speed fluctuation, got ${describe(k)}`);
  }
  return { points, k };
}

/**
 * One full turn of the crank (theta2 = 2 pi i / points, i = 0..points) on a branch, solved by the
 * closed form, with sweepForces and torqueCycleStats at the input's omega2. Only a crank that turns
 * fully has a cycle: otherwise status is 'crank-does-not-turn'; a change-point linkage, or a turn whose
 * torque is not finite somewhere, is 'limit-position'; the statistics are NaN then, the arrays filled
 * where the pose exists. Throws an Error naming the field for bad input (as sweepForces, and opts).
 */
export function forceCycle(
  l: Linkage,
  branch: Branch,
  input: InputMotion,
  inertia: LinkInertias,
  loads: Loads,
  opts: ForceCycleOptions = {},
): ForceCycle {
  const c = classify(l);
  branchSign(branch);
  const { points, k } = checkCycleOptions(opts);
  const grid = new Float64Array(points + 1);
  for (let i = 0; i <= points; i++) grid[i] = (TWO_PI * i) / points;
  const r = sweep(l, grid, { branch });
  const codes = r.statusCodes;
  const ok = STATUS_CODE.ok;
  const forces = sweepForces(l, r.theta2, r.theta3, r.theta4, (i) => codes[i] === ok, input, inertia, loads);
  let status: ForceCycleStatus = 'ok';
  if (!c.inputIsCrank) status = 'crank-does-not-turn';
  else if (c.type === 'change-point') status = 'limit-position';
  const stats = torqueCycleStats(grid, forces.torque, input.omega2, k);
  if (status === 'ok' && stats.status !== 'ok') {
    // A torque that is not finite at a solved pose clear of a limit (|sin μ| above LIMIT_SIN_MU) has overflowed.
    let overflow = stats.status === 'overflow';
    for (let i = 0; i <= points && !overflow; i++) {
      const clear = codes[i] === ok && Math.abs(Math.sin(r.theta4[i] - r.theta3[i])) > LIMIT_SIN_MU;
      if (clear && !Number.isFinite(forces.torque[i])) overflow = true;
    }
    status = overflow ? 'overflow' : 'limit-position';
  }
  const { theta2, theta3, theta4 } = r;
  const kept = status === 'ok' ? stats : missing(stats.status === 'ok' ? 'missing-points' : stats.status);
  return { status, theta2, theta3, theta4, forces, stats: kept };
}
