/**
 * A 40-digit Newton–Euler oracle for the four-bar's forces, written independently of src/solver/forces.ts:
 * nothing here imports the solver. It shares only the conventions (Fij = force of link i on link j, CG from
 * the link's first joint at an angle from the link's line, counter-clockwise positive, SI units).
 *
 * - Positions: the crank pin A from theta2; B as the intersection of the circles (A, r3) and (O4, r4), the
 *   open branch (sin(theta4 - theta3) > 0) on the left of the ray from A to O4. Or, for a given pose, the
 *   link vectors r3 (cos theta3, sin theta3) and r4 (cos theta4, sin theta4) taken as exact (as the solver
 *   takes them), the coupler's B being A + r3 and the rocker's O4 + r4.
 * - Velocities and accelerations: the velocity of B from the coupler equals that from the rocker, and so
 *   do the accelerations (relative-motion equations, 2x2 systems solved by elimination).
 * - Forces: the nine equations (force balance of each moving link, and its moments about its own centre of
 *   mass, not the joints the solver uses) as a 9x9 system solved by Gaussian elimination with partial
 *   pivoting.
 * Every double input is taken as the exact binary value it holds (ex), so the oracle answers the problem
 * the solver was given. Below the oracle: the random cases (forceCaseArb), the error measure the tests
 * share, and linkMotions, a double-precision account of each link's CG motion for the energy, momentum
 * and flywheel checks (from the rates it is given, by relative motion: no force equation).
 */
import Decimal from 'decimal.js';
import fc from 'fast-check';

const D = Decimal.clone({ precision: 40 });
type Dec = InstanceType<typeof D>;

interface Vec {
  x: Dec;
  y: Dec;
}

/** Structural copies of the solver's argument types (no import from src). */
export interface OracleLinkage {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
}
export interface OracleInertia {
  mass: number;
  inertia: number;
  cg: { dist: number; angle: number };
}
export interface OracleInertias {
  crank: OracleInertia;
  coupler: OracleInertia;
  rocker: OracleInertia;
}
export interface OracleLoads {
  gravity?: { g: number; angle?: number };
  couplerForce?: { pDist: number; pAngle: number; fx: number; fy: number };
  outputTorque?: number;
}
export interface OracleMotion {
  omega2: number;
  alpha2: number;
}
export interface Pt {
  x: number;
  y: number;
}

/** The oracle's answer, rounded to doubles, with the sizes tolerances are judged against. */
export interface OracleForces {
  torque: number;
  F12: Pt;
  F32: Pt;
  F43: Pt;
  F14: Pt;
  shakingForce: Pt;
  shakingMoment: number;
  /** sin(theta4 - theta3) of the oracle's pose. */
  sinMu: number;
  /** Largest magnitude of the four pin forces (N). */
  largestForce: number;
  /**
   * The largest force the inputs put into the problem (N): each link's inertia force m |a_G| and weight m g,
   * the applied force, each I |alpha| and the load torque over the link's length, and the size of those terms
   * for the input's rates, m (omega2² + |alpha2|) r2 and I (omega2² + |alpha2|) / r (a term whose true
   * value is 0 still carries the rounding of its parts). Where the pin forces cancel to far less than their
   * loads, errors are judged against this.
   */
  loadScale: number;
}

/**
 * The exact value of a double as a Decimal (mantissa times a power of two; rounded only at 40 digits).
 * new Decimal(x) would take the shortest decimal string of x instead, up to half an ulp away: near
 * theta = pi that alone moves sin(theta) by 1e-16 absolute, a relative 1e-6 at sin mu = 1e-10.
 */
function ex(x: number | Dec): Dec {
  if (typeof x !== 'number') return x;
  if (!Number.isFinite(x)) throw new Error(`not a finite double: ${x}`);
  if (x === 0) return new D(0);
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const hi = view.getUint32(0);
  const lo = view.getUint32(4);
  const biased = (hi >>> 20) & 0x7ff;
  let mantissa = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
  if (biased !== 0) mantissa |= 1n << 52n;
  const exponent = (biased === 0 ? 1 : biased) - 1075;
  const sign = hi >>> 31 ? -1 : 1;
  return new D(mantissa.toString()).times(new D(2).pow(exponent)).times(sign);
}
const cosE = (x: number): Dec => D.cos(ex(x));
const sinE = (x: number): Dec => D.sin(ex(x));

const v = (x: Dec | number, y: Dec | number): Vec => ({ x: ex(x), y: ex(y) });
const add = (a: Vec, b: Vec): Vec => ({ x: a.x.plus(b.x), y: a.y.plus(b.y) });
const sub = (a: Vec, b: Vec): Vec => ({ x: a.x.minus(b.x), y: a.y.minus(b.y) });
const mul = (a: Vec, k: Dec): Vec => ({ x: a.x.times(k), y: a.y.times(k) });
const perp = (a: Vec): Vec => ({ x: a.y.neg(), y: a.x });
const cross = (a: Vec, b: Vec): Dec => a.x.times(b.y).minus(a.y.times(b.x));
const rotate = (u: Vec, angle: number): Vec => {
  const c = cosE(angle);
  const s = sinE(angle);
  return { x: u.x.times(c).minus(u.y.times(s)), y: u.x.times(s).plus(u.y.times(c)) };
};

/** Solves A x = b in place by Gaussian elimination with partial pivoting. */
export function gaussSolve(A: Dec[][], b: Dec[]): Dec[] {
  const n = b.length;
  for (let col = 0; col < n; col++) {
    let piv = col;
    for (let r = col + 1; r < n; r++) if (A[r][col].abs().greaterThan(A[piv][col].abs())) piv = r;
    if (A[piv][col].isZero()) throw new Error(`singular system at column ${col}`);
    [A[col], A[piv]] = [A[piv], A[col]];
    [b[col], b[piv]] = [b[piv], b[col]];
    for (let r = col + 1; r < n; r++) {
      const f = A[r][col].div(A[col][col]);
      if (f.isZero()) continue;
      for (let c = col; c < n; c++) A[r][c] = A[r][c].minus(f.times(A[col][c]));
      b[r] = b[r].minus(f.times(b[col]));
    }
  }
  const x: Dec[] = new Array(n);
  for (let r = n - 1; r >= 0; r--) {
    let s = b[r];
    for (let c = r + 1; c < n; c++) s = s.minus(A[r][c].times(x[c]));
    x[r] = s.div(A[r][r]);
  }
  return x;
}

/** Link vectors of the pose: O2A, the coupler A→B and the rocker O4→B; null when the loop cannot close. */
interface Geometry {
  rA: Vec;
  r3: Vec;
  r4: Vec;
}

function geometryOnBranch(l: OracleLinkage, theta2: number, branch: 'open' | 'crossed'): Geometry | null {
  const rA = v(cosE(theta2).times(ex(l.r2)), sinE(theta2).times(ex(l.r2)));
  const d = sub(v(l.r1, 0), rA);
  const d2 = d.x.pow(2).plus(d.y.pow(2));
  const dist = d2.sqrt();
  const a = ex(l.r3).pow(2).minus(ex(l.r4).pow(2)).plus(d2).div(dist.times(2));
  const h2 = ex(l.r3).pow(2).minus(a.pow(2));
  if (h2.isNegative()) return null;
  const h = branch === 'open' ? h2.sqrt() : h2.sqrt().neg();
  const r3 = add(mul(d, a.div(dist)), mul(perp(d), h.div(dist)));
  return { rA, r3, r4: sub(add(rA, r3), v(l.r1, 0)) };
}

function geometryOfPose(l: OracleLinkage, theta2: number, theta3: number, theta4: number): Geometry {
  return {
    rA: v(cosE(theta2).times(ex(l.r2)), sinE(theta2).times(ex(l.r2))),
    r3: v(cosE(theta3).times(ex(l.r3)), sinE(theta3).times(ex(l.r3))),
    r4: v(cosE(theta4).times(ex(l.r4)), sinE(theta4).times(ex(l.r4))),
  };
}

/**
 * Angular rates of coupler and rocker: v_B = omega2 k×rA + omega3 k×r3 = omega4 k×r4, and
 * a_B = alpha2 k×rA - omega2² rA + alpha3 k×r3 - omega3² r3 = alpha4 k×r4 - omega4² r4.
 */
function rates(g: Geometry, m: OracleMotion): { w3: Dec; w4: Dec; a3: Dec; a4: Dec } {
  const w2 = ex(m.omega2);
  const a2 = ex(m.alpha2);
  // Unknowns (x3, x4) with x3 perp(r3) - x4 perp(r4) = rhs.
  const solve2 = (rhs: Vec): [Dec, Dec] => {
    const [x3, x4] = gaussSolve(
      [
        [perp(g.r3).x, perp(g.r4).x.neg()],
        [perp(g.r3).y, perp(g.r4).y.neg()],
      ],
      [rhs.x, rhs.y],
    );
    return [x3, x4];
  };
  const [w3, w4] = solve2(mul(perp(g.rA), w2.neg()));
  const known = sub(add(mul(perp(g.rA), a2), mul(g.rA, w2.pow(2).neg())), mul(g.r3, w3.pow(2)));
  const [a3, a4] = solve2(add(mul(known, ex(-1)), mul(g.r4, w4.pow(2).neg())));
  return { w3, w4, a3, a4 };
}

/** alpha k×r - omega² r: the acceleration of a point at r on a link turning about the origin of r. */
const relAcc = (r: Vec, w: Dec, a: Dec): Vec => sub(mul(perp(r), a), mul(r, w.pow(2)));

/** |sin mu| below which the oracle declines: the 9x9 system is singular to 40 digits. */
const NEAR_LIMIT = 1e-30;

/** Moment coefficients of a force F at r (about the reference): r × F = -r.y F.x + r.x F.y. */
const momentRow = (r: Vec): [Dec, Dec] => [r.y.neg(), r.x];

const norm = (a: Vec): number => a.x.pow(2).plus(a.y.pow(2)).sqrt().toNumber();

/** See OracleForces.loadScale. */
function loadScale(
  l: OracleLinkage,
  motion: OracleMotion,
  inertia: OracleInertias,
  loads: OracleLoads,
  aG: Vec[],
  alpha: Dec[],
): number {
  const rate = motion.omega2 ** 2 + Math.abs(motion.alpha2);
  const links = [inertia.crank, inertia.coupler, inertia.rocker];
  const lengths = [l.r2, l.r3, l.r4];
  const terms = links.flatMap((c, k) => [
    c.mass * norm(aG[k]),
    c.mass * (loads.gravity?.g ?? 0),
    c.mass * rate * l.r2,
    (c.inertia * Math.abs(alpha[k].toNumber())) / lengths[k],
    (c.inertia * rate) / lengths[k],
  ]);
  const f = loads.couplerForce;
  terms.push(f ? Math.hypot(f.fx, f.fy) : 0, Math.abs(loads.outputTorque ?? 0) / l.r4);
  return Math.max(...terms);
}

/** A pose taken as exact (radians), optionally with the coupler's and rocker's rates taken as exact too. */
export interface OraclePose {
  theta3: number;
  theta4: number;
  rates?: { omega3: number; omega4: number; alpha3: number; alpha4: number };
}

/**
 * The forces at theta2 on a branch (positions solved here), or at a given pose taken as exact (with the
 * rates derived here, or given: that isolates the force equations from the rates' own rounding). Returns
 * null where the loop cannot close or coupler and rocker are collinear to within NEAR_LIMIT (no unique
 * answer, or none the 40-digit elimination can resolve).
 */
export function oracleForces(
  l: OracleLinkage,
  theta2: number,
  where: 'open' | 'crossed' | OraclePose,
  motion: OracleMotion,
  inertia: OracleInertias,
  loads: OracleLoads,
): OracleForces | null {
  const g =
    typeof where === 'string'
      ? geometryOnBranch(l, theta2, where)
      : geometryOfPose(l, theta2, where.theta3, where.theta4);
  if (
    !g ||
    cross(g.r3, g.r4)
      .abs()
      .div(ex(l.r3).times(ex(l.r4)))
      .lessThan(NEAR_LIMIT)
  )
    return null;
  const given = typeof where === 'string' ? undefined : where.rates;
  const { w3, w4, a3, a4 } = given
    ? { w3: ex(given.omega3), w4: ex(given.omega4), a3: ex(given.alpha3), a4: ex(given.alpha4) }
    : rates(g, motion);
  const w2 = ex(motion.omega2);
  const a2 = ex(motion.alpha2);
  const O2 = v(0, 0);
  const A = g.rA;
  const O4 = v(l.r1, 0);
  const B3 = add(A, g.r3);
  const B4 = add(O4, g.r4);
  const unit = (r: Vec, len: number) => mul(r, ex(1).div(ex(len)));
  const cg = (u: Vec, c: OracleInertia) => mul(rotate(u, c.cg.angle), ex(c.cg.dist));
  const G2 = cg(unit(g.rA, l.r2), inertia.crank);
  const G3 = add(A, cg(unit(g.r3, l.r3), inertia.coupler));
  const G4 = add(O4, cg(unit(g.r4, l.r4), inertia.rocker));
  const aG2 = relAcc(G2, w2, a2);
  const aG3 = add(relAcc(A, w2, a2), relAcc(sub(G3, A), w3, a3));
  const aG4 = relAcc(sub(G4, O4), w4, a4);
  const grav = loads.gravity;
  const gv =
    grav === undefined
      ? v(0, 0)
      : grav.angle === undefined
        ? v(0, -grav.g)
        : v(cosE(grav.angle).times(ex(grav.g)), sinE(grav.angle).times(ex(grav.g)));
  const cf = loads.couplerForce;
  const P = cf ? add(A, mul(rotate(unit(g.r3, l.r3), cf.pAngle), ex(cf.pDist))) : A;
  const Fp = cf ? v(cf.fx, cf.fy) : v(0, 0);
  const T4 = ex(loads.outputTorque ?? 0);
  const m2 = ex(inertia.crank.mass);
  const m3 = ex(inertia.coupler.mass);
  const m4 = ex(inertia.rocker.mass);
  const z = ex(0);
  const one = ex(1);
  // Unknowns: F12x F12y F32x F32y F43x F43y F14x F14y T12.
  const rows: Dec[][] = [];
  const rhs: Dec[] = [];
  const eq = (coef: Array<[number, Dec]>, b: Dec) => {
    const row = new Array<Dec>(9).fill(z);
    for (const [k, c] of coef) row[k] = row[k].plus(c);
    rows.push(row);
    rhs.push(b);
  };
  // Crank: F12 + F32 = m2 (aG2 - g); about G2: (O2 - G2) × F12 + (A - G2) × F32 + T12 = I2 alpha2.
  eq(
    [
      [0, one],
      [2, one],
    ],
    m2.times(aG2.x.minus(gv.x)),
  );
  eq(
    [
      [1, one],
      [3, one],
    ],
    m2.times(aG2.y.minus(gv.y)),
  );
  const c12 = momentRow(sub(O2, G2));
  const c32 = momentRow(sub(A, G2));
  eq(
    [
      [0, c12[0]],
      [1, c12[1]],
      [2, c32[0]],
      [3, c32[1]],
      [8, one],
    ],
    ex(inertia.crank.inertia).times(a2),
  );
  // Coupler: -F32 + F43 + Fp = m3 (aG3 - g); about G3: (A - G3) × (-F32) + (B - G3) × F43 + (P - G3) × Fp = I3 alpha3.
  eq(
    [
      [2, one.neg()],
      [4, one],
    ],
    m3.times(aG3.x.minus(gv.x)).minus(Fp.x),
  );
  eq(
    [
      [3, one.neg()],
      [5, one],
    ],
    m3.times(aG3.y.minus(gv.y)).minus(Fp.y),
  );
  const c23 = momentRow(sub(A, G3));
  const c43 = momentRow(sub(B3, G3));
  eq(
    [
      [2, c23[0].neg()],
      [3, c23[1].neg()],
      [4, c43[0]],
      [5, c43[1]],
    ],
    ex(inertia.coupler.inertia)
      .times(a3)
      .minus(cross(sub(P, G3), Fp)),
  );
  // Rocker: -F43 + F14 = m4 (aG4 - g); about G4: (B - G4) × (-F43) + (O4 - G4) × F14 + T4 = I4 alpha4.
  eq(
    [
      [4, one.neg()],
      [6, one],
    ],
    m4.times(aG4.x.minus(gv.x)),
  );
  eq(
    [
      [5, one.neg()],
      [7, one],
    ],
    m4.times(aG4.y.minus(gv.y)),
  );
  const c34 = momentRow(sub(B4, G4));
  const c14 = momentRow(sub(O4, G4));
  eq(
    [
      [4, c34[0].neg()],
      [5, c34[1].neg()],
      [6, c14[0]],
      [7, c14[1]],
    ],
    ex(inertia.rocker.inertia).times(a4).minus(T4),
  );
  const x = gaussSolve(rows, rhs);
  const pt = (i: number): Pt => ({ x: x[i].toNumber(), y: x[i + 1].toNumber() });
  const mag = (i: number) =>
    x[i]
      .pow(2)
      .plus(x[i + 1].pow(2))
      .sqrt()
      .toNumber();
  const sinMu = cross(g.r3, g.r4)
    .div(ex(l.r3).times(ex(l.r4)))
    .toNumber();
  return {
    torque: x[8].toNumber(),
    F12: pt(0),
    F32: pt(2),
    F43: pt(4),
    F14: pt(6),
    shakingForce: { x: x[0].plus(x[6]).neg().toNumber(), y: x[1].plus(x[7]).neg().toNumber() },
    shakingMoment: x[8]
      .neg()
      .minus(x[7].times(ex(l.r1)))
      .toNumber(),
    sinMu,
    largestForce: Math.max(mag(0), mag(2), mag(4), mag(6)),
    loadScale: loadScale(l, motion, inertia, loads, [aG2, aG3, aG4], [a2, a3, a4]),
  };
}

/** One random case: a linkage, an input angle and branch, the input motion, mass properties and loads. */
export interface ForceCase {
  l: OracleLinkage;
  theta2: number;
  branch: 'open' | 'crossed';
  motion: OracleMotion;
  inertia: OracleInertias;
  loads: OracleLoads;
}

// fc.double draws uniformly over the doubles' bit patterns, so most of its draws in [-pi, pi] are tiny
// (1e-200): uniform reals come from integers, and magnitudes spanning decades from a uniform exponent.
const STEPS = 2 ** 30;
/** Uniform in [lo, hi]. */
export const uniform = (lo: number, hi: number) =>
  fc.integer({ min: 0, max: STEPS }).map((k) => lo + ((hi - lo) * k) / STEPS);
/** Log-uniform in [lo, hi] (both > 0). */
export const decades = (lo: number, hi: number) => uniform(Math.log10(lo), Math.log10(hi)).map((e) => 10 ** e);
/** 0 one time in five, else a log-uniform magnitude in [lo, hi] with a random sign when signed. */
const sizeArb = (lo: number, hi: number, signed = true) =>
  fc.oneof(
    { arbitrary: fc.constant(0), weight: 1 },
    { arbitrary: fc.tuple(decades(lo, hi), fc.constantFrom(1, signed ? -1 : 1)).map(([x, s]) => s * x), weight: 4 },
  );
const angleArb = uniform(-Math.PI, Math.PI);
const lengthArb = decades(0.05, 2);

export const linkInertiaArb: fc.Arbitrary<OracleInertia> = fc.record({
  mass: sizeArb(0.01, 20, false),
  inertia: sizeArb(1e-4, 2, false),
  cg: fc.record({ dist: sizeArb(1e-3, 1), angle: angleArb }),
});

export const loadsArb: fc.Arbitrary<OracleLoads> = fc.record(
  {
    gravity: fc.record({ g: sizeArb(0.1, 20, false), angle: angleArb }, { requiredKeys: ['g'] }),
    couplerForce: fc.record({ pDist: sizeArb(1e-3, 1), pAngle: angleArb, fx: sizeArb(1, 1e3), fy: sizeArb(1, 1e3) }),
    outputTorque: sizeArb(0.1, 200),
  },
  { requiredKeys: [] },
);

/**
 * A linkage that assembles at theta2: O2 at the origin, O4 at (r1, 0), the crank pin A at r2 e^(i theta2)
 * and B anywhere within 2 m, at least 5 cm from A and O4 (A at least 1 cm from O4); r3 and r4 are the
 * distances, the branch the side B is on.
 */
const assemblyArb = fc
  .record({
    r1: lengthArb,
    r2: lengthArb,
    theta2: angleArb,
    bx: uniform(-2, 2),
    by: uniform(-2, 2),
  })
  .map(({ r1, r2, theta2, bx, by }) => {
    const ax = r2 * Math.cos(theta2);
    const ay = r2 * Math.sin(theta2);
    const l = { r1, r2, r3: Math.hypot(bx - ax, by - ay), r4: Math.hypot(bx - r1, by) };
    // B left of the ray from A to O4: (O4 - A) × (B - A) > 0 is the open branch.
    const side = (r1 - ax) * (by - ay) + ay * (bx - ax);
    const ao4 = Math.hypot(r1 - ax, ay);
    return { l, theta2, branch: side > 0 ? ('open' as const) : ('crossed' as const), ao4 };
  })
  .filter(({ l, ao4 }) => l.r3 >= 0.05 && l.r4 >= 0.05 && ao4 >= 0.01)
  .map(({ l, theta2, branch }) => ({ l, theta2, branch }));

/**
 * Random cases in SI: ground and crank 5 cm to 2 m (coupler and rocker to 4.8 m), masses to 20 kg,
 * |omega2| from 0.1 to 300 rad/s, loads to 1 kN; each mass, inertia, CG offset and load is 0 one time in five.
 */
export const forceCaseArb: fc.Arbitrary<ForceCase> = fc
  .record({
    assembly: assemblyArb,
    motion: fc.record({
      omega2: fc.tuple(decades(0.1, 300), fc.constantFrom(1, -1)).map(([w, s]) => s * w),
      alpha2: sizeArb(1, 1e3),
    }),
    inertia: fc.record({ crank: linkInertiaArb, coupler: linkInertiaArb, rocker: linkInertiaArb }),
    loads: loadsArb,
  })
  .map(({ assembly, ...rest }) => ({ ...assembly, ...rest }));

/** What a test compares: the fields of JointForces. */
export interface ForcesLike {
  torque: number;
  F12: Pt;
  F32: Pt;
  F43: Pt;
  F14: Pt;
  shakingForce: Pt;
  shakingMoment: number;
}

/** The longest lever arm of a case (m): a link, a CG offset or the coupler point's distance. */
export function leverArm(c: { l: OracleLinkage; inertia: OracleInertias; loads: OracleLoads }): number {
  const { l, inertia, loads } = c;
  const cgs = [inertia.crank, inertia.coupler, inertia.rocker].map((k) => Math.abs(k.cg.dist));
  return Math.max(l.r1, l.r2, l.r3, l.r4, ...cgs, Math.abs(loads.couplerForce?.pDist ?? 0));
}

/**
 * The error of got against ref as a fraction of the problem's force scale W = max(largest pin force,
 * loadScale): each force component's error over W, the torque's and shaking moment's over W times the
 * longest lever arm. NaN anywhere gives Infinity.
 */
export function forceError(got: ForcesLike, ref: OracleForces, arm: number): number {
  const W = Math.max(ref.largestForce, ref.loadScale, Number.MIN_VALUE);
  const keys = ['F12', 'F32', 'F43', 'F14', 'shakingForce'] as const;
  const errs = keys.flatMap((k) => [Math.abs(got[k].x - ref[k].x), Math.abs(got[k].y - ref[k].y)]);
  const e = Math.max(
    ...errs.map((x) => x / W),
    Math.abs(got.torque - ref.torque) / (W * arm),
    Math.abs(got.shakingMoment - ref.shakingMoment) / (W * arm),
  );
  return Number.isNaN(e) ? Infinity : e;
}

/** A link's CG position (m), velocity (m/s) and acceleration (m/s²), angular rates, mass and inertia. */
export interface LinkMotion {
  G: Pt;
  vG: Pt;
  aG: Pt;
  omega: number;
  alpha: number;
  mass: number;
  inertia: number;
}

/** Coupler and rocker angular rates (rad/s, rad/s²), as the solver's linkRates returns them. */
export interface OracleRates {
  omega3: number;
  omega4: number;
  alpha3: number;
  alpha4: number;
}

/** A point on a link: at joint J (moving with vJ, aJ) plus d along the link's direction phi rotated by angle. */
function pointOnLink(
  J: Pt,
  vJ: Pt,
  aJ: Pt,
  phi: number,
  d: number,
  angle: number,
  w: number,
  a: number,
): { P: Pt; v: Pt; acc: Pt } {
  const r = { x: d * Math.cos(phi + angle), y: d * Math.sin(phi + angle) };
  return {
    P: { x: J.x + r.x, y: J.y + r.y },
    // v = vJ + omega k × r; a = aJ + alpha k × r - omega² r.
    v: { x: vJ.x - w * r.y, y: vJ.y + w * r.x },
    acc: { x: aJ.x - a * r.y - w * w * r.x, y: aJ.y + a * r.x - w * w * r.y },
  };
}

/**
 * Each link's CG motion (crank, coupler, rocker) at a pose with the given rates, in double precision,
 * and the coupler point's position and velocity: relative motion from O2, A and O4, nothing else.
 */
export function linkMotions(
  l: OracleLinkage,
  theta2: number,
  pose: { theta3: number; theta4: number },
  motion: OracleMotion,
  rates: OracleRates,
  inertia: OracleInertias,
  loads: OracleLoads,
): { links: LinkMotion[]; P: Pt; vP: Pt } {
  const { omega2: w2, alpha2: a2 } = motion;
  const O: Pt = { x: 0, y: 0 };
  const crankPin = pointOnLink(O, O, O, theta2, l.r2, 0, w2, a2);
  const link = (J: { P: Pt; v: Pt; acc: Pt }, phi: number, c: OracleInertia, w: number, a: number): LinkMotion => {
    const g = pointOnLink(J.P, J.v, J.acc, phi, c.cg.dist, c.cg.angle, w, a);
    return { G: g.P, vG: g.v, aG: g.acc, omega: w, alpha: a, mass: c.mass, inertia: c.inertia };
  };
  const ground = { P: { x: l.r1, y: 0 }, v: O, acc: O };
  const links = [
    link({ P: O, v: O, acc: O }, theta2, inertia.crank, w2, a2),
    link(crankPin, pose.theta3, inertia.coupler, rates.omega3, rates.alpha3),
    link(ground, pose.theta4, inertia.rocker, rates.omega4, rates.alpha4),
  ];
  const cf = loads.couplerForce;
  const p = pointOnLink(
    crankPin.P,
    crankPin.v,
    crankPin.acc,
    pose.theta3,
    cf?.pDist ?? 0,
    cf?.pAngle ?? 0,
    rates.omega3,
    rates.alpha3,
  );
  return { links, P: p.P, vP: p.v };
}

/** Gravity as a vector (m/s²): default straight down. */
export function gravityVector(loads: OracleLoads): Pt {
  const g = loads.gravity;
  if (!g) return { x: 0, y: 0 };
  if (g.angle === undefined) return { x: 0, y: -g.g };
  return { x: g.g * Math.cos(g.angle), y: g.g * Math.sin(g.angle) };
}
