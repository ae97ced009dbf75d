/** Angle helpers. Radians everywhere inside the solver; degrees only at the UI edge. */

const TWO_PI = 2 * Math.PI;

/** Degrees to radians. */
export function degToRad(deg: number): number {
  return (deg * Math.PI) / 180;
}

/** Radians to degrees. */
export function radToDeg(rad: number): number {
  return (rad * 180) / Math.PI;
}

/** Wraps an angle in radians to (-pi, pi]; non-finite input is returned unchanged. */
export function wrapAngle(rad: number): number {
  if (rad > -Math.PI && rad <= Math.PI) return rad;
  if (!Number.isFinite(rad)) return rad;
  let w = rad - TWO_PI * Math.floor((rad + Math.PI) / TWO_PI);
  // floor can land one ulp off the half-open interval.
  if (w <= -Math.PI) w += TWO_PI;
  if (w > Math.PI) w -= TWO_PI;
  return w;
}

/** Signed difference a - b wrapped to (-pi, pi], in radians. */
export function angleDiff(a: number, b: number): number {
  return wrapAngle(a - b);
}
