// The rates module itself, not the solver's barrel: the barrel would pull the sweep and NR into the main bundle.
import { couplerPointMotion, linkRates } from '../../solver/rates';
import type { InputMotion, LinkRates } from '../../solver/rates';
import type { LocalPose } from './localPose';

/** Velocity (length/s) and acceleration (length/s²) of a point, world axes (y up); NaN at a limit position. */
export interface PointRates {
  vx: number;
  vy: number;
  ax: number;
  ay: number;
}

/** The motion of this frame's pose: link rates (rad/s, rad/s²) and the motion of A, B and P. */
export interface FrameMotion {
  input: InputMotion;
  rates: LinkRates;
  A: PointRates;
  B: PointRates;
  P: PointRates;
  /** True at a limit position (coupler and rocker collinear): every rate is NaN there. */
  limit: boolean;
}

function rates(m: PointRates): PointRates {
  return { vx: m.vx, vy: m.vy, ax: m.ax, ay: m.ay };
}

/** The crank pin A: v = omega2 k x OA, a = alpha2 k x OA - omega2^2 OA (defined at a limit position too). */
function crankPin(r2: number, theta2: number, { omega2: w, alpha2: a }: InputMotion): PointRates {
  const x = r2 * Math.cos(theta2);
  const y = r2 * Math.sin(theta2);
  return { vx: -w * y, vy: w * x, ax: -a * y - w * w * x, ay: a * x - w * w * y };
}

/**
 * Rates of the frame's pose for the input motion, on the main thread (a few hundred nanoseconds): A from the
 * crank alone, B as the coupler point at r3 along AB, P the user's coupler point. Null when the
 * linkage does not assemble at theta2 or the solver refuses the input (never a throw: the panel shows why).
 */
export function frameMotion(local: LocalPose, input: InputMotion): FrameMotion | null {
  const { linkage: l, pose, theta2Rad, coupler } = local;
  if (!pose) return null;
  try {
    const r = linkRates(l, theta2Rad, pose, input);
    const B = couplerPointMotion(l, theta2Rad, pose, input, l.r3, 0);
    const P = couplerPointMotion(l, theta2Rad, pose, input, coupler.distance, coupler.angleRad);
    const limit = !Number.isFinite(r.omega3) || !Number.isFinite(r.omega4);
    return { input, rates: r, A: crankPin(l.r2, theta2Rad, input), B: rates(B), P: rates(P), limit };
  } catch {
    return null;
  }
}
