/**
 * The one units module: angles in radians inside, degrees only at the UI edge, and the wraps to each
 * documented range. Pure (no DOM), so the solver and the view layer share it. `Radians` and `Degrees`
 * are branded numbers: a plain number converts freely into either, but a value of one cannot be passed
 * where the other is required, which makes a forgotten conversion a type error.
 */

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

/** Degrees to radians. */
export function degToRad(deg: number): Radians {
  return (deg * Math.PI) / 180;
}

/** Radians to degrees. */
export function radToDeg(rad: number): Degrees {
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

/** Wraps an angle in radians to (-pi, pi]; non-finite input is returned unchanged. */
export function wrapAngle(rad: number): Radians {
  if (rad > -Math.PI && rad <= Math.PI) return rad;
  if (!Number.isFinite(rad)) return rad;
  let w = rad - TWO_PI * Math.floor((rad + Math.PI) / TWO_PI);
  // floor can land one ulp off the half-open interval.
  if (w <= -Math.PI) w += TWO_PI;
  if (w > Math.PI) w -= TWO_PI;
  return w;
}

/** Signed difference a - b wrapped to (-pi, pi], in radians. */
export function angleDiff(a: number, b: number): Radians {
  return wrapAngle(a - b);
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
