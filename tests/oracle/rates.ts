/**
 * High-precision oracles for velocity and acceleration analysis, and the tolerances derived from
 * conditioning. Nothing here imports src: the first oracle solves the same equations as the solver in
 * another form (Cartesian vectors, Cramer's rule), the second uses no velocity equations at all.
 *
 * 1. referenceRatesAtPose: the differentiated loop equations as a 2x2 linear system in Cartesian
 *    vectors, solved by Cramer's rule at 60 digits, with the given double angles taken as exact. This
 *    is what "exact to rounding for the given pose" means, and what the tight tolerances test.
 * 2. referenceMotion: no velocity equations at all. The position problem is solved at 80 digits (more
 *    for a tiny crank, see differentiator) with the law-of-cosines construction of reference.ts at
 *    theta2 - h, theta2 and theta2 + h with h = 1e-26, and the angles and the coupler point are
 *    differentiated by central differences:
 *    theta' = (u x u') / r^2 and theta'' = (u x u'') / r^2 for the link vector u of length r (no atan2
 *    branch cuts), then d/dt = omega2 d/dtheta2 and d2/dt2 = omega2^2 d2/dtheta2^2 + alpha2 d/dtheta2.
 *    Truncation is (h / d)^2 relative for a distance d (in theta2) to a limit, rounding 1e-80 / h^2 =
 *    1e-28: both far below double precision for d >= 1e-16, i.e. |sin mu| >= about 1e-8 (closer to a
 *    limit, use referenceRatesAtPose).
 *
 * Conventions as in reference.ts: O2 at the origin, O4 at (r1, 0), angles counter-clockwise from the
 * ground, sigma = +1 open (sin(theta4 - theta3) > 0), rates counter-clockwise positive.
 */
import Decimal from 'decimal.js';
import { reducedAngleDigits } from './reference';
import type { LinkLengths, Sigma } from './reference';
import { EPS, K } from './tolerance';

/** Input crank motion (rad/s, rad/s²), structural copy of the solver's InputMotion. */
export interface InputRates {
  omega2: number;
  alpha2: number;
}

/** Coupler and rocker rates (rad/s, rad/s²). */
export interface ReferenceRates {
  omega3: number;
  omega4: number;
  alpha3: number;
  alpha4: number;
}

/** Position (length), velocity (length/s) and acceleration (length/s²) of a point. */
export interface ReferencePointMotion {
  x: number;
  y: number;
  vx: number;
  vy: number;
  ax: number;
  ay: number;
}

/** Rates at a given pose, with the facts tolerances are derived from. */
export interface ReferenceRatesAtPose extends ReferenceRates {
  /** sin(theta4 - theta3) and cos(theta4 - theta3) of the given angles, exactly. */
  sinMu: number;
  cosMu: number;
}

/** True motion at theta2 on a branch: rates, the coupler point's motion and the rounded pose. */
export interface ReferenceMotion extends ReferenceRates {
  /** The pose in double (within POSE_ROUNDING), and sin, cos of theta4 - theta3 of the true pose. */
  theta3: number;
  theta4: number;
  sinMu: number;
  cosMu: number;
  point: ReferencePointMotion;
}

const D60 = Decimal.clone({ precision: 60, rounding: Decimal.ROUND_HALF_EVEN, minE: -9e15, maxE: 9e15 });
type Dec = Decimal;
type DecCtor = typeof D60;

/** The exact value of a finite double in the given Decimal precision (mantissa * 2^exponent). */
function exactIn(Dk: DecCtor, x: number, field: string): Dec {
  if (!Number.isFinite(x)) throw new Error(`oracle needs a finite ${field}, got ${x}`);
  if (x === 0) return new Dk(0);
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const bits = view.getBigUint64(0);
  const sign = bits >> 63n ? -1 : 1;
  const expBits = Number((bits >> 52n) & 0x7ffn);
  const frac = bits & 0xfffffffffffffn;
  const mantissa = expBits === 0 ? frac : frac | (1n << 52n);
  const exponent = (expBits === 0 ? 1 : expBits) - 1075;
  return new Dk(mantissa.toString()).times(new Dk(2).pow(exponent)).times(sign);
}

/** An angle in the given Decimal precision: the exact double reduced modulo 2 pi (reference.ts reducedAngleDigits). */
function angleIn(Dk: DecCtor, x: number, field: string): Dec {
  if (!Number.isFinite(x)) throw new Error(`oracle needs a finite ${field}, got ${x}`);
  return new Dk(reducedAngleDigits(x));
}

interface V {
  x: Dec;
  y: Dec;
}
const cross = (a: V, b: V): Dec => a.x.times(b.y).minus(a.y.times(b.x));

/** The rates at a pose in a Decimal context, unrounded (see referenceRatesAtPose). */
interface ExactRatesAtPose {
  omega3: Dec;
  omega4: Dec;
  alpha3: Dec;
  alpha4: Dec;
  sinMu: Dec;
  cosMu: Dec;
}

function ratesAtPoseIn(
  D: DecCtor,
  l: LinkLengths,
  theta2: number,
  pose: { theta3: number; theta4: number },
  input: InputRates,
): ExactRatesAtPose {
  const ex = (x: number, f: string) => exactIn(D, x, f);
  const [r2, r3, r4] = [ex(l.r2, 'r2'), ex(l.r3, 'r3'), ex(l.r4, 'r4')];
  const ang = (x: number, f: string) => angleIn(D, x, f);
  const [t2, t3, t4] = [ang(theta2, 'theta2'), ang(pose.theta3, 'theta3'), ang(pose.theta4, 'theta4')];
  const w2 = ex(input.omega2, 'omega2');
  const a2 = ex(input.alpha2, 'alpha2');
  const a: V = { x: r2.times(D.cos(t2)), y: r2.times(D.sin(t2)) };
  const b: V = { x: r3.times(D.cos(t3)), y: r3.times(D.sin(t3)) };
  const c: V = { x: r4.times(D.cos(t4)), y: r4.times(D.sin(t4)) };
  const det = cross(b, c);
  const w3 = w2.times(cross(a, c)).div(det).neg();
  const w4 = w2.times(cross(b, a)).div(det);
  const w = {
    x: a.x
      .times(w2.pow(2))
      .neg()
      .minus(b.x.times(w3.pow(2)))
      .plus(c.x.times(w4.pow(2))),
    y: a.y
      .times(w2.pow(2))
      .neg()
      .minus(b.y.times(w3.pow(2)))
      .plus(c.y.times(w4.pow(2))),
  };
  // i w = (-w.y, w.x)
  const g: V = { x: w.y.neg().minus(a2.times(a.x)), y: w.x.minus(a2.times(a.y)) };
  return {
    omega3: w3,
    omega4: w4,
    alpha3: cross(g, c).div(det),
    alpha4: cross(b, g).div(det).neg(),
    sinMu: det.div(r3.times(r4)),
    cosMu: b.x.times(c.x).plus(b.y.times(c.y)).div(r3.times(r4)),
  };
}

/**
 * Rates at the given pose (theta2, theta3, theta4 taken as exact doubles), by Cramer's rule on
 * omega2 a + omega3 b - omega4 c = 0 and alpha3 b - alpha4 c = i w - alpha2 a,
 * w = -omega2^2 a - omega3^2 b + omega4^2 c, with a = r2 e^{i t2}, b = r3 e^{i t3}, c = r4 e^{i t4}.
 */
export function referenceRatesAtPose(
  l: LinkLengths,
  theta2: number,
  pose: { theta3: number; theta4: number },
  input: InputRates,
): ReferenceRatesAtPose {
  const r = ratesAtPoseIn(D60, l, theta2, pose, input);
  return {
    omega3: r.omega3.toNumber(),
    omega4: r.omega4.toNumber(),
    alpha3: r.alpha3.toNumber(),
    alpha4: r.alpha4.toNumber(),
    sinMu: r.sinMu.toNumber(),
    cosMu: r.cosMu.toNumber(),
  };
}

/**
 * 120 digits: the Cartesian sums of the acceleration lose up to 2 log10(1 / |sin mu|) digits to
 * cancellation (28 at sin mu = 1e-14), and extreme inputs must not round before the comparison.
 */
const D120 = Decimal.clone({ precision: 120, rounding: Decimal.ROUND_HALF_EVEN, minE: -9e15, maxE: 9e15 });

/** The rates of referenceRatesAtPose and their rateToleranceAtPose, as Decimals: nothing overflows or underflows. */
export interface WideRates {
  ref: Record<keyof ReferenceRates, Dec>;
  tol: Record<keyof ReferenceRates, Dec>;
}

/**
 * referenceRatesAtPose at 120 digits and the bound of rateToleranceAtPose evaluated in the same
 * precision, for inputs whose rates or whose intermediate products lie beyond the double range
 * (omega2 = 1e300, r2 / r3 = 1e310): the same derivation, without the doubles' overflow.
 */
export function referenceRatesWide(
  l: LinkLengths,
  theta2: number,
  pose: { theta3: number; theta4: number },
  input: InputRates,
): WideRates {
  const D = D120;
  const r = ratesAtPoseIn(D, l, theta2, pose, input);
  const [r2, r3, r4] = [exactIn(D, l.r2, 'r2'), exactIn(D, l.r3, 'r3'), exactIn(D, l.r4, 'r4')];
  const s = r.sinMu.abs();
  const w2 = exactIn(D, input.omega2, 'omega2').abs();
  const a2 = exactIn(D, input.alpha2, 'alpha2').abs();
  const q3 = r2.div(r3);
  const q4 = r2.div(r4);
  const sinHalfMu = D.max(0, new D(1).minus(r.cosMu).div(2)).sqrt();
  const R = w2.times(q3.times(r4.minus(r3).abs().div(r4)).plus(q4.times(2).times(sinHalfMu))).div(s);
  const u = new D(K).times(EPS);
  const accel = (q: Dec, wOther: Dec, wSelf: Dec): Dec =>
    u.times(q.times(a2.plus(w2.times(w2.plus(wOther.abs())))).plus(wSelf.abs().times(R))).div(s);
  return {
    ref: { omega3: r.omega3, omega4: r.omega4, alpha3: r.alpha3, alpha4: r.alpha4 },
    tol: {
      omega3: u.times(q3).times(w2).div(s),
      omega4: u.times(q4).times(w2).div(s),
      alpha3: accel(q3, r.omega4, r.omega3),
      alpha4: accel(q4, r.omega3, r.omega4),
    },
  };
}

/** Coupler point motion at the given pose from the 60-digit rates: v_P = v_A + omega3 k x AP, etc. */
export function referencePointAtPose(
  l: LinkLengths,
  theta2: number,
  pose: { theta3: number; theta4: number },
  input: InputRates,
  pDist: number,
  pAngle: number,
): ReferencePointMotion {
  const D = D60;
  const ex = (x: number, f: string) => exactIn(D, x, f);
  const r2 = ex(l.r2, 'r2');
  const ang = (x: number, f: string) => angleIn(D, x, f);
  const t2 = ang(theta2, 'theta2');
  const phi = ang(pose.theta3, 'theta3').plus(ang(pAngle, 'pAngle'));
  const p = ex(pDist, 'pDist');
  const w2 = ex(input.omega2, 'omega2');
  const a2 = ex(input.alpha2, 'alpha2');
  // The rates again at 60 digits (rounded to double they would lose digits for this sum).
  const r3 = ex(l.r3, 'r3');
  const r4 = ex(l.r4, 'r4');
  const t3 = ang(pose.theta3, 'theta3');
  const t4 = ang(pose.theta4, 'theta4');
  const av: V = { x: r2.times(D.cos(t2)), y: r2.times(D.sin(t2)) };
  const b: V = { x: r3.times(D.cos(t3)), y: r3.times(D.sin(t3)) };
  const c: V = { x: r4.times(D.cos(t4)), y: r4.times(D.sin(t4)) };
  const det = cross(b, c);
  const w3 = w2.times(cross(av, c)).div(det).neg();
  const w4 = w2.times(cross(b, av)).div(det);
  const wx = av.x
    .times(w2.pow(2))
    .neg()
    .minus(b.x.times(w3.pow(2)))
    .plus(c.x.times(w4.pow(2)));
  const wy = av.y
    .times(w2.pow(2))
    .neg()
    .minus(b.y.times(w3.pow(2)))
    .plus(c.y.times(w4.pow(2)));
  const g: V = { x: wy.neg().minus(a2.times(av.x)), y: wx.minus(a2.times(av.y)) };
  const a3 = cross(g, c).div(det);
  const ap: V = { x: p.times(D.cos(phi)), y: p.times(D.sin(phi)) };
  return {
    x: av.x.plus(ap.x).toNumber(),
    y: av.y.plus(ap.y).toNumber(),
    vx: w2.times(av.y).plus(w3.times(ap.y)).neg().toNumber(),
    vy: w2.times(av.x).plus(w3.times(ap.x)).toNumber(),
    ax: a2.times(av.y).plus(w2.pow(2).times(av.x)).plus(a3.times(ap.y)).plus(w3.pow(2).times(ap.x)).neg().toNumber(),
    ay: a2.times(av.x).minus(w2.pow(2).times(av.y)).plus(a3.times(ap.x)).minus(w3.pow(2).times(ap.y)).toNumber(),
  };
}

/** Step of the central differences in theta2 (rad). */
const H_STEP = '1e-26';

interface Differentiator {
  D: DecCtor;
  H: Dec;
  cosH: Dec;
  sinH: Dec;
}
const differentiators = new Map<number, Differentiator>();

/**
 * Decimal context for the finite differences: 80 digits, plus the decades by which the crank is
 * shorter than the longest link (the positions change by about r2 h per step while their size is
 * Lmax, so a 1e-300 crank needs 300 more digits to see the change at all).
 */
function differentiator(l: LinkLengths): Differentiator {
  const lMax = Math.max(l.r1, l.r2, l.r3, l.r4);
  const digits = 80 + Math.max(0, Math.ceil(Math.log10(lMax / l.r2)));
  let d = differentiators.get(digits);
  if (!d) {
    const D = Decimal.clone({ precision: digits, rounding: Decimal.ROUND_HALF_EVEN, minE: -9e15, maxE: 9e15 });
    const H = new D(H_STEP);
    d = { D, H, cosH: D.cos(H), sinH: D.sin(H) };
    differentiators.set(digits, d);
  }
  return d;
}

interface Assembly {
  A: V;
  /** A -> B (length r3) and O4 -> B (length r4). */
  u: V;
  v: V;
}

/** Position at the input angle with cos c2, sin s2, law of cosines as in reference.ts. */
function assemble(D: DecCtor, r1: Dec, r2: Dec, r3: Dec, r4: Dec, c2: Dec, s2: Dec, sigma: Sigma): Assembly {
  const A: V = { x: r2.times(c2), y: r2.times(s2) };
  const dx = r1.minus(A.x);
  const dy = A.y.neg();
  const s2len = dx.pow(2).plus(dy.pow(2));
  if (s2len.isZero()) throw new Error('oracle: crank pin on O4, no unique pose');
  const s = s2len.sqrt();
  const c = r3.pow(2).plus(s2len).minus(r4.pow(2)).div(r3.times(s).times(2));
  if (c.abs().greaterThan(1)) throw new Error('oracle: loop cannot close within h of theta2');
  const sinPsi = new D(1).minus(c.pow(2)).sqrt().times(sigma);
  const k = r3.div(s);
  const u: V = { x: k.times(c.times(dx).minus(sinPsi.times(dy))), y: k.times(sinPsi.times(dx).plus(c.times(dy))) };
  return { A, u, v: { x: A.x.plus(u.x).minus(r1), y: A.y.plus(u.y) } };
}

/**
 * Angle of w in (-pi, pi] as a double: atan2 of the correctly rounded components (a 60-digit atan2
 * costs more than the rest of the oracle). Within POSE_ROUNDING of the exact angle.
 */
function angleOf(w: V): number {
  const t = Math.atan2(w.y.toNumber(), w.x.toNumber());
  return t === -Math.PI ? Math.PI : t;
}

/**
 * True rates and coupler point motion at theta2 (rad) on branch sigma, by differentiating the
 * 80-digit positions (see the module comment). Throws if the loop does not close within 1e-26 of theta2.
 */
export function referenceMotion(
  l: LinkLengths,
  theta2: number,
  sigma: Sigma,
  input: InputRates,
  pDist = 0,
  pAngle = 0,
): ReferenceMotion {
  const { D, H, cosH, sinH } = differentiator(l);
  const ex = (x: number, f: string) => exactIn(D, x, f);
  const [r1, r2, r3, r4] = [ex(l.r1, 'r1'), ex(l.r2, 'r2'), ex(l.r3, 'r3'), ex(l.r4, 'r4')];
  const t2 = angleIn(D, theta2, 'theta2');
  const w2 = ex(input.omega2, 'omega2');
  const a2 = ex(input.alpha2, 'alpha2');
  const c2 = D.cos(t2);
  const s2 = D.sin(t2);
  const at = (sign: number) =>
    assemble(
      D,
      r1,
      r2,
      r3,
      r4,
      c2.times(cosH).minus(s2.times(sinH).times(sign)),
      s2.times(cosH).plus(c2.times(sinH).times(sign)),
      sigma,
    );
  const m = at(-1);
  const z = assemble(D, r1, r2, r3, r4, c2, s2, sigma);
  const p = at(1);
  const first = (f: (q: Assembly) => V): V => ({
    x: f(p).x.minus(f(m).x).div(H.times(2)),
    y: f(p).y.minus(f(m).y).div(H.times(2)),
  });
  const second = (f: (q: Assembly) => V): V => ({
    x: f(p).x.minus(f(z).x.times(2)).plus(f(m).x).div(H.pow(2)),
    y: f(p).y.minus(f(z).y.times(2)).plus(f(m).y).div(H.pow(2)),
  });
  // Coupler point: P = A + (pDist / r3) R(pAngle) u.
  const kP = ex(pDist, 'pDist').div(r3);
  const beta = angleIn(D, pAngle, 'pAngle');
  const cb = pAngle === 0 ? new D(1) : D.cos(beta);
  const sb = pAngle === 0 ? new D(0) : D.sin(beta);
  const P = (q: Assembly): V => ({
    x: q.A.x.plus(kP.times(cb.times(q.u.x).minus(sb.times(q.u.y)))),
    y: q.A.y.plus(kP.times(sb.times(q.u.x).plus(cb.times(q.u.y)))),
  });
  const U = (q: Assembly) => q.u;
  const W = (q: Assembly) => q.v;
  const d3 = cross(z.u, first(U)).div(r3.pow(2));
  const dd3 = cross(z.u, second(U)).div(r3.pow(2));
  const d4 = cross(z.v, first(W)).div(r4.pow(2));
  const dd4 = cross(z.v, second(W)).div(r4.pow(2));
  const w3 = d3.times(w2);
  const w4 = d4.times(w2);
  const w2sq = w2.pow(2);
  const P0 = P(z);
  const P1 = first(P);
  const P2 = second(P);
  return {
    theta3: angleOf(z.u),
    theta4: angleOf(z.v),
    sinMu: cross(z.u, z.v).div(r3.times(r4)).toNumber(),
    cosMu: z.u.x.times(z.v.x).plus(z.u.y.times(z.v.y)).div(r3.times(r4)).toNumber(),
    omega3: w3.toNumber(),
    omega4: w4.toNumber(),
    alpha3: dd3.times(w2sq).plus(d3.times(a2)).toNumber(),
    alpha4: dd4.times(w2sq).plus(d4.times(a2)).toNumber(),
    point: {
      x: P0.x.toNumber(),
      y: P0.y.toNumber(),
      vx: P1.x.times(w2).toNumber(),
      vy: P1.y.times(w2).toNumber(),
      ax: P2.x.times(w2sq).plus(P1.x.times(a2)).toNumber(),
      ay: P2.y.times(w2sq).plus(P1.y.times(a2)).toNumber(),
    },
  };
}

/** Test tolerances (rad/s, rad/s²) for the four rates. */
export interface RateTolerance {
  omega3: number;
  omega4: number;
  alpha3: number;
  alpha4: number;
}

/** Tolerances (length, length/s, length/s²) for a coupler point's motion. */
export interface PointTolerance {
  position: number;
  velocity: number;
  acceleration: number;
}

/** What the tolerances need to know about a pose and its rates. */
export interface RatesForTolerance extends ReferenceRates {
  sinMu: number;
  cosMu: number;
}

/**
 * Tolerance for rates computed at a pose whose angles are taken as exact (compared with
 * referenceRatesAtPose). With s = |sin mu|, q3 = r2 / r3, q4 = r2 / r4:
 *
 * - omega_j = omega2 q_j sin(.) / sin mu: every factor is correct to a few eps relative, so the error is
 *   K eps q_j |omega2| / s (eps |omega2| (r2 / r) / |sin mu|, per link).
 * - alpha_j is a sum of terms divided by sin mu: q_j (|alpha2| + |omega2| (|omega2| + |omega_k|)) from the
 *   crank, and |omega_j| R from the relative motion of coupler and rocker, where
 *   R = |omega2| (q3 |r4 - r3| / r4 + 2 q4 |sin(mu/2)|) / s bounds |omega3 - omega4| before any
 *   cancellation. R is O(1 / s) in general but O(1) where mu -> 0 with r3 = r4, the case the textbook
 *   form of the acceleration equations (terms r3 omega3^2 and r4 omega4^2 of size 1 / s^2) loses.
 *   Each term is rounded to a few eps relative, so the error is K eps (sum of the terms) / s: one more
 *   factor 1 / s than the velocities where R is bounded, two where R grows like 1 / s (and alpha with it).
 */
export function rateToleranceAtPose(l: LinkLengths, ref: RatesForTolerance, input: InputRates): RateTolerance {
  const s = Math.abs(ref.sinMu);
  const w2 = Math.abs(input.omega2);
  const a2 = Math.abs(input.alpha2);
  const q3 = l.r2 / l.r3;
  const q4 = l.r2 / l.r4;
  const sinHalfMu = Math.sqrt(Math.max(0, (1 - ref.cosMu) / 2));
  const R = (w2 * (q3 * (Math.abs(l.r4 - l.r3) / l.r4) + 2 * q4 * sinHalfMu)) / s;
  return {
    omega3: (K * EPS * q3 * w2) / s,
    omega4: (K * EPS * q4 * w2) / s,
    alpha3: (K * EPS * (q3 * (a2 + w2 * (w2 + Math.abs(ref.omega4))) + Math.abs(ref.omega3) * R)) / s,
    alpha4: (K * EPS * (q4 * (a2 + w2 * (w2 + Math.abs(ref.omega3))) + Math.abs(ref.omega4) * R)) / s,
  };
}

/**
 * Largest error (rad) of referenceMotion's double angles: components rounded to double (eps / 2
 * relative each) and a double atan2 (about an ulp, at most 2 eps for angles up to pi) stay within 4 eps.
 */
export const POSE_ROUNDING = 4 * EPS;

/**
 * Tolerance for rates computed at the correctly rounded pose, compared with the true rates
 * (referenceMotion): the at-pose tolerance plus what moving each angle by POSE_ROUNDING does.
 * omega_j = omega2 q_j sin(.) / sin mu moves by q_j |omega2| d (1 + 2 / s) / s; alpha_j, a sum of
 * terms T / s, by T d (1 + 3 / s) / s with T = q_j (|alpha2| + |omega2| (|omega2| + |omega_k|))
 * + |omega_j| (|omega3| + |omega4|) (each term's angles and omegas move it by at most that much).
 */
export function rateToleranceTrue(l: LinkLengths, ref: RatesForTolerance, input: InputRates): RateTolerance {
  const base = rateToleranceAtPose(l, ref, input);
  const s = Math.abs(ref.sinMu);
  const w2 = Math.abs(input.omega2);
  const a2 = Math.abs(input.alpha2);
  const q3 = l.r2 / l.r3;
  const q4 = l.r2 / l.r4;
  const d = K * POSE_ROUNDING;
  const w34 = Math.abs(ref.omega3) + Math.abs(ref.omega4);
  const T3 = q3 * (a2 + w2 * (w2 + Math.abs(ref.omega4))) + Math.abs(ref.omega3) * w34;
  const T4 = q4 * (a2 + w2 * (w2 + Math.abs(ref.omega3))) + Math.abs(ref.omega4) * w34;
  return {
    omega3: base.omega3 + (q3 * w2 * d * (1 + 2 / s)) / s,
    omega4: base.omega4 + (q4 * w2 * d * (1 + 2 / s)) / s,
    alpha3: base.alpha3 + (T3 * d * (1 + 3 / s)) / s,
    alpha4: base.alpha4 + (T4 * d * (1 + 3 / s)) / s,
  };
}

/**
 * Tolerance for the coupler point P = A + pDist e^{i (theta3 + pAngle)} and its derivatives
 * v_P = v_A + omega3 k x AP, a_P = a_A + alpha3 k x AP - omega3^2 AP: each of the few terms rounded
 * (K eps of the sum of their sizes), plus pDist times the error allowed for omega3 and alpha3, plus
 * (when poseRounding > 0) pDist times the size of each term for the direction of AP moving by that much.
 */
export function pointTolerance(
  l: LinkLengths,
  ref: ReferenceRates,
  rateTol: RateTolerance,
  input: InputRates,
  pDist: number,
  poseRounding: number,
): PointTolerance {
  const p = Math.abs(pDist);
  const w2 = Math.abs(input.omega2);
  const a2 = Math.abs(input.alpha2);
  const w3 = Math.abs(ref.omega3);
  const a3 = Math.abs(ref.alpha3);
  const u = K * EPS;
  const d = K * poseRounding;
  return {
    position: u * (l.r2 + p) + p * d,
    velocity: u * (l.r2 * w2 + p * w3) + p * (rateTol.omega3 + w3 * d),
    acceleration:
      u * (l.r2 * (a2 + w2 * w2) + p * (a3 + w3 * w3)) +
      p * (rateTol.alpha3 + 2 * w3 * rateTol.omega3 + (a3 + w3 * w3) * d),
  };
}
