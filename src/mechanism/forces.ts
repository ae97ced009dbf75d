/**
 * Kinetostatics of any mobility-1 linkage by Lagrange multipliers: with the constraint Jacobian J of the sweep
 * (the input's row included) and the generalized coordinates (x, y, phi) of each link's frame, the equations of
 * motion M q'' = Q + Jᵀ λ give the multipliers from one transposed solve at each pose,
 *
 *   Jᵀ λ = G,   G_k = ( m_k (a_Gk - g) - Σ F,   I_k phi_k'' + r_k × m_k (a_Gk - g) - Σ r_p × F - T_k )
 *
 * (r_k from the frame to the CG, r_p to where a force F acts; T_k an applied torque). A joint's multipliers are
 * its reaction: for an R joint (λ_x, λ_y) is the force on links[0] from links[1]; for a P joint λ_1 n is that
 * force (normal to the slide) and λ_2 the couple; the input row's multiplier is the driver's torque on links[1]
 * from links[0] (R) or force on the block along the slide (P). Lengths are scaled inside the solver: with
 * S_c = diag(L on positions) and S_r = diag(L on length rows), Jᵀ (S_r λ) = S_c G in scaled coordinates.
 */
import { describe } from '../solver/validate';
import { luSolveTransposed } from './lu';
import { buildModel } from './model';
import { sweepWith } from './sweep';
import type { PoseHook } from './sweep';
import type { MechanismSpec } from './types';
import { GROUND } from './validate';

/** A link's mass (kg), inertia about its CG (kg·m²) and where its CG is in the drawn configuration (m). */
export interface LinkMass {
  mass: number;
  inertia: number;
  x: number;
  y: number;
}

/** Applied loads, each optional: gravity (m/s², default direction -y), torques on links (N·m), point forces. */
export interface MechanismLoads {
  gravity?: { g: number; angle?: number };
  torques?: Record<string, number>;
  /** A force (N, fixed in the world) at a point of a link given in the drawn configuration. */
  forces?: Array<{ link: string; x: number; y: number; fx: number; fy: number }>;
}

/** Forces along a sweep (N, N·m), NaN where the pose is not assembled. */
export interface MechanismForces {
  ok: Uint8Array;
  /** The driver: torque on the input joint's links[1] from links[0] (R), or force on the block along the slide (P). */
  input: Float64Array;
  /** Each joint's reaction on links[0] from links[1]: force (fx, fy) and, for a P joint, the couple m. */
  joints: Record<string, { fx: Float64Array; fy: Float64Array; m: Float64Array }>;
}

function finite(name: string, v: unknown, nonNegative = false): void {
  if (typeof v !== 'number' || !Number.isFinite(v) || (nonNegative && v < 0)) {
    throw new Error(`${name} must be a ${nonNegative ? 'non-negative ' : ''}finite number, got ${describe(v)}`);
  }
}

/**
 * The driver's effort and every joint's reaction along a sweep, for the input's rate and acceleration (rad/s,
 * rad/s² or m/s, m/s²), the moving links' masses (a link left out is massless) and the loads. SI units.
 * Throws as sweepMechanism does, and an Error naming the link or field for bad masses or loads.
 */
export function mechanismForces(
  spec: MechanismSpec,
  inputs: ArrayLike<number>,
  motion: { omega: number; alpha: number },
  masses: Record<string, LinkMass>,
  loads: MechanismLoads = {},
): MechanismForces {
  // Validates spec and motion (buildModel needs a valid spec).
  sweepWith(spec, [], motion, true);
  const model = buildModel(spec);
  const { n, scale: L, linkNames } = model;
  const m = linkNames.length;
  const mass = new Float64Array(m);
  const inertia = new Float64Array(m);
  const cgx = new Float64Array(m);
  const cgy = new Float64Array(m);
  for (const [name, v] of Object.entries(masses)) {
    const k = linkNames.indexOf(name);
    if (k < 0)
      throw new Error(
        `masses: unknown moving link ${describe(name)}${name === GROUND ? ' (the ground does not move)' : ''}`,
      );
    finite(`masses.${name}.mass`, v.mass, true);
    finite(`masses.${name}.inertia`, v.inertia, true);
    finite(`masses.${name}.x`, v.x);
    finite(`masses.${name}.y`, v.y);
    mass[k] = v.mass;
    inertia[k] = v.inertia;
    cgx[k] = v.x / L - model.cx[k];
    cgy[k] = v.y / L - model.cy[k];
  }
  const g = loads.gravity?.g ?? 0;
  finite('loads.gravity.g', g, true);
  if (loads.gravity?.angle !== undefined) finite('loads.gravity.angle', loads.gravity.angle);
  const gx = loads.gravity?.angle === undefined ? 0 : g * Math.cos(loads.gravity.angle);
  const gy = loads.gravity?.angle === undefined ? -g : g * Math.sin(loads.gravity.angle);
  const torque = new Float64Array(m);
  for (const [name, t] of Object.entries(loads.torques ?? {})) {
    const k = linkNames.indexOf(name);
    if (k < 0) throw new Error(`loads.torques: unknown moving link ${describe(name)}`);
    finite(`loads.torques.${name}`, t);
    torque[k] = t;
  }
  const forces = (loads.forces ?? []).map((f, i) => {
    const k = linkNames.indexOf(f.link);
    if (k < 0) throw new Error(`loads.forces[${i}].link: unknown moving link ${describe(f.link)}`);
    for (const key of ['x', 'y', 'fx', 'fy'] as const) finite(`loads.forces[${i}].${key}`, f[key]);
    return { k, ux: f.x / L - model.cx[k], uy: f.y / L - model.cy[k], fx: f.fx, fy: f.fy };
  });
  const count = inputs.length;
  const nan = () => new Float64Array(count).fill(NaN);
  const out: MechanismForces = { ok: new Uint8Array(count), input: nan(), joints: {} };
  for (const id of model.jointIds) out.joints[id] = { fx: nan(), fy: nan(), m: nan() };
  const rhs = new Float64Array(n);
  const hook: PoseHook = (i, ws, qd, qdd) => {
    const tr = ws.tr;
    for (let k = 0; k < m; k++) {
      const c = tr.c[k];
      const s = tr.s[k];
      // The CG's arm from the frame (physical) and its acceleration a = x'' + phi'' k × r - phi'^2 r.
      const rx = (c * cgx[k] - s * cgy[k]) * L;
      const ry = (s * cgx[k] + c * cgy[k]) * L;
      const w = qd[3 * k + 2];
      const al = qdd[3 * k + 2];
      const ax = qdd[3 * k] * L - al * ry - w * w * rx;
      const ay = qdd[3 * k + 1] * L + al * rx - w * w * ry;
      const fx = mass[k] * (ax - gx);
      const fy = mass[k] * (ay - gy);
      rhs[3 * k] = fx * L;
      rhs[3 * k + 1] = fy * L;
      rhs[3 * k + 2] = inertia[k] * al + (rx * fy - ry * fx) - torque[k];
    }
    for (const f of forces) {
      const c = tr.c[f.k];
      const s = tr.s[f.k];
      const rx = (c * f.ux - s * f.uy) * L;
      const ry = (s * f.ux + c * f.uy) * L;
      rhs[3 * f.k] -= f.fx * L;
      rhs[3 * f.k + 1] -= f.fy * L;
      rhs[3 * f.k + 2] -= rx * f.fy - ry * f.fx;
    }
    luSolveTransposed(ws.jac, n, ws.perm, rhs, ws.tmp);
    model.jointIds.forEach((id, j) => {
      const o = out.joints[id];
      if (model.kind[j] === 0) {
        o.fx[i] = rhs[2 * j] / L;
        o.fy[i] = rhs[2 * j + 1] / L;
        o.m[i] = 0;
        return;
      }
      // n · D row (length): λ1 n is the force on the block; the rotation row (angle) is the couple.
      const b = model.lb[j];
      const cb = b >= 0 ? tr.c[b] : 1;
      const sb = b >= 0 ? tr.s[b] : 0;
      const dx = cb * model.dgx[j] - sb * model.dgy[j];
      const dy = sb * model.dgx[j] + cb * model.dgy[j];
      const lam = rhs[2 * j] / L;
      o.fx[i] = -dy * lam;
      o.fy[i] = dx * lam;
      o.m[i] = rhs[2 * j + 1];
    });
    out.input[i] = model.kind[model.input] === 0 ? rhs[n - 1] : rhs[n - 1] / L;
  };
  const r = sweepWith(spec, inputs, motion, true, hook);
  out.ok = r.ok;
  return out;
}
