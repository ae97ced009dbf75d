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
import { TWO_SUM_MAX_RAD, reduceDifference } from './angles';
import type { AngleParts } from './angles';
import type { Angles, Linkage } from './types';
import { checkFinite, describe, scaleByPow2, validateLinkage } from './validate';

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

function validateInput(input: unknown): asserts input is InputMotion {
  if (typeof input !== 'object' || input === null) {
    throw new Error(`input must be an object with omega2 (rad/s) and alpha2 (rad/s²), got ${describe(input)}`);
  }
  const rec = input as Record<string, unknown>;
  checkFinite('input.omega2', rec.omega2, 'angular velocity in rad/s');
  checkFinite('input.alpha2', rec.alpha2, 'angular acceleration in rad/s²');
}

function validatePose(pose: unknown): asserts pose is Angles {
  if (typeof pose !== 'object' || pose === null) {
    throw new Error(`pose must be an object with theta3 and theta4 (radians), got ${describe(pose)}`);
  }
  const rec = pose as Record<string, unknown>;
  checkFinite('pose.theta3', rec.theta3, 'angle in radians');
  checkFinite('pose.theta4', rec.theta4, 'angle in radians');
}

/** x = m 2^e with m in [1, 2) (x > 0 finite, subnormals included). */
function split(x: number): { m: number; e: number } {
  let e = Math.floor(Math.log2(x));
  let m = scaleByPow2(x, -e);
  // log2 can round across a power of two: one correction step either way.
  if (m >= 2) {
    e += 1;
    m = scaleByPow2(x, -e);
  } else if (m < 1) {
    e -= 1;
    m = scaleByPow2(x, -e);
  }
  return { m, e };
}

/** The exact power of two of |x| (x finite, nonzero): floor(log2 |x|). */
function exponentOf(x: number): number {
  return split(Math.abs(x)).e;
}

// Module-local copies of imports used per point: loaders that turn imports into getters (vite-node)
// would otherwise call a getter on every read (as in sweep.ts).
const SMALL_ANGLE = TWO_SUM_MAX_RAD;
const reduce = reduceDifference;

/** Scratch for reduceDifference. */
const parts: AngleParts = { hi: 0, lo: 0 };

/** Range of the length ratios and input rates the direct formulas take (see ratesInto). */
const DIRECT_RATIO = 2 ** 200;
const DIRECT_OMEGA = 2 ** 200;

/**
 * Per-linkage constants of the rate formulas: length ratios only, also as m 2^e (m in [1, 2)) for
 * ratios and rates past the double range, where r2 / r3 itself can overflow (r2 / r3 > 1e308).
 */
interface RatePlan {
  /** r2 / r3 and r2 / r4. */
  q3: number;
  q4: number;
  /** (r2 / r3) (r4 - r3) / r4: the unequal-links part of omega3 - omega4 (r4 - r3 is exact when they are close). */
  q34: number;
  /** q3 = m3 2^e3, q4 = m4 2^e4, q34 = m34 2^e34, formed without overflow or underflow. */
  m3: number;
  e3: number;
  m4: number;
  e4: number;
  m34: number;
  e34: number;
  /** q3 and q4 within 2^+-200: the direct formulas cannot overflow for a direct input (see ratesInto). */
  direct: boolean;
}

function planRates(l: Linkage): RatePlan {
  const q3 = l.r2 / l.r3;
  const s2 = split(l.r2);
  const s3 = split(l.r3);
  const s4 = split(l.r4);
  // m2 / m3 lies in (1/2, 2): one more exact power of two puts it in [1, 2).
  const r3 = split(s2.m / s3.m);
  const r4 = split(s2.m / s4.m);
  const e3 = s2.e - s3.e + r3.e;
  const e4 = s2.e - s4.e + r4.e;
  // q34 = q3 (r4 - r3) / r4 = -q4 (r3 - r4) / r3: the form whose fraction lies in [0, 1) cannot overflow.
  const q34AsQ3 = l.r4 > l.r3;
  return {
    q3,
    q4: l.r2 / l.r4,
    q34: q3 * ((l.r4 - l.r3) / l.r4),
    m3: r3.m,
    e3,
    m4: r4.m,
    e4,
    m34: q34AsQ3 ? r3.m * ((l.r4 - l.r3) / l.r4) : -r4.m * ((l.r3 - l.r4) / l.r3),
    e34: q34AsQ3 ? e3 : e4,
    direct: Math.max(q3, l.r2 / l.r4) <= DIRECT_RATIO && Math.min(q3, l.r2 / l.r4) >= 1 / DIRECT_RATIO,
  };
}

/** The input motion, and omega2 = w 2^sigma, alpha2 = a 2^(2 sigma) with |w|, |a| < 4 for the scaled path. */
interface MotionPlan {
  omega2: number;
  alpha2: number;
  w: number;
  a: number;
  sigma: number;
  /** omega2 and alpha2 (when nonzero) within 2^+-200 and 2^+-400. */
  direct: boolean;
}

function planMotion(input: InputMotion): MotionPlan {
  const { omega2, alpha2 } = input;
  const w2 = Math.abs(omega2);
  const a2 = Math.abs(alpha2);
  const size = Math.max(w2, Math.sqrt(a2));
  const sigma = size === 0 ? 0 : exponentOf(size);
  const inRange = (x: number, max: number) => x === 0 || (x <= max && x >= 1 / max);
  return {
    omega2,
    alpha2,
    w: scaleByPow2(omega2, -sigma),
    a: scaleByPow2(alpha2, -2 * sigma),
    sigma,
    direct: inRange(w2, DIRECT_OMEGA) && inRange(a2, DIRECT_OMEGA * DIRECT_OMEGA),
  };
}

/**
 * The rates at one pose (see the module comment), written to out[i] of each array; all NaN at a limit
 * position. One flat function with array outputs: it runs per point over whole sweeps.
 * The direct formulas run when the plan and the motion are direct: with ratios and omega2 within 2^+-200,
 * alpha2 within 2^+-400 and 1 / |sin mu| <= 2^50, no product exceeds 2^952 nor (unless the true term is
 * that small) falls below 2^-600. Anything else takes scaledRatesInto, which cannot overflow or underflow
 * before the final result does.
 */
function ratesInto(p: RatePlan, m: MotionPlan, t2: number, t3: number, t4: number, out: SweepRates, i: number): void {
  // a = t2 - t3 and mu = t4 - t3 exactly as hi + lo; the tiny lo shifts sin by cos(hi) lo and cos by
  // -sin(hi) lo. Ordinary angles use TwoSum; past TWO_SUM_MAX_RAD the TwoSum remainder (up to a radian
  // at 1e16) is too large for that first-order correction, so the exact differences are reduced first.
  let aHi: number;
  let aLo: number;
  let muHi: number;
  let muLo: number;
  if (Math.abs(t2) <= SMALL_ANGLE && Math.abs(t3) <= SMALL_ANGLE && Math.abs(t4) <= SMALL_ANGLE) {
    aHi = t2 - t3;
    const ab = aHi - t2;
    aLo = t2 - (aHi - ab) - (t3 + ab);
    muHi = t4 - t3;
    const mb = muHi - t4;
    muLo = t4 - (muHi - mb) - (t3 + mb);
  } else {
    reduce(t2, t3, parts);
    aHi = parts.hi;
    aLo = parts.lo;
    reduce(t4, t3, parts);
    muHi = parts.hi;
    muLo = parts.lo;
  }
  const sa0 = Math.sin(aHi);
  const ca0 = Math.cos(aHi);
  const sa = sa0 + ca0 * aLo;
  const ca = ca0 - sa0 * aLo;
  // Half-angle functions give sin mu and cos mu to full relative accuracy (also where mu is near pi),
  // and sin(mu/2) for omega3 - omega4. A reduced mu differs by 2 pi k, which flips the signs of both
  // sin(mu/2) and cos(mu/2) when k is odd: every formula below uses them in pairs.
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
  // cos(a - mu/2) = cos a cos(mu/2) + sin a sin(mu/2).
  const cx = ca * ch + sa * sh;
  if (!(p.direct && m.direct)) {
    scaledRatesInto(p, m, s, c, sa, ca, sb, cb, sh, cx, out, i);
    return;
  }
  const w2 = m.omega2;
  const a2 = m.alpha2;
  const w2s = w2 / s;
  const w3 = p.q3 * sb * w2s;
  const w4 = p.q4 * sa * w2s;
  const w34 = (p.q34 * sb - 2 * p.q4 * cx * sh) * w2s;
  out.omega3[i] = w3;
  out.omega4[i] = w4;
  out.alpha3[i] = (p.q3 * (a2 * sb + w2 * cb * (w2 - w4)) + c * w3 * w34) / s;
  out.alpha4[i] = (p.q4 * (a2 * sa + w2 * ca * (w2 - w3)) + c * w4 * w34) / s;
}

/**
 * Sum of terms v_k 2^(e_k) as m 2^e: each term is brought to the exponent of the largest before adding,
 * so no term overflows and only terms below 2^-1074 of the largest are lost (as in any double sum).
 */
function sumScaled(v0: number, e0: number, v1: number, e1: number, v2: number, e2: number): { m: number; e: number } {
  let top = -Infinity;
  if (v0 !== 0) top = e0 + exponentOf(v0);
  if (v1 !== 0) top = Math.max(top, e1 + exponentOf(v1));
  if (v2 !== 0) top = Math.max(top, e2 + exponentOf(v2));
  if (top === -Infinity) return { m: 0, e: 0 };
  return { m: scaleByPow2(v0, e0 - top) + scaleByPow2(v1, e1 - top) + scaleByPow2(v2, e2 - top), e: top };
}

/**
 * The direct formulas of ratesInto with every length ratio and input rate split into m 2^e, so that no
 * intermediate overflows or underflows where the result does not: omega2 = 1e160 with r2 / r3 = 1e-20
 * (alpha3 near 1e300, while omega2^2 overflows), r2 / r3 beyond 1e308, omega2 = 1e300 at sin mu = 1e-10.
 * Mantissas stay below about 2^160 and the powers of two are applied once, at the end (scaleByPow2).
 */
function scaledRatesInto(
  p: RatePlan,
  m: MotionPlan,
  s: number,
  c: number,
  sa: number,
  ca: number,
  sb: number,
  cb: number,
  sh: number,
  cx: number,
  out: SweepRates,
  i: number,
): void {
  const { w, a, sigma } = m;
  const ws = w / s;
  // omega3 = W3 2^(e3 + sigma), omega4 = W4 2^(e4 + sigma).
  const W3 = p.m3 * sb * ws;
  const W4 = p.m4 * sa * ws;
  // omega3 - omega4 = X (w / s) 2^(eX + sigma), X 2^eX = q34 sin b - 2 q4 cos(a - mu/2) sin(mu/2).
  const x = sumScaled(p.m34 * sb, p.e34, -2 * p.m4 * cx * sh, p.e4, 0, 0);
  const W34 = x.m * ws;
  // alpha3 = 2^(2 sigma + e3) / s [m3 (a sin b + w^2 cos b) - m3 w cos b W4 2^e4 + cos mu W3 W34 2^eX].
  const t3 = sumScaled(p.m3 * (a * sb + w * w * cb), 0, -p.m3 * w * cb * W4, p.e4, c * W3 * W34, x.e);
  const t4 = sumScaled(p.m4 * (a * sa + w * w * ca), 0, -p.m4 * w * ca * W3, p.e3, c * W4 * W34, x.e);
  out.omega3[i] = scaleByPow2(W3, p.e3 + sigma);
  out.omega4[i] = scaleByPow2(W4, p.e4 + sigma);
  out.alpha3[i] = scaleByPow2(t3.m / s, 2 * sigma + p.e3 + t3.e);
  out.alpha4[i] = scaleByPow2(t4.m / s, 2 * sigma + p.e4 + t4.e);
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
  checkFinite('theta2', theta2, 'angle in radians');
  validatePose(pose);
  validateInput(input);
  ratesInto(planRates(l), planMotion(input), theta2, pose.theta3, pose.theta4, single, 0);
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
  checkFinite('theta2', theta2, 'angle in radians');
  validatePose(pose);
  validateInput(input);
  checkFinite('pDist', pDist, 'length');
  checkFinite('pAngle', pAngle, 'angle in radians');
  const { omega2: w2, alpha2: a2 } = input;
  ratesInto(planRates(l), planMotion(input), theta2, pose.theta3, pose.theta4, single, 0);
  const w3 = single.omega3[0];
  const a3 = single.alpha3[0];
  // Direction of A -> P is phi = theta3 + pAngle, summed exactly as hi + lo (TwoSum) for full accuracy,
  // or reduced exactly where lo is too large for a first-order correction (huge angles).
  let hi = pose.theta3 + pAngle;
  let lo: number;
  if (Math.abs(pose.theta3) <= TWO_SUM_MAX_RAD && Math.abs(pAngle) <= TWO_SUM_MAX_RAD) {
    const bb = hi - pose.theta3;
    lo = pose.theta3 - (hi - bb) + (pAngle - bb);
  } else {
    reduceDifference(pose.theta3, -pAngle, parts);
    hi = parts.hi;
    lo = parts.lo;
  }
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
    // omega^2 times a length as (omega length) omega: omega^2 alone can overflow where the product does not.
    ax: -a2 * ay0 - w2 * ax0 * w2 - a3 * uy - w3 * ux * w3,
    ay: a2 * ax0 - w2 * ay0 * w2 + a3 * ux - w3 * uy * w3,
  };
}

/** Throws unless v is an array or typed array (or array-like) of numbers; NaN marks a point not solved. */
function checkAngleArray(name: string, v: unknown): asserts v is ArrayLike<number> {
  if (v instanceof Float64Array || v instanceof Float32Array) return;
  const len = typeof v === 'object' && v !== null ? (v as { length?: unknown }).length : undefined;
  if (typeof len !== 'number' || !Number.isInteger(len) || len < 0) {
    throw new Error(`${name} must be an array or Float64Array of angles in radians, got ${describe(v)}`);
  }
  const a = v as ArrayLike<unknown>;
  for (let i = 0; i < len; i++) {
    if (typeof a[i] !== 'number') throw new Error(`${name}[${i}] must be an angle in radians, got ${describe(a[i])}`);
  }
}

/** The error for a point marked ok whose angle is not finite. */
function badPoint(name: string, i: number, v: number): Error {
  return new Error(`${name}[${i}] must be a finite angle in radians where ok(${i}) is true, got ${describe(v)}`);
}

/**
 * Rates along a sweep: theta2, theta3, theta4 in radians (arrays of numbers of equal length), ok(i) says
 * which points hold a solved pose (their angles must be finite; elsewhere NaN is fine). Returns
 * Float64Arrays (rad/s, rad/s²), NaN where ok(i) is false or the pose is a limit position; each value
 * equals linkRates at that point. Throws an Error naming the argument and value for a bad linkage,
 * array, length, ok or input, and for a non-finite angle at a point marked ok.
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
  checkAngleArray('theta2', theta2);
  checkAngleArray('theta3', theta3);
  checkAngleArray('theta4', theta4);
  if (typeof ok !== 'function') throw new Error(`ok must be a function of the point index, got ${describe(ok)}`);
  validateInput(input);
  const n = theta2.length;
  if (theta3.length !== n) throw new Error(`theta3 must have the length of theta2 (${n}), got ${theta3.length}`);
  if (theta4.length !== n) throw new Error(`theta4 must have the length of theta2 (${n}), got ${theta4.length}`);
  const plan = planRates(l);
  const motion = planMotion(input);
  const out = allocateRates(n);
  for (let i = 0; i < n; i++) {
    if (ok(i)) {
      const t2 = theta2[i];
      const t3 = theta3[i];
      const t4 = theta4[i];
      // x - x is 0 exactly for finite x (NaN for NaN and infinities): one cheap test per angle.
      if (t2 - t2 !== 0) throw badPoint('theta2', i, t2);
      if (t3 - t3 !== 0) throw badPoint('theta3', i, t3);
      if (t4 - t4 !== 0) throw badPoint('theta4', i, t4);
      ratesInto(plan, motion, t2, t3, t4, out, i);
    } else out.omega3[i] = out.omega4[i] = out.alpha3[i] = out.alpha4[i] = NaN;
  }
  return out;
}
