/** Outcome of one position solve. */
export const Closure = {
  /** The loop closes; the two branches are distinct. */
  Ok: 0,
  /** The loop closes at a limit (the triangle at the output pivot is flat within rounding): both branches meet. */
  Limit: 1,
  /** The loop cannot close at this input angle. */
  Unreachable: 2,
} as const;

/** Numeric closure status (see Closure). */
export type Closure = (typeof Closure)[keyof typeof Closure];

/**
 * Scratch of one solved input angle, flat numbers so a sweep allocates nothing. Positions and their derivatives
 * with respect to the joint angles are in the solver's working units (unit sphere; RSSR lengths divided by 2^exponent).
 */
export interface SpatialPoint {
  theta4: number;
  cos4: number;
  sin4: number;
  /** Pins A, B and their first and second derivatives by theta2 (A) and theta4 (B). */
  ax: number;
  ay: number;
  az: number;
  bx: number;
  by: number;
  bz: number;
  dax: number;
  day: number;
  dbx: number;
  dby: number;
  dbz: number;
  ddax: number;
  dday: number;
  ddbx: number;
  ddby: number;
  ddbz: number;
  /** Partial derivatives of the closure constraint F(theta2, theta4) = 0. */
  f2: number;
  f4: number;
  /** Transmission angle analogue at B (radians, [0, pi]). */
  mu: number;
  omega4: number;
  alpha4: number;
}

/** A zeroed scratch point. */
export function newPoint(): SpatialPoint {
  return {
    theta4: 0,
    cos4: 1,
    sin4: 0,
    ax: 0,
    ay: 0,
    az: 0,
    bx: 0,
    by: 0,
    bz: 0,
    dax: 0,
    day: 0,
    dbx: 0,
    dby: 0,
    dbz: 0,
    ddax: 0,
    dday: 0,
    ddbx: 0,
    ddby: 0,
    ddbz: 0,
    f2: 0,
    f4: 0,
    mu: 0,
    omega4: 0,
    alpha4: 0,
  };
}

/**
 * Output rates from the differentiated constraint: F2 w2 + F4 w4 = 0 and
 * F22 w2^2 + 2 F24 w2 w4 + F44 w4^2 + F2 a2 + F4 a4 = 0. At an exact limit (F4 = 0) with a moving input the rates
 * are unbounded: +-Infinity, never NaN.
 */
export function outputRates(
  p: SpatialPoint,
  f22: number,
  f24: number,
  f44: number,
  omega2: number,
  alpha2: number,
): void {
  if (omega2 === 0 && alpha2 === 0) {
    p.omega4 = 0;
    p.alpha4 = 0;
    return;
  }
  if (p.f4 === 0) {
    const s = -(p.f2 * omega2 || p.f2 * alpha2 || 1);
    p.omega4 = omega2 === 0 ? 0 : Math.sign(s) * Infinity;
    p.alpha4 = Math.sign(s) * Infinity;
    return;
  }
  const w4 = (-p.f2 * omega2) / p.f4;
  p.omega4 = w4;
  p.alpha4 = -(f22 * omega2 * omega2 + 2 * f24 * omega2 * w4 + f44 * w4 * w4 + p.f2 * alpha2) / p.f4;
}

/** theta wrapped to (-pi, pi] for |theta| < 3 pi (the solvers' phi +- psi). */
export function wrapSmall(theta: number, pi: number, twoPi: number): number {
  if (theta > pi) return theta - twoPi;
  if (theta <= -pi) return theta + twoPi;
  return theta;
}
