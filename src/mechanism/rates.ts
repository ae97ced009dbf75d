/**
 * The acceleration's right-hand side. Differentiating F(q, t) = 0 twice in time gives J q'' = rhs, where rhs holds
 * the input's acceleration and the terms quadratic in the rates (docs/mechanism.md):
 *
 *   R joint:   rhs = r_a phi_a'^2 - r_b phi_b'^2                           (r: the rotated arm R(phi) u)
 *   P joint:   rhs = phi_b'^2 (n · D) + 2 phi_b' (d · D') + n · (r_a phi_a'^2 - r_b phi_b'^2),   0
 *   input R:   rhs = alpha         input P: rhs = alpha + phi_b'^2 (d · D) - 2 phi_b' (n · D') + d · (r_a phi_a'^2 - r_b phi_b'^2)
 *
 * with D' = v_a - v_b the joint's relative velocity and v = x' + phi' k × r.
 */
import type { Model, Trig } from './model';

/** Writes the acceleration right-hand side for pose q and rates qd (scaled lengths, rad) into rhs. */
export function accelerationRhs(
  model: Model,
  q: Float64Array,
  qd: Float64Array,
  tr: Trig,
  alpha: number,
  rhs: Float64Array,
): void {
  const { n, kind, la, lb, uax, uay, ubx, uby, dgx, dgy } = model;
  const nj = kind.length;
  for (let i = 0; i < nj; i++) {
    const a = la[i];
    const b = lb[i];
    let rax = uax[i];
    let ray = uay[i];
    let wa = 0;
    let vax = 0;
    let vay = 0;
    let pax = rax;
    let pay = ray;
    if (a >= 0) {
      const c = tr.c[a];
      const s = tr.s[a];
      rax = c * uax[i] - s * uay[i];
      ray = s * uax[i] + c * uay[i];
      wa = qd[3 * a + 2];
      vax = qd[3 * a] - ray * wa;
      vay = qd[3 * a + 1] + rax * wa;
      pax = q[3 * a] + rax;
      pay = q[3 * a + 1] + ray;
    }
    let rbx = ubx[i];
    let rby = uby[i];
    let wb = 0;
    let vbx = 0;
    let vby = 0;
    let pbx = rbx;
    let pby = rby;
    let cb = 1;
    let sb = 0;
    if (b >= 0) {
      cb = tr.c[b];
      sb = tr.s[b];
      rbx = cb * ubx[i] - sb * uby[i];
      rby = sb * ubx[i] + cb * uby[i];
      wb = qd[3 * b + 2];
      vbx = qd[3 * b] - rby * wb;
      vby = qd[3 * b + 1] + rbx * wb;
      pbx = q[3 * b] + rbx;
      pby = q[3 * b + 1] + rby;
    }
    // Centripetal terms r phi'^2, formed as (r phi') phi' so large rates cannot overflow early.
    const cx = rax * wa * wa - rbx * wb * wb;
    const cy = ray * wa * wa - rby * wb * wb;
    if (kind[i] === 0) {
      rhs[2 * i] = cx;
      rhs[2 * i + 1] = cy;
      continue;
    }
    const dx = cb * dgx[i] - sb * dgy[i];
    const dy = sb * dgx[i] + cb * dgy[i];
    const nx = -dy;
    const ny = dx;
    const ddx = pax - pbx;
    const ddy = pay - pby;
    const rvx = vax - vbx;
    const rvy = vay - vby;
    rhs[2 * i] = wb * wb * (nx * ddx + ny * ddy) + 2 * wb * (dx * rvx + dy * rvy) + nx * cx + ny * cy;
    rhs[2 * i + 1] = 0;
    if (i === model.input) {
      rhs[n - 1] = alpha + wb * wb * (dx * ddx + dy * ddy) - 2 * wb * (nx * rvx + ny * rvy) + dx * cx + dy * cy;
    }
  }
  if (kind[model.input] === 0) rhs[n - 1] = alpha;
}
