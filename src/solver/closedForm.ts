import { PI } from './angles';
import { exactSumOfProducts, halfUlp, sumOfProducts } from './exact';
import type { DD } from './exact';
import type { Angles, Branch, Linkage } from './types';
import { checkFinite, describe, normalizeLinkage, scaleByPow2, validateLinkage } from './validate';

// A module-local copy of the units module's pi, read per point: loaders that turn imports into
// getters (vite-node) would otherwise call a getter on every read.
const HALF_TURN = PI;

const EPS = Number.EPSILON;
/** Sum2 error bound for the plan's constants (14 terms of size < 4): below it the exact sum is taken. */
const EXACT_BELOW = 1e-26;
/** Below this |A O4| (normalised) s^2 underflows and the closed form switches to s-scaled formulas. */
const TINY_S = 1e-120;

/** Outcome of one closed-form evaluation. */
export const Assembly = {
  /** Assembles; both branches distinct. */
  Ok: 0,
  /** Assembles at a limit (toggle/fold) position: the triangle is flat within rounding, both branches coincide. */
  Limit: 1,
  /** The loop cannot close at this input angle. */
  Unreachable: 2,
  /** The crank pin sits on the rocker pivot with r3 = r4: every theta3 = theta4 closes the loop. */
  Continuum: 3,
} as const;

/** Numeric assembly status (see Assembly). */
export type Assembly = (typeof Assembly)[keyof typeof Assembly];

/**
 * Per-linkage constants of the stable closed form (lengths normalised by a power of two).
 * For each of three input-angle regions s^2 = base + m(theta2), and every quantity the
 * solution needs is (constant - or + m): the constants are kept as double-doubles so the
 * only rounding left per point is in m itself, which is as accurate as cos/sin of theta2.
 */
export interface ClosedFormPlan {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
  /** Normalised lengths times 2^exponent are the user's lengths. */
  exponent: number;
  /** 2 r1 r2 (normalised). */
  k2: number;
  /** 1 / r3 and 1 / r4 (normalised). */
  inv3: number;
  inv4: number;
  /** r1 - r2 as a double-double, for dx near theta2 = 0. */
  d12: DD;
  /** Region constants, flat: [8 region + 2 j] = hi, [8 region + 2 j + 1] = lo for j = Ap, Am, X3, X4 where Ap = (r3+r4)^2 - base, Am = base - (r3-r4)^2,
   *  X3 = r3^2 - r4^2 + base, X4 = r4^2 - r3^2 + base. Regions: 0 near theta2 = 0, 1 middle, 2 near pi. */
  consts: Float64Array;
  /** 2^exponent when representable, else 0 (use scaleByPow2). */
  unscale: number;
}

/** Scratch output of closedFormAt; reused across a sweep to avoid allocation. */
export interface ClosedFormPoint {
  theta3: number;
  theta4: number;
  cos3: number;
  sin3: number;
  cos4: number;
  sin4: number;
  /** cos and sin of theta2, as the loop residual used them. */
  cos2: number;
  sin2: number;
  /** Loop-closure residual (f1, f2) and its norm, in normalised units. */
  f1: number;
  f2: number;
  residual: number;
}

/** The last plan built, reused while the lengths are the same (a sweep per frame re-plans otherwise). */
let lastPlan: ClosedFormPlan | null = null;
let lastLengths: Linkage = { r1: NaN, r2: NaN, r3: NaN, r4: NaN };

/** Builds (or reuses) the per-linkage constants for closedFormAt; validates the linkage, throws on bad input. */
export function planClosedForm(l: Linkage): ClosedFormPlan {
  validateLinkage(l);
  const k = lastLengths;
  if (lastPlan !== null && l.r1 === k.r1 && l.r2 === k.r2 && l.r3 === k.r3 && l.r4 === k.r4) return lastPlan;
  const plan = buildPlan(l);
  lastPlan = plan;
  lastLengths = { r1: l.r1, r2: l.r2, r3: l.r3, r4: l.r4 };
  return plan;
}

function buildPlan(l: Linkage): ClosedFormPlan {
  const n = normalizeLinkage(l);
  const { r1, r2, r3, r4 } = n;
  const sq = (x: number): readonly [number, number] => [x, x];
  const bases: Array<ReadonlyArray<number | readonly [number, number]>> = [
    [sq(r1), sq(r2), [-2 * r1, r2]], // (r1 - r2)^2
    [sq(r1), sq(r2)], // r1^2 + r2^2
    [sq(r1), sq(r2), [2 * r1, r2]], // (r1 + r2)^2
  ];
  const neg = (terms: ReadonlyArray<number | readonly [number, number]>) =>
    terms.map((t) => (typeof t === 'number' ? -t : ([-t[0], t[1]] as const)));
  const consts = new Float64Array(24);
  // Sum2 is accurate to about (n eps)^2 of the terms' size (lengths < 1 here); a constant that small
  // may be an exact tie (a flat chain, a change point), so it is recomputed exactly.
  const constant = (terms: ReadonlyArray<number | readonly [number, number]>): DD => {
    const dd = sumOfProducts(terms);
    return Math.abs(dd.hi) > EXACT_BELOW ? dd : exactSumOfProducts(terms);
  };
  bases.forEach((base, region) => {
    const dds = [
      constant([sq(r3), sq(r4), [2 * r3, r4], ...neg(base)]),
      constant([...base, [-r3, r3], [-r4, r4], [2 * r3, r4]]),
      constant([sq(r3), [-r4, r4], ...base]),
      constant([sq(r4), [-r3, r3], ...base]),
    ];
    dds.forEach((dd, j) => {
      consts[8 * region + 2 * j] = dd.hi;
      consts[8 * region + 2 * j + 1] = dd.lo;
    });
  });
  const d = r1 - r2;
  return {
    r1,
    r2,
    r3,
    r4,
    exponent: n.exponent,
    k2: 2 * r1 * r2,
    inv3: 1 / r3,
    inv4: 1 / r4,
    d12: { hi: d, lo: r1 - d - r2 },
    consts,
    unscale: Math.abs(n.exponent) <= 1000 ? 2 ** n.exponent : 0,
  };
}

/** atan2 wrapped to (-pi, pi] (atan2 gives -pi for a negative zero). */
export function wrapAtan2(y: number, x: number): number {
  const t = Math.atan2(y, x);
  return t === -HALF_TURN ? HALF_TURN : t;
}

/** Triangle factors of one input angle, filled in by assemblyFactors (normalised units). */
export interface AssemblyFactors {
  cos2: number;
  sin2: number;
  /** Vector from the crank pin A to O4. */
  dx: number;
  dy: number;
  /** (r3 + r4)^2 - s^2 and s^2 - (r3 - r4)^2, clamped to 0 at a limit. */
  dPlus: number;
  dMinus: number;
  /** r3^2 - r4^2 + s^2 and r4^2 - r3^2 + s^2. */
  x3: number;
  x4: number;
}

/** Fresh scratch factors for assemblyFactors. */
export function newAssemblyFactors(): AssemblyFactors {
  return { cos2: 1, sin2: 0, dx: 0, dy: 0, dPlus: 0, dMinus: 0, x3: 0, x4: 0 };
}

/** Rounding of a double-double constant (relative): what is left of the constants' error. */
const TINY_CONST = 4 * EPS * EPS;

/**
 * The verdict for factors within their quick tolerance: tolP and tolM are the rounding allowances of
 * dPlus and dMinus, and any angle within half an ulp of theta2 counts (s^2 moves by
 * k2 (|sin t2| h + h^2) over it, given here as k2Sin = k2 |sin t2| and k2).
 */
function limitVerdict(
  dPlus: number,
  dMinus: number,
  tolP: number,
  tolM: number,
  k2Sin: number,
  k2: number,
  theta2: number,
): Assembly {
  const hu = halfUlp(theta2);
  const exactBand = (k2Sin + k2 * hu) * hu;
  const bandP = tolP + exactBand;
  const bandM = tolM + exactBand;
  if (dPlus < -bandP || dMinus < -bandM) return Assembly.Unreachable;
  if (dPlus < bandP || dMinus < bandM) return Assembly.Limit;
  return Assembly.Ok;
}

/**
 * Whether the loop closes at theta2 (radians), and the triangle (s, r3, r4) it closes with.
 * 16 area^2 = ((r3+r4)^2 - s^2)(s^2 - (r3-r4)^2) is formed factor by factor without
 * cancellation (docs/hard-cases.md, "A stable form"), so the reachability verdict is as exact as
 * cos and sin of theta2 are.
 */
export function assemblyFactors(plan: ClosedFormPlan, theta2: number, f: AssemblyFactors): Assembly {
  const { r1, r2, k2 } = plan;
  const c = Math.cos(theta2);
  const sn = Math.sin(theta2);
  let region: number;
  let m: number;
  let dx: number;
  if (c > 0.5) {
    // 1 - cos t2 = sin^2 t2 / (1 + cos t2): no cancellation near t2 = 0.
    const oneMinusC = (sn * sn) / (1 + c);
    region = 0;
    m = k2 * oneMinusC;
    dx = plan.d12.hi + r2 * oneMinusC + plan.d12.lo;
  } else if (c < -0.5) {
    const onePlusC = (sn * sn) / (1 - c);
    region = 2;
    m = -k2 * onePlusC;
    dx = r1 - r2 * c;
  } else {
    region = 1;
    m = -k2 * c;
    dx = r1 - r2 * c;
  }
  const dy = -r2 * sn;
  const k = plan.consts;
  const o = 8 * region;
  let dPlus = k[o] - m + k[o + 1];
  let dMinus = k[o + 2] + m + k[o + 3];
  f.cos2 = c;
  f.sin2 = sn;
  f.dx = dx;
  f.dy = dy;
  f.x3 = k[o + 4] + m + k[o + 5];
  f.x4 = k[o + 6] + m + k[o + 7];
  // Each factor is (exact double-double constant) -/+ m; m carries the rounding of cos/sin t2 (a few
  // ulps of m). A factor within that of zero is a limit. The verdict is about the angle the double
  // theta2 stands for, so any angle within half an ulp of theta2 that closes the loop makes it a
  // limit too (fl(pi) reaches a flat chain closing only at pi); that moves s^2 by k2 (|sin t2| h + h^2).
  const mTol = 8 * EPS * Math.abs(m);
  const h = EPS * Math.abs(theta2); // >= one ulp of theta2: a quick bound first
  const band = k2 * (Math.abs(sn) + h) * h;
  let status: Assembly = Assembly.Ok;
  if (dPlus < mTol + band + TINY_CONST * Math.abs(k[o]) || dMinus < mTol + band + TINY_CONST * Math.abs(k[o + 2])) {
    status = limitVerdict(
      dPlus,
      dMinus,
      mTol + TINY_CONST * Math.abs(k[o]),
      mTol + TINY_CONST * Math.abs(k[o + 2]),
      k2 * Math.abs(sn),
      k2,
      theta2,
    );
    if (status === Assembly.Unreachable) return status;
    if (status === Assembly.Limit) {
      if (dPlus < 0) dPlus = 0;
      if (dMinus < 0) dMinus = 0;
    }
  }
  f.dPlus = dPlus;
  f.dMinus = dMinus;
  // Crank pin on O4: s = 0, so r3 = r4 (else dMinus < 0 above) and any theta3 = theta4 closes the loop.
  if (dx === 0 && dy === 0) return Assembly.Continuum;
  if (Math.abs(dx) + Math.abs(dy) < TINY_S) {
    // s^2 underflows here, so the factors above lost s: decide with |r3 - r4| <= s directly.
    const sLen = Math.hypot(dx, dy);
    if (Math.abs(plan.r3 - plan.r4) > sLen * (1 + 8 * EPS)) return Assembly.Unreachable;
  }
  return status;
}

const scratchFactors = newAssemblyFactors();

/**
 * Stable closed-form position at theta2 (radians) on branch sigma (+1 open, -1 crossed).
 * Writes the pose into out and returns the assembly status. theta3 = beta + sigma psi and
 * theta4 = beta + pi - sigma gamma are read off complex products (A->O4 rotated by the
 * triangle's angles), so only two atan2 calls are needed and cos/sin come for free.
 */
export function closedFormAt(plan: ClosedFormPlan, theta2: number, sigma: number, out: ClosedFormPoint): Assembly {
  const f = scratchFactors;
  const status = assemblyFactors(plan, theta2, f);
  if (status === Assembly.Unreachable) return status;
  const { r1, r2, r3, r4 } = plan;
  const { dx, dy, x3, x4 } = f;
  if (status === Assembly.Continuum) {
    const t = sigma > 0 ? theta2 : theta2 + HALF_TURN;
    const w = wrapAtan2(Math.sin(t), Math.cos(t));
    out.theta3 = w;
    out.theta4 = w;
    out.cos3 = out.cos4 = Math.cos(w);
    out.sin3 = out.sin4 = Math.sin(w);
    out.cos2 = f.cos2;
    out.sin2 = f.sin2;
    out.f1 = out.f2 = out.residual = 0;
    return status;
  }
  const { cos2, sin2 } = f;
  if (Math.abs(dx) + Math.abs(dy) >= TINY_S) {
    const y = sigma * Math.sqrt(f.dPlus) * Math.sqrt(f.dMinus);
    const re3 = dx * x3 - dy * y;
    const im3 = dx * y + dy * x3;
    const re4 = -(dx * x4 + dy * y);
    const im4 = dx * y - dy * x4;
    out.theta3 = wrapAtan2(im3, re3);
    out.theta4 = wrapAtan2(im4, re4);
    // |re3 + i im3| = s |x3 + i y| = 2 r3 s^2 (law of cosines: x3 = 2 r3 s cos psi, y = 2 r3 s sin psi),
    // and |re4 + i im4| = 2 r4 s^2: one division gives all four cos/sin, no square roots.
    const half = 0.5 / (dx * dx + dy * dy);
    const u3 = re3 * half; // r3 cos t3
    const v3 = im3 * half;
    const u4 = re4 * half; // r4 cos t4
    const v4 = im4 * half;
    out.cos3 = u3 * plan.inv3;
    out.sin3 = v3 * plan.inv3;
    out.cos4 = u4 * plan.inv4;
    out.sin4 = v4 * plan.inv4;
    const f1 = r2 * cos2 + u3 - u4 - r1;
    const f2 = r2 * sin2 + v3 - v4;
    out.cos2 = cos2;
    out.sin2 = sin2;
    out.f1 = f1;
    out.f2 = f2;
    out.residual = Math.sqrt(f1 * f1 + f2 * f2);
    return status;
  } else {
    // |A O4| = s so small that s^2 underflows: divide the triangle's X and Y by s, with
    // q = (r3 - r4) / s: X3 / s = q (r3 + r4) + s, X4 / s = s - q (r3 + r4), Y / s = sqrt(dPlus (1 - q^2)).
    const sLen = Math.hypot(dx, dy);
    const q = Math.max(-1, Math.min(1, (r3 - r4) / sLen));
    const ys = Math.sqrt(f.dPlus) * Math.sqrt((1 - q) * (1 + q));
    const beta = Math.atan2(dy, dx);
    const psi = Math.atan2(ys, q * (r3 + r4) + sLen);
    const gamma = Math.atan2(ys, sLen - q * (r3 + r4));
    const a3 = beta + sigma * psi;
    const a4 = beta + HALF_TURN - sigma * gamma;
    out.cos3 = Math.cos(a3);
    out.sin3 = Math.sin(a3);
    out.cos4 = Math.cos(a4);
    out.sin4 = Math.sin(a4);
    out.theta3 = wrapAtan2(out.sin3, out.cos3);
    out.theta4 = wrapAtan2(out.sin4, out.cos4);
  }
  const f1 = r2 * cos2 + r3 * out.cos3 - r4 * out.cos4 - r1;
  const f2 = r2 * sin2 + r3 * out.sin3 - r4 * out.sin4;
  out.cos2 = cos2;
  out.sin2 = sin2;
  out.f1 = f1;
  out.f2 = f2;
  out.residual = Math.sqrt(f1 * f1 + f2 * f2);
  return status;
}

/** Fresh scratch point for closedFormAt. */
export function newClosedFormPoint(): ClosedFormPoint {
  return { theta3: 0, theta4: 0, cos3: 1, sin3: 0, cos4: 1, sin4: 0, cos2: 1, sin2: 0, f1: 0, f2: 0, residual: 0 };
}

/** +1 for the open branch, -1 for crossed. */
export function branchSign(branch: Branch): number {
  if (branch === 'open') return 1;
  if (branch === 'crossed') return -1;
  throw new Error(`branch must be 'open' or 'crossed', got ${describe(branch)}`);
}

/**
 * Closed-form coupler and rocker angles (radians, wrapped to (-pi, pi]) at theta2 (radians).
 * Returns null when the loop cannot close at theta2. Where the crank pin lies on O4 with r3 = r4
 * (a continuum of assemblies) it returns one member (theta3 = theta4 = theta2 for open, theta2 + pi
 * for crossed) flagged continuum: true. Throws for a linkage that is not four positive finite lengths.
 */
export function solveClosedForm(
  l: Linkage,
  theta2: number,
  branch: Branch,
): (Angles & { limit: boolean; continuum: boolean }) | null {
  const plan = planClosedForm(l);
  checkFinite('theta2', theta2, 'angle in radians');
  const p = newClosedFormPoint();
  const status = closedFormAt(plan, theta2, branchSign(branch), p);
  if (status === Assembly.Unreachable) return null;
  return {
    theta3: p.theta3,
    theta4: p.theta4,
    limit: status === Assembly.Limit,
    continuum: status === Assembly.Continuum,
  };
}

/** The arrays closedFormSweep fills, one entry per input angle. */
export interface ClosedFormColumns {
  theta2: Float64Array;
  theta3: Float64Array;
  theta4: Float64Array;
  /** Loop-closure residual norm in the user's length unit. */
  residual: Float64Array;
  /** 0 ok, 1 unreachable, 2 singular (a continuum), as POINT_STATUSES. */
  statusCodes: Uint8Array;
}

const fallbackPoint = newClosedFormPoint();

/**
 * closedFormAt over every theta2 (radians) on branch sigma, written into the columns (NaN angles and
 * residual where the loop does not close). The common case (a reachable point clear of its limits,
 * |A O4| not tiny) runs here inline, the same arithmetic as assemblyFactors and closedFormAt without
 * their scratch objects; every other point goes through closedFormAt itself, so the limit verdict,
 * the continuum and the tiny-s formulas live in one place. The result equals closedFormAt's bit for
 * bit (tests/solver/closedForm.test.ts).
 */
export function closedFormSweep(
  plan: ClosedFormPlan,
  theta2s: ArrayLike<number>,
  sigma: number,
  out: ClosedFormColumns,
): void {
  const { r1, r2, k2, consts: k, unscale, exponent } = plan;
  const d12hi = plan.d12.hi;
  const d12lo = plan.d12.lo;
  const { theta2: th2, theta3: th3, theta4: th4, residual: res, statusCodes: codes } = out;
  const p = fallbackPoint;
  for (let i = 0; i < theta2s.length; i++) {
    const t2 = theta2s[i];
    th2[i] = t2;
    const c = Math.cos(t2);
    const sn = Math.sin(t2);
    let o: number;
    let m: number;
    let dx: number;
    if (c > 0.5) {
      const oneMinusC = (sn * sn) / (1 + c);
      o = 0;
      m = k2 * oneMinusC;
      dx = d12hi + r2 * oneMinusC + d12lo;
    } else if (c < -0.5) {
      o = 16;
      m = -k2 * ((sn * sn) / (1 - c));
      dx = r1 - r2 * c;
    } else {
      o = 8;
      m = -k2 * c;
      dx = r1 - r2 * c;
    }
    const dy = -r2 * sn;
    const dPlus = k[o] - m + k[o + 1];
    const dMinus = k[o + 2] + m + k[o + 3];
    const h = EPS * Math.abs(t2);
    const quick = 8 * EPS * Math.abs(m) + k2 * (Math.abs(sn) + h) * h;
    if (
      dPlus < quick + TINY_CONST * Math.abs(k[o]) ||
      dMinus < quick + TINY_CONST * Math.abs(k[o + 2]) ||
      Math.abs(dx) + Math.abs(dy) < TINY_S
    ) {
      // Near a limit, past it, or the crank pin (almost) on O4: the careful path.
      const a = closedFormAt(plan, t2, sigma, p);
      if (a === Assembly.Unreachable || a === Assembly.Continuum) {
        th3[i] = NaN;
        th4[i] = NaN;
        res[i] = NaN;
        codes[i] = a === Assembly.Unreachable ? 1 : 2;
        continue;
      }
      th3[i] = p.theta3;
      th4[i] = p.theta4;
      res[i] = unscale !== 0 ? p.residual * unscale : scaleByPow2(p.residual, exponent);
      codes[i] = 0;
      continue;
    }
    const x3 = k[o + 4] + m + k[o + 5];
    const x4 = k[o + 6] + m + k[o + 7];
    const y = sigma * Math.sqrt(dPlus) * Math.sqrt(dMinus);
    const re3 = dx * x3 - dy * y;
    const im3 = dx * y + dy * x3;
    const re4 = -(dx * x4 + dy * y);
    const im4 = dx * y - dy * x4;
    th3[i] = wrapAtan2(im3, re3);
    th4[i] = wrapAtan2(im4, re4);
    const half = 0.5 / (dx * dx + dy * dy);
    const f1 = r2 * c + re3 * half - re4 * half - r1;
    const f2 = r2 * sn + im3 * half - im4 * half;
    const rn = Math.sqrt(f1 * f1 + f2 * f2);
    res[i] = unscale !== 0 ? rn * unscale : scaleByPow2(rn, exponent);
    codes[i] = 0;
  }
}
