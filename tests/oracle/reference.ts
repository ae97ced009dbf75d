/**
 * Independent high-precision oracle for the four-bar position problem.
 *
 * Every double input (link lengths, theta2) is taken as the exact binary value it holds and the
 * geometry is evaluated with decimal.js at 60 significant digits, so the results are the true
 * answers for the given doubles, rounded once to double at the end. The derivation is deliberately
 * different from the solver's (atan2 of a Kahan area): here the law of cosines in the triangle crank
 * pin A, coupler pin B, rocker pivot O4 gives cos psi at A, the vector A -> O4 rotated by sigma psi
 * and scaled to r3 gives B, and both angles are read off B with atan2.
 *
 * Conventions (docs/hard-cases.md): O2 at the origin, O4 at (r1, 0); A = r2 (cos t2, sin t2);
 * sigma = +1 ("open") puts B left of the ray A -> O4, which gives sin(t4 - t3) > 0.
 */
import Decimal from 'decimal.js';

/** Link lengths as in src/solver/types.ts (kept structural so the oracle imports nothing from src). */
export interface LinkLengths {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
}

/** +1 open, -1 crossed. */
export type Sigma = 1 | -1;

/** A unique assembly: wrapped angles (rad) and the facts tolerances are derived from. */
export interface ReferencePose {
  theta3: number;
  theta4: number;
  /** sin(theta4 - theta3), the transmission-angle sine; its sign is sigma. */
  sinMu: number;
  /** Distance |A O4| (length unit). */
  s: number;
}

/** Outcome of the oracle at one theta2. */
export type ReferenceOutcome =
  | { kind: 'unique'; pose: ReferencePose }
  /** |A O4| outside [|r3 - r4|, r3 + r4]: the loop cannot close. */
  | { kind: 'unreachable' }
  /** A lies on O4 and r3 = r4: B anywhere on a circle, t3 = t4 (no unique answer). */
  | { kind: 'continuum' };

const D = Decimal.clone({ precision: 60, rounding: Decimal.ROUND_HALF_EVEN, minE: -9e15, maxE: 9e15 });
type Dec = InstanceType<typeof D>;

const PI: Dec = D.acos(-1);
const TWO_PI: Dec = PI.times(2);
/** Tolerance for rounding of the 60-digit arithmetic itself when deciding "exactly at a limit". */
const LIMIT_FUZZ: Dec = new D('1e-50');

/** The exact value of a finite double as a Decimal (mantissa * 2^exponent, rounded only at 60 digits). */
export function exact(x: number): Dec {
  if (!Number.isFinite(x)) throw new Error(`oracle needs finite input, got ${x}`);
  if (x === 0) return new D(0);
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const bits = view.getBigUint64(0);
  const sign = bits >> 63n ? -1 : 1;
  const expBits = Number((bits >> 52n) & 0x7ffn);
  const frac = bits & 0xfffffffffffffn;
  const mantissa = expBits === 0 ? frac : frac | (1n << 52n);
  const exponent = (expBits === 0 ? 1 : expBits) - 1075;
  return new D(mantissa.toString()).times(new D(2).pow(exponent)).times(sign);
}

/** atan2 lands in [-pi, pi]; report -pi (a negative-zero y) as pi so results lie in (-pi, pi]. */
function wrapDec(a: Dec): Dec {
  return a.lessThanOrEqualTo(PI.neg()) ? a.plus(TWO_PI) : a;
}

/** Full oracle outcome at theta2 (rad) on branch sigma. */
export function referenceSolve(l: LinkLengths, theta2: number, sigma: Sigma): ReferenceOutcome {
  const r1 = exact(l.r1);
  const r2 = exact(l.r2);
  const r3 = exact(l.r3);
  const r4 = exact(l.r4);
  const t2 = exactAngle(theta2);
  const c2 = D.cos(t2);
  const ax = r2.times(c2);
  const ay = r2.times(D.sin(t2));
  // Vector A -> O4 and its length s (law of cosines in triangle O2 A O4 for s^2).
  const dx = r1.minus(ax);
  const dy = ay.neg();
  const s2 = r1.pow(2).plus(r2.pow(2)).minus(r1.times(r2).times(2).times(c2));
  if (s2.lessThanOrEqualTo(0)) {
    // Crank pin on O4: a continuum when r3 = r4, otherwise impossible.
    return r3.minus(r4).abs().lessThanOrEqualTo(r3.times(LIMIT_FUZZ)) ? { kind: 'continuum' } : { kind: 'unreachable' };
  }
  const s = s2.sqrt();
  // Triangle A B O4 with |AB| = r3, |B O4| = r4, |A O4| = s: law of cosines for the angle psi at A.
  let c = r3.pow(2).plus(s2).minus(r4.pow(2)).div(r3.times(s).times(2));
  if (c.abs().greaterThan(new D(1).plus(LIMIT_FUZZ))) return { kind: 'unreachable' };
  if (c.greaterThan(1)) c = new D(1);
  if (c.lessThan(-1)) c = new D(-1);
  const sinPsi = new D(1).minus(c.pow(2)).sqrt().times(sigma);
  // A -> B is A -> O4 rotated by sigma * psi (counter-clockwise for the open branch: B left of the
  // ray A -> O4) and scaled to length r3.
  const k = r3.div(s);
  const ux = k.times(c.times(dx).minus(sinPsi.times(dy)));
  const uy = k.times(sinPsi.times(dx).plus(c.times(dy)));
  // O4 -> B.
  const vx = ax.plus(ux).minus(r1);
  const vy = ay.plus(uy);
  return {
    kind: 'unique',
    pose: {
      theta3: wrapDec(D.atan2(uy, ux)).toNumber(),
      theta4: wrapDec(D.atan2(vy, vx)).toNumber(),
      // sin(t4 - t3) = (u x v) / (|u| |v|)
      sinMu: ux.times(vy).minus(uy.times(vx)).div(r3.times(r4)).toNumber(),
      s: s.toNumber(),
    },
  };
}

/** Reference theta3, theta4 (rad, wrapped to (-pi, pi]) on branch sigma, or null when there is no unique assembly. */
export function referenceAngles(l: LinkLengths, theta2: number, sigma: Sigma): ReferencePose | null {
  const out = referenceSolve(l, theta2, sigma);
  return out.kind === 'unique' ? out.pose : null;
}

/**
 * Signed slack of the loop at theta2 in length units: min(r3 + r4 - s, s - |r3 - r4|).
 * Negative means unreachable; its size says how far from a limit position the input is.
 */
export function referenceSlack(l: LinkLengths, theta2: number): number {
  const r1 = exact(l.r1);
  const r2 = exact(l.r2);
  const r3 = exact(l.r3);
  const r4 = exact(l.r4);
  const t2 = exactAngle(theta2);
  const s2 = r1
    .pow(2)
    .plus(r2.pow(2))
    .minus(r1.times(r2).times(2).times(D.cos(t2)));
  const s = s2.greaterThan(0) ? s2.sqrt() : new D(0);
  return D.min(r3.plus(r4).minus(s), s.minus(r3.minus(r4).abs())).toNumber();
}

/** Loop-closure residual norm |(f1, f2)| of the given double angles, evaluated exactly (length unit). */
export function referenceResidual(l: LinkLengths, theta2: number, theta3: number, theta4: number): number {
  const r1 = exact(l.r1);
  const r2 = exact(l.r2);
  const r3 = exact(l.r3);
  const r4 = exact(l.r4);
  const t2 = exactAngle(theta2);
  const t3 = exactAngle(theta3);
  const t4 = exactAngle(theta4);
  const f1 = r2
    .times(D.cos(t2))
    .plus(r3.times(D.cos(t3)))
    .minus(r4.times(D.cos(t4)))
    .minus(r1);
  const f2 = r2
    .times(D.sin(t2))
    .plus(r3.times(D.sin(t3)))
    .minus(r4.times(D.sin(t4)));
  return f1.pow(2).plus(f2.pow(2)).sqrt().toNumber();
}

/** Input-range limits from the reachable band of cos(theta2). */
export interface ReferenceLimits {
  /** No theta2 assembles. */
  empty: boolean;
  /** Smallest reachable |theta2| (rad); 0 when there is no lower limit. */
  lowerAbs: number;
  /** Largest reachable |theta2| (rad); pi when there is no upper limit. */
  upperAbs: number;
  hasLower: boolean;
  hasUpper: boolean;
  /**
   * Half-width bounds of cos(theta2) at the limits, cU = (r1^2 + r2^2 - (r3 + r4)^2) / (2 r1 r2)
   * and cL = (r1^2 + r2^2 - (r3 - r4)^2) / (2 r1 r2): reachable iff cU <= cos(theta2) <= cL.
   */
  cosUpper: number;
  cosLower: number;
}

/**
 * Input-range limits (docs/hard-cases.md "Classification"): s <= r3 + r4 iff cos t2 >= cU, s >= |r3 - r4|
 * iff cos t2 <= cL, so the reachable |t2| is [acos(min(cL, 1)), acos(max(cU, -1))] (empty if cU > cL
 * or the band misses [-1, 1]). Equivalent to the T1, T2, T3 tests of the table.
 */
export function referenceLimits(l: LinkLengths): ReferenceLimits {
  const r1 = exact(l.r1);
  const r2 = exact(l.r2);
  const r3 = exact(l.r3);
  const r4 = exact(l.r4);
  const den = r1.times(r2).times(2);
  const base = r1.pow(2).plus(r2.pow(2));
  const cU = base.minus(r3.plus(r4).pow(2)).div(den);
  const cL = base.minus(r3.minus(r4).pow(2)).div(den);
  const empty = cU.greaterThan(cL) || cU.greaterThan(1) || cL.lessThan(-1);
  const hasLower = cL.lessThan(1);
  const hasUpper = cU.greaterThan(-1);
  return {
    empty,
    hasLower,
    hasUpper,
    lowerAbs: empty ? NaN : hasLower ? D.acos(cL).toNumber() : 0,
    upperAbs: empty ? NaN : hasUpper ? D.acos(cU).toNumber() : Math.PI,
    cosUpper: cU.toNumber(),
    cosLower: cL.toNumber(),
  };
}

/**
 * Extreme rocker angles (rad) of a crank-rocker: B lies on the circle |O2 B| = r3 + r2 or r3 - r2
 * (crank and coupler collinear), so the interior angle at O4 of triangle O2 O4 B gives
 * t4 = pi - acos((r1^2 + r4^2 - d^2) / (2 r1 r4)) on the open branch.
 */
export function referenceRockerSwing(l: LinkLengths): { min: number; max: number } {
  const r1 = exact(l.r1);
  const r2 = exact(l.r2);
  const r3 = exact(l.r3);
  const r4 = exact(l.r4);
  const t4 = (d: Dec): Dec => PI.minus(D.acos(r1.pow(2).plus(r4.pow(2)).minus(d.pow(2)).div(r1.times(r4).times(2))));
  const a = t4(r3.plus(r2));
  const b = t4(r3.minus(r2).abs());
  return { min: D.min(a, b).toNumber(), max: D.max(a, b).toNumber() };
}

/** a - b wrapped to (-pi, pi] (rad), in double precision. */
export function angleDiff(a: number, b: number): number {
  let d = (a - b) % (2 * Math.PI);
  if (d > Math.PI) d -= 2 * Math.PI;
  else if (d <= -Math.PI) d += 2 * Math.PI;
  return d;
}

/** Degrees to radians for test inputs (x * pi / 180 in double; 90 -> fl(pi/2), 180 -> fl(pi)). */
export function deg(x: number): number {
  return (x * Math.PI) / 180;
}

/** Radians to degrees for comparing with the table. */
export function toDeg(x: number): number {
  return (x * 180) / Math.PI;
}

/** Exact conversion of a radian double to degrees in 60 digits (for comparing with 10-decimal tables). */
export function exactToDeg(x: number): number {
  return exact(x).times(180).div(PI).toNumber();
}

/** Enough digits for any double's remainder modulo 2 pi (its integer part has up to 309 digits). */
const WIDE = Decimal.clone({ precision: 420, rounding: Decimal.ROUND_HALF_EVEN, minE: -9e15, maxE: 9e15 });
const WIDE_PI = WIDE.acos(-1);

/** The exact value of a finite double at 420 digits (every double is exact there). */
function wideExact(x: number): InstanceType<typeof WIDE> {
  if (x === 0) return new WIDE(0);
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const bits = view.getBigUint64(0);
  const expBits = Number((bits >> 52n) & 0x7ffn);
  const frac = bits & 0xfffffffffffffn;
  const mantissa = expBits === 0 ? frac : frac | (1n << 52n);
  const e = (expBits === 0 ? 1 : expBits) - 1075;
  return new WIDE(mantissa.toString()).times(new WIDE(2).pow(e)).times(bits >> 63n ? -1 : 1);
}

/** The exact a - b modulo 2 pi into (-pi, pi], at 420 digits. */
function wideReduced(a: number, b: number): InstanceType<typeof WIDE> {
  const x = wideExact(a).minus(wideExact(b));
  const turn = WIDE_PI.times(2);
  let r = x.minus(x.div(turn).round().times(turn));
  if (r.lessThanOrEqualTo(WIDE_PI.neg())) r = r.plus(turn);
  if (r.greaterThan(WIDE_PI)) r = r.minus(turn);
  return r;
}

/**
 * The exact double x (radians) reduced modulo 2 pi at 420 digits, as a decimal string any Decimal clone
 * reads to its own precision: its cos and sin are those of x. The oracles take angles through this
 * because a 60-digit context holds a double exactly only below about 1e60 (1e100 has 101 digits), and a
 * rounded huge angle has an unrelated cosine.
 */
export function reducedAngleDigits(x: number): string {
  if (!Number.isFinite(x)) throw new Error(`oracle needs a finite angle, got ${x}`);
  return wideReduced(x, 0).toString();
}

/** An angle for the 60-digit oracle: the exact double reduced modulo 2 pi (see reducedAngleDigits). */
export function exactAngle(x: number): Dec {
  return new D(reducedAngleDigits(x));
}

/**
 * The exact a - b (doubles taken as exact) reduced modulo 2 pi into (-pi, pi], rounded once to a
 * double; b defaults to 0 (then it is the exact wrap of a). The double nearest to a value just above
 * -pi is -fl(pi); reported here as it falls, the caller decides how to compare at the seam.
 */
export function referenceWrap(a: number, b = 0): number {
  return wideReduced(a, b).toNumber();
}
