/**
 * Velocity and acceleration analysis of the four-bar at a solved pose.
 *
 * Differentiating the loop r2 e^{i t2} + r3 e^{i t3} - r4 e^{i t4} - r1 = 0 once and twice in time and
 * projecting on the directions of the coupler and the rocker (the complex-number loop method of Norton,
 * Design of Machinery, chapters 6 and 7) gives, with mu = t4 - t3, s = sin mu, c = cos mu, a = t2 - t3
 * and b = t2 - t4:
 *
 *   omega3 = omega2 (r2 / r3) sin b / s
 *   omega4 = omega2 (r2 / r4) sin a / s
 *   alpha3 = [ (r2 / r3) (alpha2 sin b + omega2 cos b (omega2 - omega4)) + c omega3 (omega3 - omega4) ] / s
 *   alpha4 = [ (r2 / r4) (alpha2 sin a + omega2 cos a (omega2 - omega3)) + c omega4 (omega3 - omega4) ] / s
 *
 * The acceleration numerators are the textbook ones (r4 omega4^2 - r3 omega3^2 c - ...) with the
 * velocity relations r3 omega3 - r4 omega4 c = -r2 omega2 cos a and r4 omega4 - r3 omega3 c = r2 omega2 cos b
 * substituted: the textbook form adds two terms of size 1 / s^2 whose difference can be far smaller
 * (at a toggle with mu -> 0 it is smaller by about |r4 - r3| / r + |mu|), and loses it to rounding. Here
 * the large factors meet only in the product omega * (omega3 - omega4), and the relative angular
 * velocity of coupler and rocker is formed without cancellation:
 *
 *   omega3 - omega4 = (omega2 / s) [ (r2 / r3) ((r4 - r3) / r4) sin b - 2 (r2 / r4) cos(a - mu/2) sin(mu/2) ]
 *
 * (r4 sin b - r3 sin a = (r4 - r3) sin b + r3 (sin b - sin a), and sin b - sin a = -2 cos(a - mu/2) sin(mu/2)).
 * Only length ratios appear, so links of any scale neither overflow nor underflow.
 *
 * The differences a and mu are formed exactly (TwoSum) and their sines and cosines corrected by the
 * rounding error of the difference, so sin mu keeps full relative accuracy even where mu is close to pi
 * (b = a - mu then follows from the difference formula: its few eps of absolute error only ever multiply
 * bounded terms). A pose's angles are taken as exact, and the rates are exact to rounding for them:
 * no check that the pose closes the loop is made. Velocities then carry about
 * eps |omega2| (r2 / r) / |sin mu| of error, accelerations one more factor 1 / |sin mu| where the
 * relative angular velocity omega3 - omega4 is bounded (see tests/oracle/rates.ts for the bounds tested).
 */
import type { Angles, Linkage } from './types';
import { validateLinkage } from './validate';

/** Input crank motion: angular velocity (rad/s) and acceleration (rad/s²), counter-clockwise positive. */
export interface InputMotion {
  omega2: number;
  alpha2: number;
}

/** Coupler and rocker rates at a pose: omega in rad/s and alpha in rad/s², counter-clockwise positive. */
export interface LinkRates {
  omega3: number;
  omega4: number;
  alpha3: number;
  alpha4: number;
}

/** A coupler point's position (length unit), velocity (length/s) and acceleration (length/s²). */
export interface PointMotion {
  x: number;
  y: number;
  vx: number;
  vy: number;
  ax: number;
  ay: number;
}

/** Rates of a whole sweep (rad/s, rad/s²); NaN where the point is not ok or sits at a limit position. */
export interface SweepRates {
  omega3: Float64Array;
  omega4: Float64Array;
  alpha3: Float64Array;
  alpha4: Float64Array;
}

/**
 * |sin mu| at or below which a pose counts as a limit position (coupler and rocker collinear): the
 * velocity equations are singular there and every rate is NaN. Each angle of a pose carries up to
 * half an ulp of pi (1.1e-16 rad) of rounding, so a closed-form limit pose (flat within rounding)
 * has |sin mu| <= 2 eps; 4 eps covers it, and anything larger is answered exactly for the given angles.
 */
export const LIMIT_SIN_MU = 4 * Number.EPSILON;

function show(value: unknown): string {
  if (typeof value === 'number') return String(value);
  if (typeof value === 'string') return JSON.stringify(value);
  if (value === undefined) return 'undefined (missing)';
  try {
    return JSON.stringify(value) ?? String(value);
  } catch {
    return String(value);
  }
}

function requireFinite(value: unknown, field: string, what: string): asserts value is number {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new Error(`${field} must be a finite ${what}, got ${show(value)}`);
  }
}

function validateInput(input: unknown): asserts input is InputMotion {
  if (typeof input !== 'object' || input === null) {
    throw new Error(`input must be an object with omega2 (rad/s) and alpha2 (rad/s²), got ${show(input)}`);
  }
  const rec = input as Record<string, unknown>;
  requireFinite(rec.omega2, 'input.omega2', 'angular velocity in rad/s');
  requireFinite(rec.alpha2, 'input.alpha2', 'angular acceleration in rad/s²');
}

function validatePose(pose: unknown): asserts pose is Angles {
  if (typeof pose !== 'object' || pose === null) {
    throw new Error(`pose must be an object with theta3 and theta4 (radians), got ${show(pose)}`);
  }
  const rec = pose as Record<string, unknown>;
  requireFinite(rec.theta3, 'pose.theta3', 'angle in radians');
  requireFinite(rec.theta4, 'pose.theta4', 'angle in radians');
}

/** Per-linkage constants of the rate formulas: length ratios only. */
interface RatePlan {
  /** r2 / r3 and r2 / r4. */
  q3: number;
  q4: number;
  /** (r2 / r3) (r4 - r3) / r4: the unequal-links part of omega3 - omega4 (r4 - r3 is exact when they are close). */
  q34: number;
}

function planRates(l: Linkage): RatePlan {
  const q3 = l.r2 / l.r3;
  return { q3, q4: l.r2 / l.r4, q34: q3 * ((l.r4 - l.r3) / l.r4) };
}

/**
 * The rates at one pose (see the module comment), written to out[i] of each array; all NaN at a limit
 * position. One flat function with array outputs: it runs per point over whole sweeps.
 */
function ratesInto(
  p: RatePlan,
  t2: number,
  t3: number,
  t4: number,
  w2: number,
  a2: number,
  out: SweepRates,
  i: number,
): void {
  // a = t2 - t3 exactly as aHi + aLo (TwoSum); the tiny aLo shifts sin by cos(aHi) aLo and cos by -sin(aHi) aLo.
  const aHi = t2 - t3;
  const ab = aHi - t2;
  const aLo = t2 - (aHi - ab) - (t3 + ab);
  const sa0 = Math.sin(aHi);
  const ca0 = Math.cos(aHi);
  const sa = sa0 + ca0 * aLo;
  const ca = ca0 - sa0 * aLo;
  // mu = t4 - t3 the same way; half-angle functions give sin mu and cos mu to full relative accuracy
  // (also where mu is near pi), and sin(mu/2) for omega3 - omega4.
  const muHi = t4 - t3;
  const mb = muHi - t4;
  const muLo = t4 - (muHi - mb) - (t3 + mb);
  const sh0 = Math.sin(0.5 * muHi);
  const ch0 = Math.cos(0.5 * muHi);
  const sh = sh0 + 0.5 * ch0 * muLo;
  const ch = ch0 - 0.5 * sh0 * muLo;
  const s = 2 * sh * ch;
  if (!(Math.abs(s) > LIMIT_SIN_MU)) {
    out.omega3[i] = out.omega4[i] = out.alpha3[i] = out.alpha4[i] = NaN;
    return;
  }
  const c = (ch - sh) * (ch + sh);
  // b = t2 - t4 = a - mu. Its sine and cosine only ever multiply bounded terms, so the few eps of
  // absolute error of the angle-difference formula stay within the bounds above.
  const sb = sa * c - ca * s;
  const cb = ca * c + sa * s;
  const w2s = w2 / s;
  const w3 = p.q3 * sb * w2s;
  const w4 = p.q4 * sa * w2s;
  // cos(a - mu/2) = cos a cos(mu/2) + sin a sin(mu/2).
  const w34 = (p.q34 * sb - 2 * p.q4 * (ca * ch + sa * sh) * sh) * w2s;
  out.omega3[i] = w3;
  out.omega4[i] = w4;
  out.alpha3[i] = (p.q3 * (a2 * sb + w2 * cb * (w2 - w4)) + c * w3 * w34) / s;
  out.alpha4[i] = (p.q4 * (a2 * sa + w2 * ca * (w2 - w3)) + c * w4 * w34) / s;
}

function allocateRates(n: number): SweepRates {
  return {
    omega3: new Float64Array(n),
    omega4: new Float64Array(n),
    alpha3: new Float64Array(n),
    alpha4: new Float64Array(n),
  };
}

/** One-point scratch for linkRates and couplerPointMotion. */
const single = allocateRates(1);

/**
 * Coupler and rocker angular velocities (rad/s) and accelerations (rad/s²) at theta2 (radians) and the
 * solved pose, for the input crank motion. The pose's angles are taken as exact. At a limit position
 * (|sin mu| <= LIMIT_SIN_MU: coupler and rocker collinear) the rates are unbounded and undetermined, and
 * all four are NaN. Throws an Error naming the field for a bad linkage, theta2, pose or input.
 */
export function linkRates(l: Linkage, theta2: number, pose: Angles, input: InputMotion): LinkRates {
  validateLinkage(l);
  requireFinite(theta2, 'theta2', 'angle in radians');
  validatePose(pose);
  validateInput(input);
  ratesInto(planRates(l), theta2, pose.theta3, pose.theta4, input.omega2, input.alpha2, single, 0);
  return { omega3: single.omega3[0], omega4: single.omega4[0], alpha3: single.alpha3[0], alpha4: single.alpha4[0] };
}

/**
 * Coupler point P (pDist from A in the length unit, pAngle radians counter-clockwise from the line AB):
 * position, velocity (length/s) and acceleration (length/s²) at theta2 and the solved pose. A negative
 * pDist points the other way along the same line. At a limit position x and y are finite and the
 * velocity and acceleration are NaN. Throws an Error naming the field for bad input.
 */
export function couplerPointMotion(
  l: Linkage,
  theta2: number,
  pose: Angles,
  input: InputMotion,
  pDist: number,
  pAngle: number,
): PointMotion {
  validateLinkage(l);
  requireFinite(theta2, 'theta2', 'angle in radians');
  validatePose(pose);
  validateInput(input);
  requireFinite(pDist, 'pDist', 'length');
  requireFinite(pAngle, 'pAngle', 'angle in radians');
  const { omega2: w2, alpha2: a2 } = input;
  ratesInto(planRates(l), theta2, pose.theta3, pose.theta4, w2, a2, single, 0);
  const w3 = single.omega3[0];
  const a3 = single.alpha3[0];
  // Direction of A -> P is phi = theta3 + pAngle, summed exactly as hi + lo (TwoSum) for full accuracy.
  const hi = pose.theta3 + pAngle;
  const bb = hi - pose.theta3;
  const lo = pose.theta3 - (hi - bb) + (pAngle - bb);
  const sp = Math.sin(hi);
  const cp = Math.cos(hi);
  const ux = pDist * (cp - sp * lo);
  const uy = pDist * (sp + cp * lo);
  const c2 = Math.cos(theta2);
  const s2 = Math.sin(theta2);
  const ax0 = l.r2 * c2;
  const ay0 = l.r2 * s2;
  // v_P = v_A + omega3 k x AP; a_P = a_A + alpha3 k x AP - omega3^2 AP, with a_A = alpha2 k x OA - omega2^2 OA.
  return {
    x: ax0 + ux,
    y: ay0 + uy,
    vx: -w2 * ay0 - w3 * uy,
    vy: w2 * ax0 + w3 * ux,
    ax: -a2 * ay0 - w2 * w2 * ax0 - a3 * uy - w3 * w3 * ux,
    ay: a2 * ax0 - w2 * w2 * ay0 + a3 * ux - w3 * w3 * uy,
  };
}

/**
 * Rates along a sweep: theta2, theta3, theta4 in radians (equal lengths), ok(i) says which points hold a
 * solved pose. Returns Float64Arrays (rad/s, rad/s²), NaN where ok(i) is false or the pose is a limit
 * position; each value equals linkRates at that point. Throws an Error naming the field for a bad
 * linkage, input or array length.
 */
export function sweepRates(
  l: Linkage,
  theta2: ArrayLike<number>,
  theta3: ArrayLike<number>,
  theta4: ArrayLike<number>,
  ok: (i: number) => boolean,
  input: InputMotion,
): SweepRates {
  validateLinkage(l);
  validateInput(input);
  const n = theta2.length;
  if (theta3.length !== n) throw new Error(`theta3 must have the length of theta2 (${n}), got ${theta3.length}`);
  if (theta4.length !== n) throw new Error(`theta4 must have the length of theta2 (${n}), got ${theta4.length}`);
  const plan = planRates(l);
  const { omega2: w2, alpha2: a2 } = input;
  const out = allocateRates(n);
  for (let i = 0; i < n; i++) {
    if (ok(i)) ratesInto(plan, theta2[i], theta3[i], theta4[i], w2, a2, out, i);
    else out.omega3[i] = out.omega4[i] = out.alpha3[i] = out.alpha4[i] = NaN;
  }
  return out;
}
