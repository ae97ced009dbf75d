/**
 * Position, velocity and acceleration of any mobility-1 planar linkage along a path of inputs, by Newton–Raphson
 * on the constraint equations (model.ts) with natural-parameter continuation from the drawn configuration:
 * a predictor along the tangent of the constraint manifold (J q' = e_input), a chord-Newton corrector (the
 * Jacobian factored once per step, refactored only when the iteration contracts slowly), and step control
 * that refuses a step whose det J changes sign or whose corrector lands far from its prediction (a singular
 * configuration lies between, or the iteration jumped to another assembly). Where the step shrinks to nothing
 * the input cannot go on: the point is reported 'limit' and the sweep waits at the last pose for an input that
 * turns back. Rates come from the same Jacobian at the converged pose: J q' = e ω, J q'' = rhs (rates.ts).
 */
import { describe } from '../solver/validate';
import { planDyads, poseDyads } from './dyads';
import type { DyadPlan } from './dyads';
import { luFactor, luSolve } from './lu';
import { buildModel, evaluate, newTrig, sliderState, trigOf } from './model';
import type { Model, Trig } from './model';
import { accelerationRhs } from './rates';
import type { LinkSeries, MechanismSpec, MechanismStatus, MechanismSweep, PointSeries, SliderSeries } from './types';
import { validateSpec } from './validate';

/** Status names, indexed by MechanismSweep.status. */
export const MECHANISM_STATUSES: readonly MechanismStatus[] = ['ok', 'limit', 'singular', 'failed'];

/** Largest predicted move of any coordinate in one continuation step (scaled length or radians). */
export const MAX_MOVE = 0.125;
/** A drawn pose whose smallest LU pivot is below this fraction of the largest is singular: no direction to go. */
export const SINGULAR_PIVOT = 1e-12;
/** A step (input units, relative) below which the continuation gives up: the input cannot go on. */
const H_MIN = 1e-12;
const MAX_ITERATIONS = 16;
/** Continuation steps (accepted or refused) allowed for one input before the point is 'failed'. */
const MAX_ATTEMPTS = 5000;
/** The dyad path walks between inputs in steps of at most this (rad), checking that every dyad closes. */
export const MAX_DYAD_STEP = 0.05;
const EPS = Number.EPSILON;
/** Steps below this (relative) that no longer shrink are rounding noise: the corrector has converged. */
const NOISE = 1e-12;

/**
 * Called at every assembled pose when rates are asked, with J factored at the pose (ws.jac, ws.perm) and the
 * scaled rates qd, qdd: the forces (forces.ts) solve with the same factors.
 */
export type PoseHook = (i: number, ws: Workspace, qd: Float64Array, qdd: Float64Array) => void;

/** Every array the solver works in, allocated once per sweep. */
export interface Workspace {
  model: Model;
  q: Float64Array;
  qTry: Float64Array;
  f: Float64Array;
  jac: Float64Array;
  perm: Int32Array;
  tmp: Float64Array;
  tangent: Float64Array;
  minPivot: Float64Array;
  tr: Trig;
  /** det J of the latest factorisation. */
  det: number;
}

function maxAbs(v: Float64Array): number {
  let m = 0;
  for (let i = 0; i < v.length; i++) {
    const a = Math.abs(v[i]);
    if (a > m || a !== a) m = a;
  }
  return m;
}

/** Factors J at ws.qTry (F as well); returns false for an exactly singular J. */
function factorAt(ws: Workspace, t: number): boolean {
  trigOf(ws.model, ws.qTry, ws.tr);
  evaluate(ws.model, ws.qTry, t, ws.tr, ws.f, ws.jac);
  ws.det = luFactor(ws.jac, ws.model.n, ws.perm, ws.minPivot);
  return ws.det !== 0 && Number.isFinite(ws.det);
}

/**
 * Corrects ws.qTry onto F(q, t) = 0 by chord Newton (refactoring when the contraction is slow). Returns the
 * iterations used, negated when it did not converge.
 */
function correct(ws: Workspace, t: number): number {
  const { model, qTry, f, jac, perm, tmp } = ws;
  const n = model.n;
  if (!factorAt(ws, t)) return -1;
  const floor = 4 * EPS * Math.max(1, maxAbs(qTry));
  let prev = Infinity;
  for (let k = 1; k <= MAX_ITERATIONS; k++) {
    for (let i = 0; i < n; i++) f[i] = -f[i];
    luSolve(jac, n, perm, f, tmp);
    let norm = 0;
    for (let i = 0; i < n; i++) {
      qTry[i] += f[i];
      const a = Math.abs(f[i]);
      if (a > norm || a !== a) norm = a;
    }
    if (!(norm < 1)) return -k;
    // Converged when the step is at rounding level, or the error left after it (ratio / (1 - ratio) of the
    // step for a contracting iteration, with a margin of 64: chord steps do not contract evenly) is.
    if (norm <= floor) return k;
    const ratio = norm / prev;
    if (k > 1 && ratio < 0.5 && (64 * norm * ratio) / (1 - ratio) <= floor) return k;
    // Stagnation at the rounding noise of the residual (about cond(J) eps, above the floor when J is not
    // well conditioned): the steps stop shrinking while already tiny.
    if (k > 2 && ratio >= 0.5 && norm <= NOISE * Math.max(1, maxAbs(qTry))) return k;
    prev = norm;
    if (ratio > 0.25 && k > 1) {
      if (!factorAt(ws, t)) return -k;
    } else {
      trigOf(model, qTry, ws.tr);
      evaluate(model, qTry, t, ws.tr, f, null);
    }
  }
  return -MAX_ITERATIONS;
}

/** The tangent dq/dt at the factored pose: J q' = e_input (the input's row is F = ... - t). */
function tangentFromFactors(ws: Workspace): void {
  const n = ws.model.n;
  ws.tangent.fill(0);
  ws.tangent[n - 1] = 1;
  luSolve(ws.jac, n, ws.perm, ws.tangent, ws.tmp);
}

/** Series of every joint, tracer, link and slider, NaN-filled, with rate arrays when asked. */
function allocate(model: Model, count: number, withRates: boolean): MechanismSweep {
  const nan = () => new Float64Array(count).fill(NaN);
  const series = (): PointSeries =>
    withRates ? { x: nan(), y: nan(), vx: nan(), vy: nan(), ax: nan(), ay: nan() } : { x: nan(), y: nan() };
  const joints: Record<string, PointSeries> = {};
  const sliders: Record<string, SliderSeries> = {};
  model.jointIds.forEach((id, i) => {
    joints[id] = series();
    if (model.kind[i] === 1) sliders[id] = withRates ? { s: nan(), v: nan(), a: nan() } : { s: nan() };
  });
  const points: Record<string, PointSeries> = {};
  for (const id of model.pointIds) points[id] = series();
  const links: Record<string, LinkSeries> = {};
  for (const l of model.linkNames)
    links[l] = withRates ? { angle: nan(), omega: nan(), alpha: nan() } : { angle: nan() };
  return {
    ok: new Uint8Array(count),
    status: new Uint8Array(count),
    joints,
    points,
    links,
    sliders,
    detJ: nan(),
    iterations: new Uint16Array(count),
    scale: model.scale,
    method: 'newton',
  };
}

/** A point on link k at local (ux, uy): position, and velocity and acceleration when qd, qdd are given. */
function writePoint(
  out: PointSeries,
  i: number,
  k: number,
  ux: number,
  uy: number,
  q: Float64Array,
  tr: Trig,
  scale: number,
  qd: Float64Array | null,
  qdd: Float64Array | null,
): void {
  if (k < 0) {
    out.x[i] = ux * scale;
    out.y[i] = uy * scale;
    if (qd && qdd) out.vx![i] = out.vy![i] = out.ax![i] = out.ay![i] = 0;
    return;
  }
  const c = tr.c[k];
  const s = tr.s[k];
  const rx = c * ux - s * uy;
  const ry = s * ux + c * uy;
  out.x[i] = (q[3 * k] + rx) * scale;
  out.y[i] = (q[3 * k + 1] + ry) * scale;
  if (!qd || !qdd) return;
  const w = qd[3 * k + 2];
  const al = qdd[3 * k + 2];
  out.vx![i] = (qd[3 * k] - ry * w) * scale;
  out.vy![i] = (qd[3 * k + 1] + rx * w) * scale;
  out.ax![i] = (qdd[3 * k] - ry * al - rx * w * w) * scale;
  out.ay![i] = (qdd[3 * k + 1] + rx * al - ry * w * w) * scale;
}

/** Everything at point i from the pose q (and its rates). */
function record(
  ws: Workspace,
  out: MechanismSweep,
  i: number,
  qd: Float64Array | null,
  qdd: Float64Array | null,
): void {
  const { model, q, tr } = ws;
  const { scale } = model;
  trigOf(model, q, tr);
  model.jointIds.forEach((id, j) => {
    const a = model.la[j];
    writePoint(out.joints[id], i, a, model.uax[j], model.uay[j], q, tr, scale, qd, qdd);
    if (model.kind[j] === 1) {
      const s = sliderState(model, q, tr, j);
      const sl = out.sliders[id];
      sl.s[i] = (s.dx * s.ddx + s.dy * s.ddy) * scale;
      if (qd && qdd) {
        const ds = sliderRates(model, j, q, qd, qdd, tr);
        sl.v![i] = ds[0] * scale;
        sl.a![i] = ds[1] * scale;
      }
    }
  });
  model.pointIds.forEach((id, p) => {
    writePoint(out.points[id], i, model.pl[p], model.pux[p], model.puy[p], q, tr, scale, qd, qdd);
  });
  model.linkNames.forEach((l, k) => {
    const ls = out.links[l];
    ls.angle[i] = q[3 * k + 2];
    if (qd && qdd) {
      ls.omega![i] = qd[3 * k + 2];
      ls.alpha![i] = qdd[3 * k + 2];
    }
  });
}

const sRates = new Float64Array(2);

/** A slider's s' and s'' (scaled): s = d · D, so s' = phi_b' (n · D) + d · D' and s'' as the input's row. */
function sliderRates(
  model: Model,
  j: number,
  q: Float64Array,
  qd: Float64Array,
  qdd: Float64Array,
  tr: Trig,
): Float64Array {
  const s = sliderState(model, q, tr, j);
  const a = model.la[j];
  const b = model.lb[j];
  const vel = (k: number, rx: number, ry: number, v: Float64Array) =>
    k < 0 ? [0, 0] : [v[3 * k] - ry * v[3 * k + 2], v[3 * k + 1] + rx * v[3 * k + 2]];
  const [vax, vay] = vel(a, s.rax, s.ray, qd);
  const [vbx, vby] = vel(b, s.rbx, s.rby, qd);
  const wa = a < 0 ? 0 : qd[3 * a + 2];
  const wb = b < 0 ? 0 : qd[3 * b + 2];
  const alb = b < 0 ? 0 : qdd[3 * b + 2];
  const [aax, aay] = vel(a, s.rax, s.ray, qdd);
  const [abx, aby] = vel(b, s.rbx, s.rby, qdd);
  const nx = -s.dy;
  const ny = s.dx;
  const rvx = vax - vbx;
  const rvy = vay - vby;
  // Relative acceleration D'' = a_a - a_b, with the centripetal terms -r phi'^2.
  const rax = aax - s.rax * wa * wa - (abx - s.rbx * wb * wb);
  const ray = aay - s.ray * wa * wa - (aby - s.rby * wb * wb);
  sRates[0] = wb * (nx * s.ddx + ny * s.ddy) + s.dx * rvx + s.dy * rvy;
  // s'' = d'' · D + 2 d' · D' + d · D'', d'' = -phi_b'^2 d + phi_b'' n.
  sRates[1] =
    -wb * wb * (s.dx * s.ddx + s.dy * s.ddy) +
    alb * (nx * s.ddx + ny * s.ddy) +
    2 * wb * (nx * rvx + ny * rvy) +
    s.dx * rax +
    s.dy * ray;
  return sRates;
}

/** Exact rates at the pose ws.q (input t): J at the pose itself, J q' = e ω, J q'' = rhs; det J into out. */
function exactRates(
  ws: Workspace,
  t: number,
  omega: number,
  alpha: number,
  qd: Float64Array,
  qdd: Float64Array,
  out: MechanismSweep,
  i: number,
): void {
  const n = ws.model.n;
  ws.qTry.set(ws.q);
  factorAt(ws, t);
  qd.fill(0);
  qd[n - 1] = omega;
  luSolve(ws.jac, n, ws.perm, qd, ws.tmp);
  accelerationRhs(ws.model, ws.q, qd, ws.tr, alpha, qdd);
  luSolve(ws.jac, n, ws.perm, qdd, ws.tmp);
  out.detJ[i] = ws.det;
}

/**
 * The dyad path (dyads.ts): each input is reached from the previous one in steps of at most MAX_DYAD_STEP, every
 * step posed in closed form; a dyad that cannot close stops the path there ('limit'), as in the Newton path.
 */
function sweepDyads(
  ws: Workspace,
  plan: DyadPlan,
  inputs: ArrayLike<number>,
  rates: { omega: number; alpha: number } | undefined,
  out: MechanismSweep,
  onPose: PoseHook | undefined,
): void {
  const { q, qTry } = ws;
  const n = ws.model.n;
  const qd = rates ? new Float64Array(n) : null;
  const qdd = rates ? new Float64Array(n) : null;
  let t = 0;
  let blocked = 0;
  let blockedAt = 0;
  for (let i = 0; i < inputs.length; i++) {
    const target = inputs[i];
    if (blocked !== 0 && (target - blockedAt) * blocked >= 0) {
      out.status[i] = 1;
      continue;
    }
    blocked = 0;
    const steps = Math.ceil(Math.abs(target - t) / MAX_DYAD_STEP);
    qTry.set(q);
    for (let k = 1; k <= steps; k++) {
      const tt = k === steps ? target : t + ((target - t) * k) / steps;
      if (!poseDyads(plan, tt, qTry)) {
        blocked = Math.sign(target - t);
        blockedAt = tt;
        break;
      }
    }
    if (blocked !== 0) {
      // No pose at or beyond the first input that failed: wait at the last pose for the path to turn back.
      out.status[i] = 1;
      continue;
    }
    q.set(qTry);
    t = target;
    out.ok[i] = 1;
    if (qd && qdd && rates) exactRates(ws, t, rates.omega, rates.alpha, qd, qdd, out, i);
    record(ws, out, i, qd, qdd);
    if (onPose && qd && qdd) onPose(i, ws, qd, qdd);
  }
}

/** Throws an Error naming the index unless every input is finite, and unless rates are two finite numbers. */
function checkInputs(inputs: ArrayLike<number>, rates: { omega: number; alpha: number } | undefined): void {
  if (typeof inputs !== 'object' || inputs === null || typeof inputs.length !== 'number') {
    throw new Error(`inputs must be an array of numbers, got ${describe(inputs)}`);
  }
  for (let i = 0; i < inputs.length; i++) {
    const v = inputs[i];
    if (typeof v !== 'number' || !Number.isFinite(v))
      throw new Error(`inputs[${i}] must be a finite number, got ${describe(v)}`);
  }
  if (rates === undefined) return;
  if (typeof rates !== 'object' || rates === null)
    throw new Error(`rates must be { omega, alpha }, got ${describe(rates)}`);
  for (const k of ['omega', 'alpha'] as const) {
    if (typeof rates[k] !== 'number' || !Number.isFinite(rates[k])) {
      throw new Error(`rates.${k} must be a finite number, got ${describe(rates[k])}`);
    }
  }
}

/**
 * Poses (and, with rates, velocities and accelerations) of a mobility-1 linkage at each input (radians for an R
 * input, length for a P input; 0 = as drawn), reached by continuity from the drawn configuration along the
 * inputs in order. rates: the input's rate ω (rad/s or length/s) and acceleration α (per s²). Points the
 * linkage cannot reach on its drawn branch have ok 0, a status and NaN values. Throws an Error naming the
 * offending id, field or input for a spec that is not a mobility-1 linkage (validate.ts) or non-finite inputs.
 */
export function sweepMechanism(
  spec: MechanismSpec,
  inputs: ArrayLike<number>,
  rates?: { omega: number; alpha: number },
): MechanismSweep {
  return sweepWith(spec, inputs, rates, true);
}

/** sweepMechanism, with the dyad path allowed or not (tests compare the two paths; not in the barrel). */
export function sweepWith(
  spec: MechanismSpec,
  inputs: ArrayLike<number>,
  rates: { omega: number; alpha: number } | undefined,
  allowDyads: boolean,
  onPose?: PoseHook,
): MechanismSweep {
  validateSpec(spec);
  checkInputs(inputs, rates);
  const model = buildModel(spec);
  const n = model.n;
  const count = inputs.length;
  const out = allocate(model, count, rates !== undefined);
  const q = new Float64Array(n);
  for (let k = 0; k < model.linkNames.length; k++) {
    q[3 * k] = model.cx[k];
    q[3 * k + 1] = model.cy[k];
  }
  const ws: Workspace = {
    model,
    q,
    qTry: new Float64Array(q),
    f: new Float64Array(n),
    jac: new Float64Array(n * n),
    perm: new Int32Array(n),
    tmp: new Float64Array(n),
    tangent: new Float64Array(n),
    minPivot: new Float64Array(1),
    tr: newTrig(model.linkNames.length),
    det: 0,
  };
  const inputScale = model.kind[model.input] === 1 ? 1 / model.scale : 1;
  if (!factorAt(ws, 0) || ws.minPivot[0] < SINGULAR_PIVOT) {
    out.status.fill(2);
    return out;
  }
  const plan = allowDyads ? planDyads(model) : null;
  out.method = plan ? 'dyads' : 'newton';
  if (plan) {
    sweepDyads(ws, plan, inputs, rates, out, onPose);
    return out;
  }
  tangentFromFactors(ws);
  const detSign = Math.sign(ws.det);
  const qd = rates ? new Float64Array(n) : null;
  const qdd = rates ? new Float64Array(n) : null;
  const rateScale = inputScale;
  let t = 0;
  let hMax = Infinity;
  let blocked = 0;
  let blockedAt = 0;
  let det = ws.det;
  const qSave = new Float64Array(n);
  for (let i = 0; i < count; i++) {
    const target = inputs[i] * inputScale;
    if (blocked !== 0 && (target - blockedAt) * blocked >= 0) {
      out.status[i] = 1;
      continue;
    }
    blocked = 0;
    qSave.set(q);
    const tSave = t;
    let iterations = 0;
    let attempts = 0;
    let failed = false;
    while (t !== target) {
      if (++attempts > MAX_ATTEMPTS) {
        failed = true;
        break;
      }
      let h = target - t;
      if (Math.abs(h) > hMax) h = Math.sign(h) * hMax;
      const slope = maxAbs(ws.tangent);
      if (Math.abs(h) * slope > MAX_MOVE) h = (Math.sign(h) * MAX_MOVE) / slope;
      const move = Math.abs(h) * slope;
      const tNext = h === target - t ? target : t + h;
      const qTry = ws.qTry;
      for (let k = 0; k < n; k++) qTry[k] = q[k] + h * ws.tangent[k];
      const used = correct(ws, tNext);
      iterations += Math.abs(used);
      let accept = used > 0 && Math.sign(ws.det) === detSign;
      if (accept) {
        // The corrector must stay near its prediction: a long way off means another assembly was found.
        let dist = 0;
        for (let k = 0; k < n; k++) dist = Math.max(dist, Math.abs(qTry[k] - q[k] - h * ws.tangent[k]));
        accept = dist <= 0.5 * move + 1e-9;
      }
      if (!accept) {
        hMax = Math.abs(h) / 4;
        if (hMax <= H_MIN * Math.max(1, Math.abs(t))) {
          blocked = Math.sign(target - t);
          hMax = Infinity;
          break;
        }
        continue;
      }
      q.set(qTry);
      t = tNext;
      det = ws.det;
      tangentFromFactors(ws);
      hMax = Math.abs(h) * (used <= 3 ? 4 : used <= 6 ? 2 : 1.25);
    }
    out.iterations[i] = Math.min(iterations, 65535);
    if (failed) {
      // Too many steps for one input (the corrector converging too slowly to make progress): give up on this
      // point, keep the last pose.
      q.set(qSave);
      t = tSave;
      ws.qTry.set(q);
      factorAt(ws, t);
      tangentFromFactors(ws);
      hMax = Infinity;
      out.status[i] = 3;
      continue;
    }
    if (blocked !== 0) {
      // Back to the last input reached: the continuation crept up to the fold, where going back is as hard as
      // going on (the tangent is unbounded there).
      blockedAt = t;
      q.set(qSave);
      t = tSave;
      ws.qTry.set(q);
      factorAt(ws, t);
      tangentFromFactors(ws);
      out.status[i] = 1;
      continue;
    }
    out.ok[i] = 1;
    out.detJ[i] = det;
    if (rates && qd && qdd) {
      // Exact rates need J at the converged pose itself (the continuation's factors are one chord step behind).
      exactRates(ws, t, rates.omega * rateScale, rates.alpha * rateScale, qd, qdd, out, i);
      tangentFromFactors(ws);
    }
    record(ws, out, i, qd, qdd);
    if (onPose && qd && qdd) onPose(i, ws, qd, qdd);
  }
  return out;
}
