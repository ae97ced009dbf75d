/**
 * The one units module: angles in radians inside, degrees only at the UI edge, and the wraps to each
 * documented range. Pure (no DOM), so the solver and the view layer share it. `Radians` and `Degrees`
 * are branded numbers: a plain number converts freely into either, but a value of one cannot be passed
 * where the other is required, which makes a forgotten conversion a type error.
 */
import { describe } from './validate';

/** An angle in radians (branded: see the module comment). */
export type Radians = number & { readonly __unit?: 'rad' };
/** An angle in degrees (branded: see the module comment). */
export type Degrees = number & { readonly __unit?: 'deg' };

/** pi, for the few formulas outside this module that need the constant itself (circles, half turns). */
export const PI = Math.PI;
/** One full turn in radians (2 pi, rounded to a double). */
export const TWO_PI = 2 * Math.PI;
/** Radians per degree and degrees per radian. */
const RAD_PER_DEG = Math.PI / 180;
const DEG_PER_RAD = 180 / Math.PI;

/** Degrees to radians (NaN and infinities pass through); throws an Error naming deg for a non-number. */
export function degToRad(deg: number): Radians {
  if (typeof deg !== 'number') throw new Error(`deg must be a number of degrees, got ${describe(deg)}`);
  return (deg * Math.PI) / 180;
}

/** Radians to degrees (NaN and infinities pass through); throws an Error naming rad for a non-number. */
export function radToDeg(rad: number): Degrees {
  if (typeof rad !== 'number') throw new Error(`rad must be a number of radians, got ${describe(rad)}`);
  return (rad * 180) / Math.PI;
}

/** Radians per second to revolutions per minute, and back. */
export function radPerSToRpm(omegaRadPerS: number): number {
  return (omegaRadPerS * 60) / TWO_PI;
}
/** Revolutions per minute to radians per second. */
export function rpmToRadPerS(rpm: number): number {
  return (rpm * TWO_PI) / 60;
}
/** Radians per second to degrees per second. */
export function radPerSToDegPerS(omegaRadPerS: number): number {
  return omegaRadPerS * DEG_PER_RAD;
}
/** Degrees per second to radians per second. */
export function degPerSToRadPerS(degPerS: number): number {
  return degPerS * RAD_PER_DEG;
}

/** 2 pi as an unevaluated sum of three doubles (hi + mid + lo, about 160 bits), for Cody-Waite reduction. */
const TWO_PI_MID = 2.4492935982947064e-16;
const TWO_PI_LO = -5.989539619436679e-33;
/** Below this |x| the three-double reduction is exact to rounding (k * hi and k * mid are exact products). */
const CODY_WAITE_MAX = 2 ** 26;
/** Dekker's splitting constant for binary64. */
const SPLITTER = 134217729;

/** Product error a * b - fl(a * b), exact (Dekker's TwoProduct). */
function prodError(a: number, b: number, p: number): number {
  let t = SPLITTER * a;
  const ah = t - (t - a);
  const al = a - ah;
  t = SPLITTER * b;
  const bh = t - (t - b);
  const bl = b - bh;
  return ah * bh - p + ah * bl + al * bh + al * bl;
}

/** A reduced angle as an unevaluated sum hi + lo, |lo| <= ulp(hi) (see reduceDifference). */
export interface AngleParts {
  hi: number;
  lo: number;
}

const cwParts: AngleParts = { hi: 0, lo: 0 };

/** codyWaite's result as hi + lo (the compensated sum split once more), into out. */
function codyWaiteParts(x: number, k: number, out: AngleParts): void {
  const ph = k * TWO_PI;
  const pl = prodError(k, TWO_PI, ph);
  const qh = k * TWO_PI_MID;
  const ql = prodError(k, TWO_PI_MID, qh);
  const r0 = x - ph;
  const s1 = r0 - pl;
  const b1 = s1 - r0;
  const e1 = r0 - (s1 - b1) + (-pl - b1);
  const s2 = s1 - qh;
  const b2 = s2 - s1;
  const e2 = s1 - (s2 - b2) + (-qh - b2);
  const tail = e1 + e2 - ql - k * TWO_PI_LO;
  const hi = s2 + tail;
  out.hi = hi;
  out.lo = tail - (hi - s2);
}

/**
 * x - k 2 pi to about 2^-100 absolute, for an integer |k| <= 2^25 and |x| < 2^26: k hi and k mid are
 * formed exactly, x - k hi is exact (Sterbenz), and the small terms are added with compensation.
 */
function codyWaite(x: number, k: number): number {
  const ph = k * TWO_PI;
  const pl = prodError(k, TWO_PI, ph);
  const qh = k * TWO_PI_MID;
  const ql = prodError(k, TWO_PI_MID, qh);
  const r0 = x - ph;
  // r0 - pl - qh - ql - k lo with the rounding errors of the first two additions carried (TwoSum).
  const s1 = r0 - pl;
  const b1 = s1 - r0;
  const e1 = r0 - (s1 - b1) + (-pl - b1);
  const s2 = s1 - qh;
  const b2 = s2 - s1;
  const e2 = s1 - (s2 - b2) + (-qh - b2);
  return s2 + (e1 + e2 - ql - k * TWO_PI_LO);
}

/**
 * Largest |angle| (rad) whose differences the solver keeps as an exact TwoSum hi + lo with the first-order
 * correction sin(hi) + lo cos(hi): lo is at most half an ulp of hi, so the neglected lo^2 / 2 stays below
 * 2^-99 (eps^2 of the difference). Past it lo grows (to 1 rad at 1e16) and the difference is reduced
 * exactly with angleDiff instead; one range test keeps ordinary angles on the fast path.
 */
export const TWO_SUM_MAX_RAD = 16;

/** Bits of the fixed-point constants of the exact reduction (1/(2 pi) needs 971 + 53 + 200 for any double). */
const FRACTION_BITS = 1280;
/** Bits of a turn fraction returned by turnFraction (absolute resolution 2^-130 turn). */
const TURN_BITS = 130n;
let invTwoPiFixed = 0n;
let twoPiFixed = 0n;

/** atan(1/x) * 2^bits by its Taylor series (x >= 5), truncated; error below 2^-bits * (terms). */
function atanInvFixed(x: bigint, bits: bigint): bigint {
  const x2 = x * x;
  let power = (1n << bits) / x;
  let sum = power;
  for (let n = 3n, sign = -1n; power !== 0n; n += 2n, sign = -sign) {
    power /= x2;
    sum += (sign * power) / n;
  }
  return sum;
}

/** Machin's formula pi = 16 atan(1/5) - 4 atan(1/239), computed once, on the first huge argument. */
function reductionConstants(): void {
  if (invTwoPiFixed !== 0n) return;
  const bits = BigInt(FRACTION_BITS + 64);
  const piFixed = 16n * atanInvFixed(5n, bits) - 4n * atanInvFixed(239n, bits);
  invTwoPiFixed = (1n << (bits + BigInt(FRACTION_BITS))) / (2n * piFixed);
  twoPiFixed = (2n * piFixed) >> (bits - TURN_BITS);
}

const bitsView = new DataView(new ArrayBuffer(8));

/** x / (2 pi) modulo 1, centred in [-1/2, 1/2), as a signed integer over 2^130 (finite x, exact to 2^-130). */
function turnFraction(x: number): bigint {
  reductionConstants();
  bitsView.setFloat64(0, x);
  const hiWord = bitsView.getUint32(0);
  const biased = (hiWord >>> 20) & 0x7ff;
  const mant = (BigInt(hiWord & 0xfffff) << 32n) | BigInt(bitsView.getUint32(4));
  const m = biased === 0 ? mant : mant | (1n << 52n);
  const e = BigInt((biased === 0 ? 1 : biased) - 1075);
  // x / (2 pi) = m 2^e invTwoPiFixed / 2^FRACTION_BITS; keep the fraction only.
  const g = BigInt(FRACTION_BITS) - e;
  const n = m * invTwoPiFixed;
  let f = (g > 0n ? n & ((1n << g) - 1n) : 0n) >> (g - TURN_BITS);
  const half = 1n << (TURN_BITS - 1n);
  if (f >= half) f -= 2n * half;
  return hiWord >>> 31 ? -f : f;
}

/** A turn fraction (over 2^130) times 2 pi, as the nearest double (within an ulp). */
function turnsToRadians(f: bigint): number {
  if (f === 0n) return 0;
  const neg = f < 0n;
  const p = (neg ? -f : f) * twoPiFixed; // over 2^260
  const len = p.toString(2).length;
  const shift = len > 64 ? len - 64 : 0;
  const top = Number(p >> BigInt(shift));
  const v = top * 2 ** (shift - 260);
  return neg ? -v : v;
}

/** A turn fraction (over 2^130) times 2 pi as hi + lo: the double nearest, and the exact rest rounded. */
function turnsToParts(f: bigint, out: AngleParts): void {
  const hi = turnsToRadians(f);
  out.hi = hi;
  out.lo = 0;
  if (hi === 0) return;
  const neg = f < 0n;
  const p = (neg ? -f : f) * twoPiFixed; // over 2^260
  bitsView.setFloat64(0, Math.abs(hi));
  const hiWord = bitsView.getUint32(0);
  const biased = (hiWord >>> 20) & 0x7ff;
  const mant = (BigInt(hiWord & 0xfffff) << 32n) | BigInt(bitsView.getUint32(4)) | (1n << 52n);
  // |hi| >= 2 pi 2^-130, so its exponent plus 260 is positive: hi is an integer over 2^260.
  const rest = p - (mant << BigInt(biased - 1075 + 260));
  const lo = Number(rest) * 2 ** -260;
  out.lo = neg ? -lo : lo;
}

/**
 * The exact a - b modulo 2 pi as hi + lo, into out: |hi| below about 3 pi, |lo| <= ulp(hi), accurate to
 * about 2^-100 absolute, so sin(hi) + lo cos(hi) and cos(hi) - lo sin(hi) are the sine and cosine of the
 * exact difference to full relative accuracy (a single rounded double near pi would not give its small
 * sine that). Any finite a, b; NaN parts for a non-finite one (a missing pose stays missing).
 */
export function reduceDifference(a: number, b: number, out: AngleParts): void {
  if (a - a !== 0 || b - b !== 0) {
    out.hi = out.lo = NaN;
    return;
  }
  const d = a - b;
  const bb = d - a;
  const err = a - (d - bb) + (-b - bb);
  if (Math.abs(d) < CODY_WAITE_MAX) {
    codyWaiteParts(d, Math.round(d / TWO_PI), cwParts);
    // Add the rounding error of d: TwoSum with hi, then fold it into lo.
    const h = cwParts.hi + err;
    const hb = h - cwParts.hi;
    const e = cwParts.hi - (h - hb) + (err - hb);
    const lo = cwParts.lo + e;
    const hi = h + lo;
    out.hi = hi;
    out.lo = lo - (hi - h);
    return;
  }
  const half = 1n << (TURN_BITS - 1n);
  let f = turnFraction(a) - turnFraction(b);
  if (f >= half) f -= 2n * half;
  else if (f < -half) f += 2n * half;
  turnsToParts(f, out);
}

/** A wrapped result within an ulp of +-pi could round just outside the range: fold it onto pi. */
function inRange(r: number): Radians {
  return r > -Math.PI && r <= Math.PI ? r : Math.PI;
}

/**
 * Wraps an angle in radians to (-pi, pi], exactly for every finite double (the result is within an
 * ulp of the true x - 2 pi k, by Cody-Waite reduction below 2^26 and Payne-Hanek style fixed-point
 * reduction above); -pi maps to pi. Non-finite input (no direction) gives NaN; a non-number throws.
 */
export function wrapAngle(rad: number): Radians {
  if (typeof rad !== 'number') throw new Error(`wrapAngle: rad must be a number of radians, got ${describe(rad)}`);
  if (rad > -Math.PI && rad <= Math.PI) return rad;
  if (!(Math.abs(rad) < CODY_WAITE_MAX)) {
    if (!Number.isFinite(rad)) return NaN;
    return inRange(turnsToRadians(turnFraction(rad)));
  }
  const k = Math.round(rad / TWO_PI);
  let r = codyWaite(rad, k);
  if (r > Math.PI) r = codyWaite(rad, k + 1);
  else if (r <= -Math.PI) r = codyWaite(rad, k - 1);
  return inRange(r);
}

/**
 * Signed difference a - b wrapped to (-pi, pi], in radians: the exact difference is reduced (to within
 * an ulp), so huge or very unequal angles lose nothing. Non-finite input gives NaN; a non-number throws.
 */
export function angleDiff(a: number, b: number): Radians {
  if (typeof a !== 'number' || typeof b !== 'number') {
    const [name, v] = typeof a !== 'number' ? ['a', a] : ['b', b];
    throw new Error(`angleDiff: ${name} must be a number of radians, got ${describe(v)}`);
  }
  const d = a - b;
  const bb = d - a;
  const err = a - (d - bb) + (-b - bb);
  if (!Number.isFinite(a) || !Number.isFinite(b)) return NaN;
  if (err === 0) return wrapAngle(d);
  if (Math.abs(a) < CODY_WAITE_MAX && Math.abs(b) < CODY_WAITE_MAX) return wrapAngle(wrapAngle(d) + err);
  const half = 1n << (TURN_BITS - 1n);
  let f = turnFraction(a) - turnFraction(b);
  if (f >= half) f -= 2n * half;
  else if (f < -half) f += 2n * half;
  return inRange(turnsToRadians(f));
}

/** Wraps degrees into [0, 360); non-finite input gives 0 (the input angle theta2 shown to people). */
export function wrapDeg360(deg: number): Degrees {
  if (!Number.isFinite(deg)) return 0;
  // x % 360 is exact in binary floating point, so this is right for any magnitude.
  const w = deg % 360;
  if (w < 0) {
    const v = w + 360;
    // -1e-17 + 360 rounds to 360: fold it back into the half-open range.
    return v >= 360 ? 0 : v;
  }
  return w === 0 ? 0 : w;
}

/** Wraps degrees into (-180, 180]; non-finite input is returned unchanged (every output angle shown). */
export function wrapDeg180(deg: number): Degrees {
  if (!Number.isFinite(deg)) return deg;
  if (deg > -180 && deg <= 180) return deg;
  // Exact remainder first, then one exact shift: no rounding for any magnitude.
  let w = deg % 360;
  if (w > 180) w -= 360;
  else if (w <= -180) w += 360;
  return w;
}

/** Radians to degrees wrapped to (-180, 180]. */
export function radToDeg180(rad: number): Degrees {
  return wrapDeg180(radToDeg(rad));
}

/** Radians to degrees wrapped to [0, 360). */
export function radToDeg360(rad: number): Degrees {
  return wrapDeg360(radToDeg(rad));
}
