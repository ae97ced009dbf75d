/**
 * Kinetostatics of the four-bar: the input torque, the pin forces and the shaking force and moment at
 * a solved pose, with the links' inertia, gravity at any angle, a force at a coupler point and a load
 * torque on the rocker (docs/forces.md has the conventions, the equations and the accuracy).
 *
 * Convention: Fij is the force of link i on link j (1 ground, 2 crank, 3 coupler, 4 rocker), in N; torques
 * and moments in N·m, counter-clockwise positive; SI throughout (m, kg, s). With q_i = m_i (a_Gi - g) the
 * force a link's pins and loads must supply beyond its weight, the nine Newton–Euler equations are
 *
 *   crank   F12 + F32 = q2,                 T12 + A × F32 = I2 alpha2 + rG2 × q2      (moments about O2)
 *   coupler F43 - F32 + Fp = q3,            r3 × F43 + rP × Fp = I3 alpha3 + rG3 × q3 (moments about A)
 *   rocker  F14 - F43 = q4,                 -r4 × F43 + T4 = I4 alpha4 + rG4 × q4     (moments about O4)
 *
 * (rGi from the link's first joint, r3 = B - A, r4 = B - O4, rP = P - A). The two moment equations of
 * coupler and rocker hold F43 alone: with M3 = I3 alpha3 + rG3 × q3 - rP × Fp and
 * M4 = I4 alpha4 + rG4 × q4 - T4 they read r3 × F43 = M3 and r4 × F43 = -M4, a 2x2 system whose
 * determinant is r3 r4 sin mu (mu = theta4 - theta3), solved in closed form along the link directions:
 *
 *   F43 = (M3 / (r3 sin mu)) u4 + (M4 / (r4 sin mu)) u3.
 *
 * The rest follows by substitution: F32 = F43 + Fp - q3, F14 = F43 + q4, F12 = q2 - F32 and
 * T12 = I2 alpha2 + rG2 × q2 - A × F32. No step subtracts two large numbers to get a small one beyond
 * what the equations themselves do, so every result is accurate to a few eps of the largest force (or
 * moment / length) involved, over the inherent 1 / |sin mu| amplification of rounding in the pose and
 * loads. sin mu is formed from the exact difference theta4 - theta3 (TwoSum, or an exact reduction for
 * huge angles), so it keeps full relative accuracy near mu = 0 and pi, where cos3 sin4 - sin3 cos4 would
 * not. Near a toggle the pin forces grow like 1 / |sin mu|; at a limit position (|sin mu| <= LIMIT_SIN_MU,
 * the rule linkRates uses) every field is NaN.
 */
import { TWO_SUM_MAX_RAD, reduceDifference } from './angles';
import type { AngleParts } from './angles';
import type { Point } from './kinematics';
import { LIMIT_SIN_MU, linkRates, sweepRates } from './rates';
import type { InputMotion, SweepRates } from './rates';
import type { Angles, Linkage } from './types';
import { checkFinite, checkObject, describe } from './validate';

/** Mass properties of one link: mass (kg, >= 0), inertia about its CG (kg·m², >= 0) and where the CG sits. */
export interface LinkInertia {
  mass: number;
  inertia: number;
  /**
   * CG from the link's first joint (O2 for the crank, A for the coupler, O4 for the rocker): dist in m
   * (any sign, like a coupler point's pDist) at angle radians counter-clockwise from the link's line
   * (O2→A, A→B, O4→B).
   */
  cg: { dist: number; angle: number };
}

/** The three moving links' mass properties. */
export interface LinkInertias {
  crank: LinkInertia;
  coupler: LinkInertia;
  rocker: LinkInertia;
}

/** External loads, each optional (absent means none). */
export interface Loads {
  /** g in m/s² (>= 0; 0 turns gravity off) pointing at angle radians from +x (default -pi/2: -y). */
  gravity?: { g: number; angle?: number };
  /** A force (fx, fy in N) at the coupler point pDist (m) from A at pAngle (radians) from AB, as couplerPoint. */
  couplerForce?: { pDist: number; pAngle: number; fx: number; fy: number };
  /** A load torque on the rocker from outside the linkage, N·m, counter-clockwise positive. */
  outputTorque?: number;
}

/** Forces at one pose: Fij is the force of link i on link j (N); torques and moments N·m, counter-clockwise +. */
export interface JointForces {
  /**
   * 'ok'; 'limit-position' where the pose is a limit (coupler and rocker in line: the rates, and so the forces, are
   * unbounded; every field NaN); 'overflow' where the rates are finite but a force passes the double range (every
   * field NaN).
   */
  status: 'ok' | 'limit-position' | 'overflow';
  /** T12: torque of the ground (motor) on the crank. */
  torque: number;
  F12: Point;
  F32: Point;
  F43: Point;
  F14: Point;
  /** Force of the linkage on the ground: F21 + F41 = -(F12 + F14). */
  shakingForce: Point;
  /** Moment of the linkage on the ground about O2: -T12 + O2O4 × F41 (the motor's reaction included). */
  shakingMoment: number;
}

/** The fields of JointForces over a sweep (N, N·m), NaN where the point is not ok or at a limit position. */
export interface SweepForces {
  torque: Float64Array;
  f12x: Float64Array;
  f12y: Float64Array;
  f32x: Float64Array;
  f32y: Float64Array;
  f43x: Float64Array;
  f43y: Float64Array;
  f14x: Float64Array;
  f14y: Float64Array;
  shakingX: Float64Array;
  shakingY: Float64Array;
  shakingMoment: Float64Array;
}

const LINKS = ['crank', 'coupler', 'rocker'] as const;

/** Throws unless v is a finite number >= 0. */
function checkNonNegative(name: string, v: unknown, what: string): asserts v is number {
  if (typeof v !== 'number' || !Number.isFinite(v) || v < 0) {
    throw new Error(`${name} must be a non-negative finite ${what}, got ${describe(v)}`);
  }
}

function validateLinkInertia(name: string, v: unknown): asserts v is LinkInertia {
  checkObject(name, v);
  checkNonNegative(`${name}.mass`, v.mass, 'mass in kg');
  checkNonNegative(`${name}.inertia`, v.inertia, 'moment of inertia in kg·m²');
  checkObject(`${name}.cg`, v.cg);
  checkFinite(`${name}.cg.dist`, v.cg.dist, 'length in m');
  checkFinite(`${name}.cg.angle`, v.cg.angle, 'angle in radians');
}

/** Throws an Error naming the field and value unless v is three valid LinkInertia. */
function validateInertias(v: unknown): asserts v is LinkInertias {
  checkObject('inertia', v);
  for (const link of LINKS) validateLinkInertia(`inertia.${link}`, v[link]);
}

/** Throws an Error naming the field and value unless v is a valid Loads. */
function validateLoads(v: unknown): asserts v is Loads {
  checkObject('loads', v);
  const { gravity, couplerForce, outputTorque } = v;
  if (gravity !== undefined) {
    checkObject('loads.gravity', gravity);
    checkNonNegative('loads.gravity.g', gravity.g, 'acceleration in m/s²');
    if (gravity.angle !== undefined) checkFinite('loads.gravity.angle', gravity.angle, 'angle in radians');
  }
  if (couplerForce !== undefined) {
    checkObject('loads.couplerForce', couplerForce);
    checkFinite('loads.couplerForce.pDist', couplerForce.pDist, 'length in m');
    checkFinite('loads.couplerForce.pAngle', couplerForce.pAngle, 'angle in radians');
    checkFinite('loads.couplerForce.fx', couplerForce.fx, 'force in N');
    checkFinite('loads.couplerForce.fy', couplerForce.fy, 'force in N');
  }
  if (outputTorque !== undefined) checkFinite('loads.outputTorque', outputTorque, 'torque in N·m');
}

/**
 * Per-call constants: lengths, each link's mass, inertia and CG as (dist cos angle, dist sin angle) in
 * the link's frame (so the CG's direction is a rotation of the link's, no angle sum), gravity as a vector,
 * the coupler point likewise and its force, and the load torque.
 */
interface ForcePlan {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
  /** [m, I, cg along the link, cg across the link] for crank, coupler, rocker. */
  link: Float64Array;
  gx: number;
  gy: number;
  /** Coupler point along and across AB (m), its force (N); the load torque on the rocker (N·m). */
  pu: number;
  pv: number;
  fx: number;
  fy: number;
  t4: number;
}

function planForces(l: Linkage, inertia: LinkInertias, loads: Loads): ForcePlan {
  const link = new Float64Array(12);
  LINKS.forEach((name, k) => {
    const { mass, inertia: i, cg } = inertia[name];
    link.set([mass, i, cg.dist * Math.cos(cg.angle), cg.dist * Math.sin(cg.angle)], 4 * k);
  });
  const g = loads.gravity?.g ?? 0;
  const gAngle = loads.gravity?.angle;
  // The default direction is -y exactly (cos(-pi/2) would leave a 6e-17 g sideways component).
  const gx = gAngle === undefined ? 0 : g * Math.cos(gAngle);
  const gy = gAngle === undefined ? -g : g * Math.sin(gAngle);
  const p = loads.couplerForce;
  return {
    r1: l.r1,
    r2: l.r2,
    r3: l.r3,
    r4: l.r4,
    link,
    gx,
    gy,
    pu: p ? p.pDist * Math.cos(p.pAngle) : 0,
    pv: p ? p.pDist * Math.sin(p.pAngle) : 0,
    fx: p ? p.fx : 0,
    fy: p ? p.fy : 0,
    t4: loads.outputTorque ?? 0,
  };
}

const parts: AngleParts = { hi: 0, lo: 0 };

// Module-local copies of imports read per point: loaders that turn imports into getters (vite-node) would
// otherwise call a getter on every read (as in rates.ts).
const SMALL_ANGLE = TWO_SUM_MAX_RAD;
const reduce = reduceDifference;
const LIMIT = LIMIT_SIN_MU;

/** sin(b - a) of the exact difference, to full relative accuracy also near 0 and pi (see angles.ts). */
function sinOfDifference(b: number, a: number): number {
  let hi: number;
  let lo: number;
  if (Math.abs(a) <= SMALL_ANGLE && Math.abs(b) <= SMALL_ANGLE) {
    hi = b - a;
    const bb = hi - b;
    lo = b - (hi - bb) - (a + bb);
  } else {
    reduce(b, a, parts);
    hi = parts.hi;
    lo = parts.lo;
  }
  return Math.sin(hi) + Math.cos(hi) * lo;
}

/**
 * Link k's inertia-minus-weight load q = m (a_G - g) and I alpha + rG × q (its moment about the link's
 * first joint), written to out as [qx, qy, moment]. The joint moves with acceleration (ax, ay); the link
 * points along (c, s) and turns at rate w with acceleration a; the CG's offset in the link's frame is the plan's.
 */
function linkLoad(
  p: ForcePlan,
  k: number,
  c: number,
  s: number,
  w: number,
  a: number,
  ax: number,
  ay: number,
  out: Float64Array,
): void {
  const L = p.link;
  const m = L[4 * k];
  const rx = c * L[4 * k + 2] - s * L[4 * k + 3];
  const ry = s * L[4 * k + 2] + c * L[4 * k + 3];
  // a_G = a_joint + alpha k × rG - omega^2 rG, omega^2 rG as (omega rG) omega: omega^2 alone can overflow.
  const qx = m * (ax - a * ry - w * rx * w - p.gx);
  const qy = m * (ay + a * rx - w * ry * w - p.gy);
  out[0] = qx;
  out[1] = qy;
  out[2] = L[4 * k + 1] * a + (rx * qy - ry * qx);
}

const q2 = new Float64Array(3);
const q3 = new Float64Array(3);
const q4 = new Float64Array(3);

/** Writes NaN to every field at index i. */
function nanInto(out: SweepForces, i: number): void {
  out.torque[i] = out.f12x[i] = out.f12y[i] = out.f32x[i] = out.f32y[i] = out.f43x[i] = NaN;
  out.f43y[i] = out.f14x[i] = out.f14y[i] = out.shakingX[i] = out.shakingY[i] = out.shakingMoment[i] = NaN;
}

/** The forces at one pose with its rates (see the module comment), written to index i of out. */
function forcesInto(
  p: ForcePlan,
  t2: number,
  t3: number,
  t4: number,
  w2: number,
  a2: number,
  r: SweepRates,
  i: number,
  out: SweepForces,
): void {
  const s = sinOfDifference(t4, t3);
  if (!(Math.abs(s) > LIMIT)) return nanInto(out, i);
  const c2 = Math.cos(t2);
  const s2 = Math.sin(t2);
  const c3 = Math.cos(t3);
  const s3 = Math.sin(t3);
  const c4 = Math.cos(t4);
  const s4 = Math.sin(t4);
  const ax = p.r2 * c2;
  const ay = p.r2 * s2;
  linkLoad(p, 0, c2, s2, w2, a2, 0, 0, q2);
  // Acceleration of A: alpha2 k × O2A - omega2^2 O2A.
  linkLoad(p, 1, c3, s3, r.omega3[i], r.alpha3[i], -a2 * ay - w2 * ax * w2, a2 * ax - w2 * ay * w2, q3);
  linkLoad(p, 2, c4, s4, r.omega4[i], r.alpha4[i], 0, 0, q4);
  // Coupler point P from A, and the moments M3 (coupler about A) and M4 (rocker about O4).
  const px = c3 * p.pu - s3 * p.pv;
  const py = s3 * p.pu + c3 * p.pv;
  const m3 = q3[2] - (px * p.fy - py * p.fx);
  const m4 = q4[2] - p.t4;
  const k3 = m3 / p.r3 / s;
  const k4 = m4 / p.r4 / s;
  const f43x = k3 * c4 + k4 * c3;
  const f43y = k3 * s4 + k4 * s3;
  const f32x = f43x + p.fx - q3[0];
  const f32y = f43y + p.fy - q3[1];
  const f14x = f43x + q4[0];
  const f14y = f43y + q4[1];
  const f12x = q2[0] - f32x;
  const f12y = q2[1] - f32y;
  const torque = q2[2] - (ax * f32y - ay * f32x);
  out.torque[i] = torque;
  out.f12x[i] = f12x;
  out.f12y[i] = f12y;
  out.f32x[i] = f32x;
  out.f32y[i] = f32y;
  out.f43x[i] = f43x;
  out.f43y[i] = f43y;
  out.f14x[i] = f14x;
  out.f14y[i] = f14y;
  out.shakingX[i] = -(f12x + f14x);
  out.shakingY[i] = -(f12y + f14y);
  out.shakingMoment[i] = -torque - p.r1 * f14y;
}

const FIELDS = [
  'torque',
  'f12x',
  'f12y',
  'f32x',
  'f32y',
  'f43x',
  'f43y',
  'f14x',
  'f14y',
  'shakingX',
  'shakingY',
  'shakingMoment',
] as const;

/** The twelve arrays of a sweep, views of one buffer. */
function allocateForces(n: number): SweepForces {
  const buffer = new ArrayBuffer(8 * n * FIELDS.length);
  const entries = FIELDS.map((f, k) => [f, new Float64Array(buffer, 8 * n * k, n)]);
  return Object.fromEntries(entries) as SweepForces;
}

const single = allocateForces(1);
const singleRates: SweepRates = {
  omega3: new Float64Array(1),
  omega4: new Float64Array(1),
  alpha3: new Float64Array(1),
  alpha4: new Float64Array(1),
};

/**
 * Input torque T12, pin forces and shaking force and moment (SI: N, N·m) at theta2 (radians) and the
 * solved pose, for the input crank motion (rad/s, rad/s²), the links' mass properties and the loads;
 * the rates come from linkRates and the pose's angles are taken as exact. Pin forces grow like
 * 1 / |sin mu| near a toggle; at a limit position (|sin mu| <= LIMIT_SIN_MU) every field is NaN.
 * Throws an Error naming the field and value for a bad linkage, theta2, pose, input, inertia or loads.
 */
export function linkForces(
  l: Linkage,
  theta2: number,
  pose: Angles,
  input: InputMotion,
  inertia: LinkInertias,
  loads: Loads,
): JointForces {
  const rates = linkRates(l, theta2, pose, input);
  validateInertias(inertia);
  validateLoads(loads);
  singleRates.omega3[0] = rates.omega3;
  singleRates.omega4[0] = rates.omega4;
  singleRates.alpha3[0] = rates.alpha3;
  singleRates.alpha4[0] = rates.alpha4;
  const p = planForces(l, inertia, loads);
  forcesInto(p, theta2, pose.theta3, pose.theta4, input.omega2, input.alpha2, singleRates, 0, single);
  const f = single;
  const fields = [f.torque, f.f12x, f.f12y, f.f32x, f.f32y, f.f43x, f.f43y, f.f14x, f.f14y];
  const finite = fields.every((a) => Number.isFinite(a[0]));
  const ratesFinite = [rates.omega3, rates.omega4, rates.alpha3, rates.alpha4].every(Number.isFinite);
  const status = finite ? 'ok' : ratesFinite ? 'overflow' : 'limit-position';
  const x = (v: number) => (finite ? v : NaN);
  return {
    status,
    torque: x(f.torque[0]),
    F12: { x: x(f.f12x[0]), y: x(f.f12y[0]) },
    F32: { x: x(f.f32x[0]), y: x(f.f32y[0]) },
    F43: { x: x(f.f43x[0]), y: x(f.f43y[0]) },
    F14: { x: x(f.f14x[0]), y: x(f.f14y[0]) },
    shakingForce: { x: x(f.shakingX[0]), y: x(f.shakingY[0]) },
    shakingMoment: x(f.shakingMoment[0]),
  };
}

/**
 * linkForces along a sweep, in one pass after sweepRates: theta2, theta3, theta4 in radians (arrays of
 * equal length), ok(i) says which points hold a solved pose. Returns Float64Arrays (N, N·m), NaN where
 * ok(i) is false or the pose is a limit position; each value equals linkForces at that point. Throws as
 * sweepRates does, and an Error naming the field for bad inertia or loads.
 */
export function sweepForces(
  l: Linkage,
  theta2: ArrayLike<number>,
  theta3: ArrayLike<number>,
  theta4: ArrayLike<number>,
  ok: (i: number) => boolean,
  input: InputMotion,
  inertia: LinkInertias,
  loads: Loads,
): SweepForces {
  const rates = sweepRates(l, theta2, theta3, theta4, ok, input);
  validateInertias(inertia);
  validateLoads(loads);
  const p = planForces(l, inertia, loads);
  const n = theta2.length;
  const out = allocateForces(n);
  const { omega2, alpha2 } = input;
  for (let i = 0; i < n; i++) {
    // sweepRates has checked the angles of every ok point; its NaN rates mark the rest.
    if (Number.isNaN(rates.omega3[i])) nanInto(out, i);
    else forcesInto(p, theta2[i], theta3[i], theta4[i], omega2, alpha2, rates, i, out);
  }
  return out;
}
