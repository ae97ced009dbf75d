import { PI, TWO_PI } from '../solver';
import { Closure, newPoint, outputRates, wrapSmall } from './point';
import type { SpatialPoint } from './point';
import type { SpatialBranch, SpatialInput, SpatialPose, SphericalLinkage, Vec3 } from './types';
import { branchSigma, checkFinite, validateInput, validateSpherical } from './validate';
import { add, cross, dot, norm, scale, sub, vec3 } from './vec3';

// Module-local copies of the units module's constants (read per point; see src/solver/closedForm.ts).
const HALF_TURN = PI;
const FULL_TURN = TWO_PI;
const EPS = Number.EPSILON;

/** Per-linkage constants of the spherical solve (all arcs in radians). */
export interface SphericalPlan {
  a1: number;
  a2: number;
  a3: number;
  a4: number;
  sa1: number;
  ca1: number;
  sa2: number;
  ca2: number;
  sa4: number;
  ca4: number;
  /** sin(a2 - a1), A . u at theta2 = 0. */
  sinA2mA1: number;
  /** sin^2((a1 - a2)/2), cos^2((a1 + a2)/2) and sin a1 sin a2: the haversine terms of the arc A O4. */
  hMinus: number;
  cPlus: number;
  sa1sa2: number;
  /** Coupler point: present, cos and sin of pDist and pAngle. */
  hasP: boolean;
  cpd: number;
  spd: number;
  cpa: number;
  spa: number;
}

/** Validates l (throws an Error naming the field) and returns the solve's constants. */
export function planSpherical(l: SphericalLinkage): SphericalPlan {
  validateSpherical(l);
  const { a1, a2, a3, a4 } = l;
  const hm = Math.sin((a1 - a2) / 2);
  const cp = Math.cos((a1 + a2) / 2);
  const pd = l.pDist ?? 0;
  const pa = l.pAngle ?? 0;
  return {
    a1,
    a2,
    a3,
    a4,
    sa1: Math.sin(a1),
    ca1: Math.cos(a1),
    sa2: Math.sin(a2),
    ca2: Math.cos(a2),
    sa4: Math.sin(a4),
    ca4: Math.cos(a4),
    sinA2mA1: Math.sin(a2 - a1),
    hMinus: hm * hm,
    cPlus: cp * cp,
    sa1sa2: Math.sin(a1) * Math.sin(a2),
    hasP: l.pDist !== undefined,
    cpd: Math.cos(pd),
    spd: Math.sin(pd),
    cpa: Math.cos(pa),
    spa: Math.sin(pa),
  };
}

/**
 * Arc d = |A O4| (radians) at input angle theta2 from the haversine forms
 * sin^2(d/2) = sin^2((a1-a2)/2) + sin a1 sin a2 sin^2(theta2/2), cos^2(d/2) = cos^2((a1+a2)/2) + sin a1 sin a2 cos^2(theta2/2):
 * sums of non-negative terms, so d keeps full relative accuracy at both ends (where acos of the cosine rule loses half).
 */
export function arcToO4(plan: SphericalPlan, theta2: number): number {
  const h = Math.sin(theta2 / 2);
  const c = Math.cos(theta2 / 2);
  return 2 * Math.atan2(Math.sqrt(plan.hMinus + plan.sa1sa2 * h * h), Math.sqrt(plan.cPlus + plan.sa1sa2 * c * c));
}

/**
 * Solves the spherical loop at theta2 on branch sigma (-1 open, +1 crossed) into p: theta4 = phi + sigma psi where phi
 * is the direction of A seen from O4 (in the frame u, y of the rocker's angle) and psi the angle at O4 of the spherical
 * triangle O4 A B (sides d, a3, a4), from the half-angle formula
 * tan(psi/2) = sqrt(sin(s - d) sin(s - a4) / (sin s sin(s - a3))), flat-triangle safe. Also fills the constraint's
 * partials F2 = A'.B and F4 = A.B' (F4 = -sigma sin a4 sin d sin psi, exact at a limit) and the transmission angle.
 */
export function sphericalAt(plan: SphericalPlan, theta2: number, sigma: number, p: SpatialPoint): Closure {
  const { sa1, ca1, sa2, ca2, sa4, ca4, a3, a4 } = plan;
  const c2 = Math.cos(theta2);
  const s2 = Math.sin(theta2);
  const hs = Math.sin(theta2 / 2);
  const hav = 2 * hs * hs; // 1 - cos theta2 without cancellation
  // A . u and A . y, u = (cos a1, 0, -sin a1) the ground circle's tangent beyond O4: A . u = sin(a2 - a1) at theta2 = 0.
  const au = plan.sinA2mA1 - sa2 * ca1 * hav;
  const ay = sa2 * s2;
  const d = arcToO4(plan, theta2);
  const g1 = a3 + a4 - d;
  const g2 = d + a3 - a4;
  const g3 = d + a4 - a3;
  const sum = d + a3 + a4;
  const g4 = FULL_TURN - sum;
  // Each g carries a few roundings of terms below 2 pi; a g negative by less is a limit (flat triangle).
  const tol = 8 * EPS * sum;
  if (g1 < -tol || g2 < -tol || g3 < -tol || g4 < -8 * EPS * FULL_TURN) return Closure.Unreachable;
  const limit = g1 <= 0 || g2 <= 0 || g3 <= 0 || g4 <= 0;
  // sin(s - d) = sin(g1/2), sin(s - a4) = sin(g2/2), sin(s - a3) = sin(g3/2), sin s = sin(g4/2).
  const n1 = Math.sqrt(Math.sin(Math.max(0, g1) / 2)) * Math.sqrt(Math.sin(Math.max(0, g2) / 2));
  // sin s from s itself while s < pi/2 (tiny arcs: pi - s would round to pi), from 2 pi - 2 s beyond.
  const sinS = sum < HALF_TURN ? Math.sin(sum / 2) : Math.sin(Math.max(0, g4) / 2);
  const n2 = Math.sqrt(sinS) * Math.sqrt(Math.sin(Math.max(0, g3) / 2));
  const psi = 2 * Math.atan2(n1, n2);
  const phi = Math.atan2(ay, au);
  const t4 = wrapSmall(phi + sigma * psi, HALF_TURN, FULL_TURN);
  const c4 = Math.cos(t4);
  const s4 = Math.sin(t4);
  p.theta4 = t4;
  p.cos4 = c4;
  p.sin4 = s4;
  p.ax = sa2 * c2;
  p.ay = ay;
  p.az = ca2;
  // B = cos a4 O4 + sin a4 (cos theta4 u + sin theta4 y), O4 = (sin a1, 0, cos a1).
  p.bx = ca4 * sa1 + sa4 * c4 * ca1;
  p.by = sa4 * s4;
  p.bz = ca4 * ca1 - sa4 * c4 * sa1;
  p.dax = -ay;
  p.day = p.ax;
  p.dbx = -sa4 * s4 * ca1;
  p.dby = sa4 * c4;
  p.dbz = sa4 * s4 * sa1;
  p.ddax = -p.ax;
  p.dday = -ay;
  p.ddbx = -sa4 * c4 * ca1;
  p.ddby = -sa4 * s4;
  p.ddbz = sa4 * c4 * sa1;
  p.f2 = p.dax * p.bx + p.day * p.by;
  // At a limit psi is 0 or pi exactly and so is sin psi (Math.sin(pi) is 1.2e-16, not 0).
  const sinPsi = limit ? 0 : Math.sin(psi);
  p.f4 = -sigma * sa4 * Math.hypot(au, ay) * sinPsi;
  // Transmission angle: between the arcs B->A and B->O4 at B, as the rocker's tangent t and inward tangent see A.
  const aDotT = -s4 * au + c4 * ay;
  const aDotIn = sa4 * (ca1 * p.az + sa1 * p.ax) - ca4 * (c4 * au + s4 * ay);
  p.mu = Math.atan2(Math.abs(aDotT), aDotIn);
  return limit ? Closure.Limit : Closure.Ok;
}

/** Fills p.omega4 and p.alpha4 for the input's omega2 (rad/s) and alpha2 (rad/s^2) after sphericalAt. */
export function sphericalRates(plan: SphericalPlan, p: SpatialPoint, omega2: number, alpha2: number): void {
  const f22 = p.ddax * p.bx + p.dday * p.by;
  const f24 = p.dax * p.dbx + p.day * p.dby;
  const f44 = p.ax * p.ddbx + p.ay * p.ddby + p.az * p.ddbz;
  void plan;
  outputRates(p, f22, f24, f44, omega2, alpha2);
}

/**
 * The coupler point P = cos(pd) A + sin(pd) (cos(pa) t + sin(pa) n), n = A x B / |A x B|, t = n x A, written to
 * out[at..at+2] (unit sphere). Scalar arithmetic, no objects: a sweep calls it once per angle.
 */
export function couplerPointInto(
  plan: SphericalPlan,
  ax: number,
  ay: number,
  az: number,
  bx: number,
  by: number,
  bz: number,
  out: Float64Array | number[],
  at: number,
): void {
  // A x (B - A) = A x B, formed from the chord so a short coupler keeps its digits.
  const dx = bx - ax;
  const dy = by - ay;
  const dz = bz - az;
  let nx = ay * dz - az * dy;
  let ny = az * dx - ax * dz;
  let nz = ax * dy - ay * dx;
  const nn = nx * nx + ny * ny + nz * nz;
  const k = 1 / (nn > 1e-290 ? Math.sqrt(nn) : Math.hypot(nx, ny, nz));
  nx *= k;
  ny *= k;
  nz *= k;
  const tx = ny * az - nz * ay;
  const ty = nz * ax - nx * az;
  const tz = nx * ay - ny * ax;
  const { cpd, spd, cpa, spa } = plan;
  out[at] = cpd * ax + spd * (cpa * tx + spa * nx);
  out[at + 1] = cpd * ay + spd * (cpa * ty + spa * ny);
  out[at + 2] = cpd * az + spd * (cpa * tz + spa * nz);
}

/** couplerPointInto for two pins as vectors. */
export function couplerPointOf(plan: SphericalPlan, A: Vec3, B: Vec3): Vec3 {
  const out = [0, 0, 0];
  couplerPointInto(plan, A.x, A.y, A.z, B.x, B.y, B.z, out, 0);
  return vec3(out[0], out[1], out[2]);
}

/**
 * The coupler's angular velocity W about the sphere's centre from its two pins: W x A = vA, W x B = vB gives
 * W = A x vA + lambda A with lambda = (vB - (A x vA) x B) . n / |n|, n = A x B / |A x B|. The same form gives the
 * angular acceleration from aA - W x vA and aB - W x vB.
 */
function bodyRate(A: Vec3, B: Vec3, gA: Vec3, gB: Vec3, nHat: Vec3, nLen: number): Vec3 {
  const w0 = cross(A, gA);
  const lambda = dot(sub(gB, cross(w0, B)), nHat) / nLen;
  return add(w0, scale(A, lambda));
}

/** Motion of the coupler point P from the pins' positions, velocities and accelerations (unit sphere). */
export function couplerPointMotion(
  A: Vec3,
  B: Vec3,
  P: Vec3,
  vA: Vec3,
  vB: Vec3,
  aA: Vec3,
  aB: Vec3,
): { v: Vec3; a: Vec3 } {
  const n = cross(A, sub(B, A));
  const nLen = norm(n);
  const nHat = scale(n, 1 / nLen);
  const w = bodyRate(A, B, vA, vB, nHat, nLen);
  const wd = bodyRate(A, B, sub(aA, cross(w, vA)), sub(aB, cross(w, vB)), nHat, nLen);
  const v = cross(w, P);
  return { v, a: add(cross(wd, P), cross(w, v)) };
}

/** A vector times a rate that may be infinite, with 0 * Infinity read as 0 (a limit's unbounded rates). */
export function times(u: Vec3, k: number): Vec3 {
  if (Number.isFinite(k)) return scale(u, k);
  const f = (c: number) => (c === 0 ? 0 : c * k);
  return vec3(f(u.x), f(u.y), f(u.z));
}

/** The pose of a solved point: positions, and with input motion the rates of A, B (and P) by the chain rule. */
export function poseOf(
  p: SpatialPoint,
  omega2: number,
  alpha2: number,
  couplerPoint: ((A: Vec3, B: Vec3) => Vec3) | null,
  unit: number,
): SpatialPose {
  const A = vec3(p.ax, p.ay, p.az);
  const B = vec3(p.bx, p.by, p.bz);
  const dA = vec3(p.dax, p.day, 0);
  const dB = vec3(p.dbx, p.dby, p.dbz);
  const vA = scale(dA, omega2);
  const aA = add(scale(vec3(p.ddax, p.dday, 0), omega2 * omega2), scale(dA, alpha2));
  const w4 = p.omega4;
  const finite = Number.isFinite(w4) && Number.isFinite(p.alpha4);
  const vB = times(dB, w4);
  const aB = finite ? add(scale(vec3(p.ddbx, p.ddby, p.ddbz), w4 * w4), scale(dB, p.alpha4)) : times(dB, p.alpha4);
  const pose: SpatialPose = {
    A: scale(A, unit),
    B: scale(B, unit),
    theta4: p.theta4,
    omega4: p.omega4,
    alpha4: p.alpha4,
    velocity: { A: scale(vA, unit), B: times(vB, unit) },
    acceleration: { A: scale(aA, unit), B: times(aB, unit) },
  };
  if (couplerPoint !== null) {
    const P = couplerPoint(A, B);
    pose.P = scale(P, unit);
    if (finite) {
      const m = couplerPointMotion(A, B, P, vA, vB, aA, aB);
      pose.velocity.P = scale(m.v, unit);
      pose.acceleration.P = scale(m.a, unit);
    } else {
      // Unbounded: P moves with the coupler, whose rate is dominated by the output's.
      const m = couplerPointMotion(A, B, P, vec3(0, 0, 0), dB, vec3(0, 0, 0), vec3(0, 0, 0));
      pose.velocity.P = times(m.v, w4);
      pose.acceleration.P = times(m.v, p.alpha4);
    }
  }
  return pose;
}

/**
 * Solves a spherical four-bar at input angle theta2 (radians) on the branch given ('open' where
 * (A - B) . dB/dtheta4 > 0): positions on the unit sphere, theta4 in (-pi, pi], and with input = { omega2 (rad/s),
 * alpha2 (rad/s^2) } the exact rates from the differentiated constraint A . B = cos a3. Returns null where the loop
 * cannot close. Throws an Error naming the field for a bad linkage, theta2, branch or input.
 */
export function solveSpherical(
  l: SphericalLinkage,
  theta2: number,
  branch: SpatialBranch,
  input?: SpatialInput,
): SpatialPose | null {
  const plan = planSpherical(l);
  checkFinite('theta2', theta2, 'angle in radians');
  const sigma = branchSigma(branch);
  validateInput(input);
  const p = newPoint();
  if (sphericalAt(plan, theta2, sigma, p) === Closure.Unreachable) return null;
  const omega2 = input?.omega2 ?? 0;
  const alpha2 = input?.alpha2 ?? 0;
  sphericalRates(plan, p, omega2, alpha2);
  return poseOf(p, omega2, alpha2, plan.hasP ? (A, B) => couplerPointOf(plan, A, B) : null, 1);
}
