/**
 * The fast path: a linkage driven at a ground pivot whose other links fall into RRR dyads solved one after
 * another (an Assur decomposition into groups of class II, kind RRR) is posed in closed form, two circle
 * intersections' worth of arithmetic per dyad, with no iteration. Each dyad keeps the side it is drawn on: a
 * dyad changes side only through a flat (singular) configuration, which the Newton continuation refuses to
 * cross as well, so both paths follow the same branch. Linkages with P joints, a floating input or a group of
 * higher class (a triad such as Stephenson II's) return null from planDyads and go to Newton.
 */
import type { Model } from './model';

/** The decomposition: the input link and the dyads in solving order. */
export interface DyadPlan {
  inputLink: number;
  /** +1 when the input link is links[1] of the input joint (it turns by +t), -1 when it is links[0]. */
  inputSign: number;
  /** The input pivot (scaled, on the ground) and its point in the input link's frame. */
  px: number;
  py: number;
  ux: number;
  uy: number;
  count: number;
  /** Known links carrying the dyad's outer joints (-1 ground) and the joints' points in their frames. */
  kA: Int32Array;
  aX: Float64Array;
  aY: Float64Array;
  kB: Int32Array;
  bX: Float64Array;
  bY: Float64Array;
  /** The dyad's two links (l1 at the outer joint A, l2 at B), arm lengths |J - A|, |J - B|, the drawn side. */
  l1: Int32Array;
  l2: Int32Array;
  r1: Float64Array;
  r2: Float64Array;
  side: Float64Array;
  /** The outer joint's point in l1's / l2's frame and the drawn angle of A → J / B → J. */
  u1x: Float64Array;
  u1y: Float64Array;
  ang1: Float64Array;
  u2x: Float64Array;
  u2y: Float64Array;
  ang2: Float64Array;
}

/** Joint i's point in link k's frame (k is one of its two links). */
function localOn(model: Model, i: number, k: number): [number, number] {
  return model.la[i] === k ? [model.uax[i], model.uay[i]] : [model.ubx[i], model.uby[i]];
}

/** The drawn world position of joint i (frames are at their centroids, unrotated, in the drawn pose). */
function drawnPoint(model: Model, i: number): [number, number] {
  const a = model.la[i];
  return a < 0 ? [model.uax[i], model.uay[i]] : [model.cx[a] + model.uax[i], model.cy[a] + model.uay[i]];
}

/** The dyad decomposition of model, or null when the linkage is not a chain of RRR dyads on a ground input. */
export function planDyads(model: Model): DyadPlan | null {
  const nj = model.kind.length;
  const m = model.linkNames.length;
  if (model.kind.some((k) => k !== 0)) return null;
  const inp = model.input;
  let inputLink: number;
  let inputSign: number;
  if (model.la[inp] === -1 && model.lb[inp] >= 0) {
    inputLink = model.lb[inp];
    inputSign = 1;
  } else if (model.lb[inp] === -1 && model.la[inp] >= 0) {
    inputLink = model.la[inp];
    inputSign = -1;
  } else return null;
  const known = new Set<number>([-1, inputLink]);
  const used = new Set<number>([inp]);
  const other = (i: number, k: number) => (model.la[i] === k ? model.lb[i] : model.la[i]);
  /** An unused joint of link k (other than skip) to a known link. */
  const anchor = (k: number, skip: number): number => {
    for (let i = 0; i < nj; i++) {
      if (i === skip || used.has(i)) continue;
      if ((model.la[i] === k || model.lb[i] === k) && known.has(other(i, k))) return i;
    }
    return -1;
  };
  const dyads: Array<{ j: number; a: number; b: number; l1: number; l2: number }> = [];
  let grew = true;
  while (grew) {
    grew = false;
    for (let j = 0; j < nj; j++) {
      if (used.has(j)) continue;
      const l1 = model.la[j];
      const l2 = model.lb[j];
      if (l1 < 0 || l2 < 0 || known.has(l1) || known.has(l2)) continue;
      const a = anchor(l1, j);
      const b = anchor(l2, j);
      if (a < 0 || b < 0 || a === b) continue;
      dyads.push({ j, a, b, l1, l2 });
      used.add(j).add(a).add(b);
      known.add(l1).add(l2);
      grew = true;
    }
  }
  if (used.size !== nj || known.size !== m + 1) return null;
  const n = dyads.length;
  const f = () => new Float64Array(n);
  const plan: DyadPlan = {
    inputLink,
    inputSign,
    px: model.la[inp] < 0 ? model.uax[inp] : model.ubx[inp],
    py: model.la[inp] < 0 ? model.uay[inp] : model.uby[inp],
    ux: localOn(model, inp, inputLink)[0],
    uy: localOn(model, inp, inputLink)[1],
    count: n,
    kA: new Int32Array(n),
    aX: f(),
    aY: f(),
    kB: new Int32Array(n),
    bX: f(),
    bY: f(),
    l1: new Int32Array(n),
    l2: new Int32Array(n),
    r1: f(),
    r2: f(),
    side: f(),
    u1x: f(),
    u1y: f(),
    ang1: f(),
    u2x: f(),
    u2y: f(),
    ang2: f(),
  };
  dyads.forEach((d, k) => {
    const ka = other(d.a, d.l1);
    const kb = other(d.b, d.l2);
    plan.kA[k] = ka;
    plan.kB[k] = kb;
    [plan.aX[k], plan.aY[k]] = localOn(model, d.a, ka);
    [plan.bX[k], plan.bY[k]] = localOn(model, d.b, kb);
    plan.l1[k] = d.l1;
    plan.l2[k] = d.l2;
    const pj = drawnPoint(model, d.j);
    const pa = drawnPoint(model, d.a);
    const pb = drawnPoint(model, d.b);
    plan.r1[k] = Math.hypot(pj[0] - pa[0], pj[1] - pa[1]);
    plan.r2[k] = Math.hypot(pj[0] - pb[0], pj[1] - pb[1]);
    const cross = (pb[0] - pa[0]) * (pj[1] - pa[1]) - (pb[1] - pa[1]) * (pj[0] - pa[0]);
    plan.side[k] = cross >= 0 ? 1 : -1;
    [plan.u1x[k], plan.u1y[k]] = localOn(model, d.a, d.l1);
    [plan.u2x[k], plan.u2y[k]] = localOn(model, d.b, d.l2);
    plan.ang1[k] = Math.atan2(pj[1] - pa[1], pj[0] - pa[0]);
    plan.ang2[k] = Math.atan2(pj[1] - pb[1], pj[0] - pb[0]);
  });
  return plan;
}

const TWO_PI = 2 * Math.acos(-1);

/** phi + 2 pi k nearest to prev: link angles stay continuous along the path. */
function nearest(phi: number, prev: number): number {
  return phi + TWO_PI * Math.round((prev - phi) / TWO_PI);
}

/** Sets link k's pose so that its point (ux, uy) lands on (wx, wy) at rotation phi. */
function place(q: Float64Array, k: number, phi: number, ux: number, uy: number, wx: number, wy: number): void {
  const c = Math.cos(phi);
  const s = Math.sin(phi);
  q[3 * k] = wx - (c * ux - s * uy);
  q[3 * k + 1] = wy - (s * ux + c * uy);
  q[3 * k + 2] = phi;
}

/** World position of point (ux, uy) of link k (-1 ground) at pose q, into out. */
function world(q: Float64Array, k: number, ux: number, uy: number, out: Float64Array, o: number): void {
  if (k < 0) {
    out[o] = ux;
    out[o + 1] = uy;
    return;
  }
  const phi = q[3 * k + 2];
  const c = Math.cos(phi);
  const s = Math.sin(phi);
  out[o] = q[3 * k] + c * ux - s * uy;
  out[o + 1] = q[3 * k + 1] + s * ux + c * uy;
}

const pts = new Float64Array(4);

/**
 * Poses every link at input t (rad) into q, in place (q holds the previous pose: its angles unwrap the new
 * ones). Returns false, with q partly written, when a dyad cannot close (its circles miss).
 */
export function poseDyads(plan: DyadPlan, t: number, q: Float64Array): boolean {
  place(q, plan.inputLink, plan.inputSign * t, plan.ux, plan.uy, plan.px, plan.py);
  for (let k = 0; k < plan.count; k++) {
    world(q, plan.kA[k], plan.aX[k], plan.aY[k], pts, 0);
    world(q, plan.kB[k], plan.bX[k], plan.bY[k], pts, 2);
    const ax = pts[0];
    const ay = pts[1];
    const dx = pts[2] - ax;
    const dy = pts[3] - ay;
    const d = Math.hypot(dx, dy);
    const r1 = plan.r1[k];
    const r2 = plan.r2[k];
    // Distance from A to the chord's foot along AB; h^2 = (r1 - a)(r1 + a) keeps accuracy near tangency.
    const a = ((r1 - r2) * (r1 + r2) + d * d) / (2 * d);
    const h2 = (r1 - a) * (r1 + a);
    if (!(h2 >= 0)) return false;
    const h = plan.side[k] * Math.sqrt(h2);
    const jx = ax + (a * dx - h * dy) / d;
    const jy = ay + (a * dy + h * dx) / d;
    const l1 = plan.l1[k];
    const l2 = plan.l2[k];
    const phi1 = nearest(Math.atan2(jy - ay, jx - ax) - plan.ang1[k], q[3 * l1 + 2]);
    const phi2 = nearest(Math.atan2(jy - pts[3], jx - pts[2]) - plan.ang2[k], q[3 * l2 + 2]);
    place(q, l1, phi1, plan.u1x[k], plan.u1y[k], ax, ay);
    place(q, l2, phi2, plan.u2x[k], plan.u2y[k], pts[2], pts[3]);
  }
  return true;
}
