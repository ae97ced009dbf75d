/**
 * The constraint model: every moving link k has a pose q[3k..3k+2] = (x, y, phi), the position (divided by the
 * spec's scale) of a frame fixed in the link, placed at the centroid of its joints as drawn, and its rotation from
 * the drawn configuration. The drawn configuration is q0 = (centroid, 0) for every link, where every constraint
 * holds by construction. Each joint adds two equations, the input one (docs/mechanism.md):
 *
 *   R joint (links a, b), point u_a on a, u_b on b:  x_a + R(phi_a) u_a - x_b - R(phi_b) u_b = 0
 *   P joint (block a, guide b), direction d = R(phi_b) d_g, normal n = (-d_y, d_x), D = P_a - P_b:
 *                                                    n · D = 0 and phi_a - phi_b = 0
 *   input R: phi_b - phi_a - t = 0          input P: d · D - t = 0
 *
 * The ground is link -1, at rest with the identity pose.
 */
import { GROUND } from './validate';
import type { MechanismSpec } from './types';

/** The compiled spec: flat typed arrays the solver reads per iteration. */
export interface Model {
  /** Moving links, in spec order without the ground. */
  linkNames: string[];
  /** Unknowns: 3 per moving link; equals the number of equations (mobility 1). */
  n: number;
  /** Lengths are divided by scale (a power of two, exact) inside the solver. */
  scale: number;
  jointIds: string[];
  /** 0 R, 1 P. */
  kind: Uint8Array;
  la: Int32Array;
  lb: Int32Array;
  /** Joint point in link a's and link b's frames (scaled); a P joint's guide direction in b's frame. */
  uax: Float64Array;
  uay: Float64Array;
  ubx: Float64Array;
  uby: Float64Array;
  dgx: Float64Array;
  dgy: Float64Array;
  /** The input joint's index. */
  input: number;
  /** Centroids (scaled): the drawn pose. */
  cx: Float64Array;
  cy: Float64Array;
  pointIds: string[];
  pl: Int32Array;
  pux: Float64Array;
  puy: Float64Array;
}

/** The power of two nearest the spec's extent (so squares neither overflow nor underflow; scaling is exact). */
function scaleOf(spec: MechanismSpec): number {
  let minX = Infinity;
  let maxX = -Infinity;
  let minY = Infinity;
  let maxY = -Infinity;
  for (const j of spec.joints) {
    minX = Math.min(minX, j.x);
    maxX = Math.max(maxX, j.x);
    minY = Math.min(minY, j.y);
    maxY = Math.max(maxY, j.y);
  }
  const extent = Math.max(maxX - minX, maxY - minY, Math.abs(minX), Math.abs(maxX), Math.abs(minY), Math.abs(maxY));
  if (!(extent > 0) || !Number.isFinite(extent)) return 1;
  return 2 ** Math.round(Math.log2(extent));
}

/** Compiles a validated spec. */
export function buildModel(spec: MechanismSpec): Model {
  const scale = scaleOf(spec);
  const linkNames = spec.links.filter((l) => l !== GROUND);
  const index = new Map(linkNames.map((l, k) => [l, k]));
  index.set(GROUND, -1);
  const m = linkNames.length;
  const cx = new Float64Array(m);
  const cy = new Float64Array(m);
  const count = new Float64Array(m);
  for (const j of spec.joints) {
    for (const l of j.links) {
      const k = index.get(l)!;
      if (k < 0) continue;
      cx[k] += j.x / scale;
      cy[k] += j.y / scale;
      count[k]++;
    }
  }
  for (let k = 0; k < m; k++) {
    cx[k] /= count[k];
    cy[k] /= count[k];
  }
  const nj = spec.joints.length;
  const model: Model = {
    linkNames,
    n: 3 * m,
    scale,
    jointIds: spec.joints.map((j) => j.id),
    kind: new Uint8Array(nj),
    la: new Int32Array(nj),
    lb: new Int32Array(nj),
    uax: new Float64Array(nj),
    uay: new Float64Array(nj),
    ubx: new Float64Array(nj),
    uby: new Float64Array(nj),
    dgx: new Float64Array(nj),
    dgy: new Float64Array(nj),
    input: spec.joints.findIndex((j) => j.id === spec.input.joint),
    cx,
    cy,
    pointIds: (spec.points ?? []).map((p) => p.id),
    pl: new Int32Array((spec.points ?? []).map((p) => index.get(p.link)!)),
    pux: new Float64Array(
      (spec.points ?? []).map((p) => p.x / scale - (index.get(p.link)! < 0 ? 0 : cx[index.get(p.link)!])),
    ),
    puy: new Float64Array(
      (spec.points ?? []).map((p) => p.y / scale - (index.get(p.link)! < 0 ? 0 : cy[index.get(p.link)!])),
    ),
  };
  spec.joints.forEach((j, i) => {
    const a = index.get(j.links[0])!;
    const b = index.get(j.links[1])!;
    const x = j.x / scale;
    const y = j.y / scale;
    model.kind[i] = j.kind === 'P' ? 1 : 0;
    model.la[i] = a;
    model.lb[i] = b;
    model.uax[i] = a < 0 ? x : x - cx[a];
    model.uay[i] = a < 0 ? y : y - cy[a];
    model.ubx[i] = b < 0 ? x : x - cx[b];
    model.uby[i] = b < 0 ? y : y - cy[b];
    if (j.kind === 'P') {
      model.dgx[i] = Math.cos(j.angle!);
      model.dgy[i] = Math.sin(j.angle!);
    }
  });
  return model;
}

/** Per-evaluation scratch: each link's cos and sin of phi. */
export interface Trig {
  c: Float64Array;
  s: Float64Array;
}

export function newTrig(m: number): Trig {
  return { c: new Float64Array(m), s: new Float64Array(m) };
}

/** Fills t with cos and sin of every link's phi. */
export function trigOf(model: Model, q: Float64Array, t: Trig): void {
  const m = model.linkNames.length;
  for (let k = 0; k < m; k++) {
    const phi = q[3 * k + 2];
    t.c[k] = Math.cos(phi);
    t.s[k] = Math.sin(phi);
  }
}

/**
 * The constraint residual F(q, t) (length n) and, when jac is given, its Jacobian dF/dq (n×n, row-major, fully
 * written). Rows 2i, 2i + 1 are joint i's; row n - 1 is the input's. t: the input (rad, or scaled length).
 */
export function evaluate(
  model: Model,
  q: Float64Array,
  inputValue: number,
  tr: Trig,
  f: Float64Array,
  jac: Float64Array | null,
): void {
  const { n, kind, la, lb, uax, uay, ubx, uby, dgx, dgy } = model;
  const nj = kind.length;
  if (jac) jac.fill(0);
  const tc = tr.c;
  const ts = tr.s;
  for (let i = 0; i < nj; i++) {
    const a = la[i];
    const b = lb[i];
    let rax = uax[i];
    let ray = uay[i];
    let pax = rax;
    let pay = ray;
    let phia = 0;
    if (a >= 0) {
      const c = tc[a];
      const s = ts[a];
      rax = c * uax[i] - s * uay[i];
      ray = s * uax[i] + c * uay[i];
      pax = q[3 * a] + rax;
      pay = q[3 * a + 1] + ray;
      phia = q[3 * a + 2];
    }
    let rbx = ubx[i];
    let rby = uby[i];
    let pbx = rbx;
    let pby = rby;
    let phib = 0;
    let cb = 1;
    let sb = 0;
    if (b >= 0) {
      cb = tc[b];
      sb = ts[b];
      rbx = cb * ubx[i] - sb * uby[i];
      rby = sb * ubx[i] + cb * uby[i];
      pbx = q[3 * b] + rbx;
      pby = q[3 * b + 1] + rby;
      phib = q[3 * b + 2];
    }
    const r0 = 2 * i * n;
    const r1 = r0 + n;
    if (kind[i] === 0) {
      f[2 * i] = pax - pbx;
      f[2 * i + 1] = pay - pby;
      if (jac) {
        if (a >= 0) {
          jac[r0 + 3 * a] = 1;
          jac[r0 + 3 * a + 2] = -ray;
          jac[r1 + 3 * a + 1] = 1;
          jac[r1 + 3 * a + 2] = rax;
        }
        if (b >= 0) {
          jac[r0 + 3 * b] = -1;
          jac[r0 + 3 * b + 2] = rby;
          jac[r1 + 3 * b + 1] = -1;
          jac[r1 + 3 * b + 2] = -rbx;
        }
      }
    } else {
      const dx = cb * dgx[i] - sb * dgy[i];
      const dy = sb * dgx[i] + cb * dgy[i];
      const nx = -dy;
      const ny = dx;
      const ddx = pax - pbx;
      const ddy = pay - pby;
      f[2 * i] = nx * ddx + ny * ddy;
      f[2 * i + 1] = phia - phib;
      if (jac) {
        if (a >= 0) {
          jac[r0 + 3 * a] = nx;
          jac[r0 + 3 * a + 1] = ny;
          jac[r0 + 3 * a + 2] = ny * rax - nx * ray;
          jac[r1 + 3 * a + 2] = 1;
        }
        if (b >= 0) {
          jac[r0 + 3 * b] = -nx;
          jac[r0 + 3 * b + 1] = -ny;
          jac[r0 + 3 * b + 2] = -(dx * ddx + dy * ddy) - (ny * rbx - nx * rby);
          jac[r1 + 3 * b + 2] = -1;
        }
      }
    }
  }
  inputRow(model, q, inputValue, tr, f, jac);
}

/** The input's residual (row n - 1) and its Jacobian row. */
function inputRow(
  model: Model,
  q: Float64Array,
  inputValue: number,
  tr: Trig,
  f: Float64Array,
  jac: Float64Array | null,
): void {
  const { n } = model;
  const i = model.input;
  const a = model.la[i];
  const b = model.lb[i];
  const row = (n - 1) * n;
  if (model.kind[i] === 0) {
    f[n - 1] = (b >= 0 ? q[3 * b + 2] : 0) - (a >= 0 ? q[3 * a + 2] : 0) - inputValue;
    if (jac) {
      if (b >= 0) jac[row + 3 * b + 2] = 1;
      if (a >= 0) jac[row + 3 * a + 2] = -1;
    }
    return;
  }
  const s = sliderState(model, q, tr, i);
  f[n - 1] = s.dx * s.ddx + s.dy * s.ddy - inputValue;
  if (!jac) return;
  if (a >= 0) {
    jac[row + 3 * a] = s.dx;
    jac[row + 3 * a + 1] = s.dy;
    jac[row + 3 * a + 2] = s.dy * s.rax - s.dx * s.ray;
  }
  if (b >= 0) {
    jac[row + 3 * b] = -s.dx;
    jac[row + 3 * b + 1] = -s.dy;
    jac[row + 3 * b + 2] = -s.dy * s.ddx + s.dx * s.ddy - (s.dy * s.rbx - s.dx * s.rby);
  }
}

/** A P joint's geometry at q (scratch object, overwritten by each call). */
export interface SliderState {
  dx: number;
  dy: number;
  ddx: number;
  ddy: number;
  rax: number;
  ray: number;
  rbx: number;
  rby: number;
}

const slider: SliderState = { dx: 0, dy: 0, ddx: 0, ddy: 0, rax: 0, ray: 0, rbx: 0, rby: 0 };

/** Joint i's block and guide arms r_a, r_b (rotated local points), separation D and direction d at q. */
export function sliderState(model: Model, q: Float64Array, tr: Trig, i: number): SliderState {
  const a = model.la[i];
  const b = model.lb[i];
  const ca = a >= 0 ? tr.c[a] : 1;
  const sa = a >= 0 ? tr.s[a] : 0;
  const cb = b >= 0 ? tr.c[b] : 1;
  const sb = b >= 0 ? tr.s[b] : 0;
  const rax = ca * model.uax[i] - sa * model.uay[i];
  const ray = sa * model.uax[i] + ca * model.uay[i];
  const rbx = cb * model.ubx[i] - sb * model.uby[i];
  const rby = sb * model.ubx[i] + cb * model.uby[i];
  slider.rax = rax;
  slider.ray = ray;
  slider.rbx = rbx;
  slider.rby = rby;
  slider.ddx = (a >= 0 ? q[3 * a] : 0) + rax - (b >= 0 ? q[3 * b] : 0) - rbx;
  slider.ddy = (a >= 0 ? q[3 * a + 1] : 0) + ray - (b >= 0 ? q[3 * b + 1] : 0) - rby;
  slider.dx = cb * model.dgx[i] - sb * model.dgy[i];
  slider.dy = sb * model.dgx[i] + cb * model.dgy[i];
  return slider;
}
