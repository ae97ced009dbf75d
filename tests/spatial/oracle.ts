/**
 * Independent 50-digit oracle for the spatial four-bars (decimal.js). Every double input is taken as the exact binary
 * value it holds. The derivation differs from src/spatial's on purpose: the pins are built straight from the issue's
 * conventions as vectors, the closure constraint is reduced to P cos t4 + Q sin t4 = R and solved as the quadratic in
 * tan(t4/2), (R + P) t^2 - 2 Q t + (R - P) = 0 (both roots in the cancellation-free pair), and the branch is read off
 * the sign of (A - B) . dB/dt4 at each root. Rates are central differences of the 50-digit angle.
 */
import Decimal from 'decimal.js';
import { exact } from '../oracle/reference';

const D = Decimal.clone({ precision: 50 });
type Dec = InstanceType<typeof D>;
const PI_D = D.acos(-1);
const ZERO = new D(0);
/** A double as the exact binary value it holds (decimal.js reads a number through its shortest decimal, which is not). */
const ex = (x: number): Dec => new D(exact(x));

interface V {
  x: Dec;
  y: Dec;
  z: Dec;
}

const v = (x: Dec | number, y: Dec | number, z: Dec | number): V => ({ x: new D(x), y: new D(y), z: new D(z) });
const dot = (a: V, b: V): Dec => a.x.mul(b.x).add(a.y.mul(b.y)).add(a.z.mul(b.z));
const add = (a: V, b: V): V => v(a.x.add(b.x), a.y.add(b.y), a.z.add(b.z));
const sub = (a: V, b: V): V => v(a.x.sub(b.x), a.y.sub(b.y), a.z.sub(b.z));
const mul = (a: V, k: Dec): V => v(a.x.mul(k), a.y.mul(k), a.z.mul(k));
const cross = (a: V, b: V): V =>
  v(a.y.mul(b.z).sub(a.z.mul(b.y)), a.z.mul(b.x).sub(a.x.mul(b.z)), a.x.mul(b.y).sub(a.y.mul(b.x)));
const toNum = (a: V) => ({ x: a.x.toNumber(), y: a.y.toNumber(), z: a.z.toNumber() });

/** One linkage as the oracle sees it: the input pin, the output pin's circle and the constraint's P, Q, R. */
interface Model {
  A(t2: Dec): V;
  B(t4: Dec): V;
  dB(t4: Dec): V;
  pqr(A: V): { P: Dec; Q: Dec; R: Dec };
  coupler?(A: V, B: V): V;
}

export interface SphericalArcs {
  a1: number;
  a2: number;
  a3: number;
  a4: number;
  pDist?: number;
  pAngle?: number;
}

export interface RSSRLengths {
  r2: number;
  r3: number;
  r4: number;
  a: number;
  beta: number;
  h2: number;
  h4: number;
}

function sphericalModel(l: SphericalArcs): Model {
  const [a1, a2, a3, a4] = [l.a1, l.a2, l.a3, l.a4].map(ex);
  const [sa2, ca2, sa4, ca4, ca3] = [D.sin(a2), D.cos(a2), D.sin(a4), D.cos(a4), D.cos(a3)];
  const O4 = v(D.sin(a1), 0, D.cos(a1));
  const u = v(D.cos(a1), 0, D.sin(a1).neg());
  const y = v(0, 1, 0);
  const model: Model = {
    A: (t2) => v(sa2.mul(D.cos(t2)), sa2.mul(D.sin(t2)), ca2),
    B: (t4) => add(mul(O4, ca4), mul(add(mul(u, D.cos(t4)), mul(y, D.sin(t4))), sa4)),
    dB: (t4) => mul(add(mul(u, D.sin(t4).neg()), mul(y, D.cos(t4))), sa4),
    pqr: (A) => ({
      P: sa4.mul(dot(A, u)),
      Q: sa4.mul(dot(A, y)),
      R: ca3.sub(ca4.mul(dot(A, O4))),
    }),
  };
  if (l.pDist !== undefined) {
    const pd = ex(l.pDist);
    const pa = ex(l.pAngle ?? 0);
    model.coupler = (A, B) => {
      const t0 = sub(B, mul(A, dot(A, B)));
      const t = mul(t0, new D(1).div(dot(t0, t0).sqrt()));
      const n = cross(A, t);
      return add(mul(A, D.cos(pd)), mul(add(mul(t, D.cos(pa)), mul(n, D.sin(pa))), D.sin(pd)));
    };
  }
  return model;
}

function rssrModel(l: RSSRLengths): Model {
  const [r2, r3, r4, a, beta, h2, h4] = [l.r2, l.r3, l.r4, l.a, l.beta, l.h2, l.h4].map(ex);
  const w = v(0, D.sin(beta).neg(), D.cos(beta));
  const e1 = v(1, 0, 0);
  const e2 = v(0, D.cos(beta), D.sin(beta));
  const C = add(v(a, 0, 0), mul(w, h4));
  return {
    A: (t2) => v(r2.mul(D.cos(t2)), r2.mul(D.sin(t2)), h2),
    B: (t4) => add(C, mul(add(mul(e1, D.cos(t4)), mul(e2, D.sin(t4))), r4)),
    dB: (t4) => mul(add(mul(e1, D.sin(t4).neg()), mul(e2, D.cos(t4))), r4),
    pqr: (A) => {
      const AC = sub(A, C);
      return {
        P: r4.mul(2).mul(dot(AC, e1)),
        Q: r4.mul(2).mul(dot(AC, e2)),
        R: dot(AC, AC).add(r4.mul(r4)).sub(r3.mul(r3)),
      };
    },
  };
}

/** theta4 (Decimal, wrapped to (-pi, pi]) on the branch (+1 open, -1 crossed), or null if the loop cannot close. */
function theta4At(m: Model, t2: Dec, open: boolean): { t4: Dec; A: V; B: V; sinPsi: Dec } | null {
  const A = m.A(t2);
  const { P, Q, R } = m.pqr(A);
  const disc = P.mul(P).add(Q.mul(Q)).sub(R.mul(R));
  if (disc.isNeg()) return null;
  const sq = disc.sqrt();
  const k = Q.isNeg() ? Q.sub(sq) : Q.add(sq);
  const roots = k.isZero() ? [PI_D, PI_D] : [D.atan(k.div(R.add(P))).mul(2), D.atan(R.sub(P).div(k)).mul(2)];
  const rho = P.mul(P).add(Q.mul(Q)).sqrt();
  for (const root of roots) {
    const B = m.B(root);
    const s = dot(sub(A, B), m.dB(root));
    if (s.isZero() || s.isPos() === open) {
      let t4 = root;
      if (t4.gt(PI_D)) t4 = t4.sub(PI_D.mul(2));
      if (t4.lte(PI_D.neg())) t4 = t4.add(PI_D.mul(2));
      return { t4, A, B, sinPsi: sq.div(rho) };
    }
  }
  return null;
}

/** The oracle's pose: theta4, pins, rates (for omega2, alpha2) and sin psi (the conditioning at the output pivot). */
export interface OraclePose {
  theta4: number;
  A: { x: number; y: number; z: number };
  B: { x: number; y: number; z: number };
  P?: { x: number; y: number; z: number };
  omega4: number;
  alpha4: number;
  vB: { x: number; y: number; z: number };
  aB: { x: number; y: number; z: number };
  vP?: { x: number; y: number; z: number };
  aP?: { x: number; y: number; z: number };
  /** sin of the angle at the output pivot: 0 at a limit; the position's condition grows like 1 / sinPsi. */
  sinPsi: number;
}

/** The step of the central differences: truncation h^2 ~ 1e-24, rounding 1e-50 / h^2 ~ 1e-26. */
const H = new D('1e-12');

function oracle(m: Model, theta2: number, open: boolean, omega2: number, alpha2: number): OraclePose | null {
  const t2 = ex(theta2);
  const c = theta4At(m, t2, open);
  if (c === null) return null;
  const plus = theta4At(m, t2.add(H), open);
  const minus = theta4At(m, t2.sub(H), open);
  let d1 = ZERO;
  let d2 = ZERO;
  if (plus !== null && minus !== null) {
    const unwrap = (x: Dec) => {
      let d = x.sub(c.t4);
      if (d.gt(PI_D)) d = d.sub(PI_D.mul(2));
      if (d.lt(PI_D.neg())) d = d.add(PI_D.mul(2));
      return d;
    };
    const dp = unwrap(plus.t4);
    const dm = unwrap(minus.t4);
    d1 = dp.sub(dm).div(H.mul(2));
    d2 = dp.add(dm).div(H.mul(H));
  }
  const w2 = ex(omega2);
  const a2 = ex(alpha2);
  const pointMotion = (f: (x: NonNullable<typeof c>) => V) => {
    const p0 = f(c);
    if (plus === null || minus === null) return { v: v(0, 0, 0), a: v(0, 0, 0) };
    const pp = f(plus);
    const pm = f(minus);
    const first = mul(sub(pp, pm), new D(1).div(H.mul(2)));
    const second = mul(sub(add(pp, pm), mul(p0, new D(2))), new D(1).div(H.mul(H)));
    return { v: mul(first, w2), a: add(mul(second, w2.mul(w2)), mul(first, a2)) };
  };
  const b = pointMotion((x) => x.B);
  const pose: OraclePose = {
    theta4: c.t4.toNumber(),
    A: toNum(c.A),
    B: toNum(c.B),
    omega4: d1.mul(w2).toNumber(),
    alpha4: d2.mul(w2.mul(w2)).add(d1.mul(a2)).toNumber(),
    vB: toNum(b.v),
    aB: toNum(b.a),
    sinPsi: c.sinPsi.toNumber(),
  };
  if (m.coupler) {
    const cp = m.coupler;
    pose.P = toNum(cp(c.A, c.B));
    const pm = pointMotion((x) => cp(x.A, x.B));
    pose.vP = toNum(pm.v);
    pose.aP = toNum(pm.a);
  }
  return pose;
}

/** The 50-digit spherical pose at theta2 (radians) on the branch, or null where the loop cannot close. */
export function sphericalOracle(
  l: SphericalArcs,
  theta2: number,
  branch: 'open' | 'crossed',
  omega2 = 0,
  alpha2 = 0,
): OraclePose | null {
  return oracle(sphericalModel(l), theta2, branch === 'open', omega2, alpha2);
}

/** The 50-digit RSSR pose at theta2 (radians) on the branch, or null where the loop cannot close. */
export function rssrOracle(
  l: RSSRLengths,
  theta2: number,
  branch: 'open' | 'crossed',
  omega2 = 0,
  alpha2 = 0,
): OraclePose | null {
  return oracle(rssrModel(l), theta2, branch === 'open', omega2, alpha2);
}

/** A 50-digit test of whether the loop closes at theta2 (P^2 + Q^2 >= R^2), the linkage's constants made once. */
export function closer(kind: 'spherical' | 'rssr', l: SphericalArcs | RSSRLengths): (theta2: number) => boolean {
  const m = kind === 'spherical' ? sphericalModel(l as SphericalArcs) : rssrModel(l as RSSRLengths);
  return (theta2) => {
    const { P, Q, R } = m.pqr(m.A(ex(theta2)));
    return !P.mul(P).add(Q.mul(Q)).sub(R.mul(R)).isNeg();
  };
}

/** The angle difference a - b wrapped to (-pi, pi] (doubles). */
export function angleGap(a: number, b: number): number {
  let d = a - b;
  const TWO = 2 * Math.acos(-1);
  d -= TWO * Math.round(d / TWO);
  return d;
}
