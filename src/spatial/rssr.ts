import { PI, TWO_PI } from '../solver';
import { Closure, newPoint } from './point';
import { outputRates, wrapSmall } from './point';
import type { SpatialPoint } from './point';
import { poseOf } from './spherical';
import type { RSSRLinkage, SpatialBranch, SpatialInput, SpatialPose } from './types';
import { branchSigma, checkFinite, validateInput, validateRSSR } from './validate';

const HALF_TURN = PI;
const FULL_TURN = TWO_PI;
const EPS = Number.EPSILON;

/** Per-linkage constants of the RSSR solve: lengths divided by 2^exponent (the longest in [1, 2)), so no square overflows. */
export interface RSSRPlan {
  r2: number;
  r3: number;
  r4: number;
  a: number;
  h2: number;
  h4: number;
  cb: number;
  sb: number;
  /** r2 - a, p at theta2 = 0. */
  r2ma: number;
  /** Working lengths times 2^exponent are the user's. */
  exponent: number;
  /** 2^exponent (the user's unit per working unit). */
  unit: number;
}

/** x times 2^e, in two steps so neither factor overflows. */
function timesPow2(x: number, e: number): number {
  const h = Math.trunc(e / 2);
  return x * 2 ** h * 2 ** (e - h);
}

/** Validates l (throws an Error naming the field) and returns the solve's constants. */
export function planRSSR(l: RSSRLinkage): RSSRPlan {
  validateRSSR(l);
  const longest = Math.max(l.r2, l.r3, l.r4, l.a, Math.abs(l.h2), Math.abs(l.h4));
  const exponent = Math.floor(Math.log2(longest));
  const n = (x: number) => timesPow2(x, -exponent);
  const r2 = n(l.r2);
  const a = n(l.a);
  return {
    r2,
    r3: n(l.r3),
    r4: n(l.r4),
    a,
    h2: n(l.h2),
    h4: n(l.h4),
    cb: Math.cos(l.beta),
    sb: Math.sin(l.beta),
    r2ma: r2 - a,
    exponent,
    unit: 2 ** exponent,
  };
}

/**
 * Solves the RSSR loop at theta2 on branch sigma (-1 open, +1 crossed) into p (working units). With C the rocker
 * circle's centre, A - C = p e1 + q e2 + z w: the coupler's reach in the rocker's plane is r3' = sqrt(r3^2 - z^2) and
 * theta4 = phi + sigma psi, phi = atan2(q, p), psi the angle at C of the plane triangle (m = |(p, q)|, r4, r3'), from
 * tan(psi/2) = sqrt((s - m)(s - r4) / (s (s - r3'))) (flat-triangle safe). F = |A - B|^2/2 - r3^2/2; F4 = sigma r4 m sin psi.
 */
export function rssrAt(plan: RSSRPlan, theta2: number, sigma: number, p: SpatialPoint): Closure {
  const { r2, r3, r4, a, h2, h4, cb, sb } = plan;
  const c2 = Math.cos(theta2);
  const s2 = Math.sin(theta2);
  const hs = Math.sin(theta2 / 2);
  // p = r2 cos theta2 - a = (r2 - a) - 2 r2 sin^2(theta2/2): no cancellation near theta2 = 0 when r2 is close to a.
  const pp = plan.r2ma - 2 * r2 * hs * hs;
  const q = r2 * s2 * cb + h2 * sb;
  const z = -r2 * s2 * sb + h2 * cb - h4;
  const az = Math.abs(z);
  if (az > r3 + 4 * EPS * (r2 + Math.abs(h2) + Math.abs(h4) + r3)) return Closure.Unreachable;
  // Exactly r3 in a plane (z = 0): the planar limit keeps src/solver's flat positions flat.
  const r3p = az === 0 ? r3 : az >= r3 ? 0 : Math.sqrt(r3 - az) * Math.sqrt(r3 + az);
  let m = Math.sqrt(pp * pp + q * q);
  if (m < 1e-150) m = Math.hypot(pp, q);
  const g1 = r4 + r3p - m;
  const g2 = m + r3p - r4;
  const g3 = m + r4 - r3p;
  const sum = m + r4 + r3p;
  const tol = 4 * EPS * sum;
  if (g1 < -tol || g2 < -tol || g3 < -tol) return Closure.Unreachable;
  const limit = g1 <= 0 || g2 <= 0 || g3 <= 0 || az >= r3;
  const psi =
    2 *
    Math.atan2(Math.sqrt(Math.max(0, g1)) * Math.sqrt(Math.max(0, g2)), Math.sqrt(sum) * Math.sqrt(Math.max(0, g3)));
  const phi = Math.atan2(q, pp);
  const t4 = wrapSmall(phi + sigma * psi, HALF_TURN, FULL_TURN);
  const c4 = Math.cos(t4);
  const s4 = Math.sin(t4);
  p.theta4 = t4;
  p.cos4 = c4;
  p.sin4 = s4;
  p.ax = r2 * c2;
  p.ay = r2 * s2;
  p.az = h2;
  // B = (a, 0, 0) + h4 w + r4 (cos theta4 e1 + sin theta4 e2), w = (0, -sin beta, cos beta), e2 = (0, cos beta, sin beta).
  p.bx = a + r4 * c4;
  p.by = -h4 * sb + r4 * s4 * cb;
  p.bz = h4 * cb + r4 * s4 * sb;
  p.dax = -p.ay;
  p.day = p.ax;
  p.ddax = -p.ax;
  p.dday = -p.ay;
  p.dbx = -r4 * s4;
  p.dby = r4 * c4 * cb;
  p.dbz = r4 * c4 * sb;
  p.ddbx = -r4 * c4;
  p.ddby = -r4 * s4 * cb;
  p.ddbz = -r4 * s4 * sb;
  // A - B in the rocker's frame: (p - r4 cos theta4) e1 + (q - r4 sin theta4) e2 + z w.
  const de1 = pp - r4 * c4;
  const de2 = q - r4 * s4;
  const dx = de1;
  const dy = de2 * cb - z * sb;
  p.f2 = dx * p.dax + dy * p.day;
  p.f4 = limit ? 0 : sigma * r4 * m * Math.sin(psi);
  // Transmission angle analogue: (A - B) against the rocker's tangent and its inward radius at B.
  p.mu = Math.atan2(Math.abs(-s4 * pp + c4 * q), r4 - c4 * pp - s4 * q);
  return limit ? Closure.Limit : Closure.Ok;
}

/** Fills p.omega4 and p.alpha4 for omega2 (rad/s), alpha2 (rad/s^2) after rssrAt (working units). */
export function rssrRates(plan: RSSRPlan, p: SpatialPoint, omega2: number, alpha2: number): void {
  const { r2, r4, cb } = plan;
  const s2 = p.ay / r2;
  const c2 = p.ax / r2;
  const dx = p.ax - p.bx;
  const dy = p.ay - p.by;
  const f22 = r2 * r2 - r2 * (c2 * dx + s2 * dy);
  const f24 = -r2 * r4 * (s2 * p.sin4 + c2 * p.cos4 * cb);
  // F22 = |A'|^2 + (A - B) . A'', F24 = -A' . B', F44 = |B'|^2 - (A - B) . B''.
  const f44 = r4 * r4 - (dx * p.ddbx + dy * p.ddby + (p.az - p.bz) * p.ddbz);
  outputRates(p, f22, f24, f44, omega2, alpha2);
}

/**
 * Solves an RSSR linkage at input angle theta2 (radians) on the branch given ('open' where (A - B) . dB/dtheta4 > 0):
 * pin positions in the linkage's length unit, theta4 in (-pi, pi], and with input = { omega2 (rad/s), alpha2 (rad/s^2) }
 * the exact rates from the differentiated constraint |A - B| = r3. Returns null where the loop cannot close. Throws an
 * Error naming the field for a bad linkage, theta2, branch or input.
 */
export function solveRSSR(
  l: RSSRLinkage,
  theta2: number,
  branch: SpatialBranch,
  input?: SpatialInput,
): SpatialPose | null {
  const plan = planRSSR(l);
  checkFinite('theta2', theta2, 'angle in radians');
  const sigma = branchSigma(branch);
  validateInput(input);
  const p = newPoint();
  if (rssrAt(plan, theta2, sigma, p) === Closure.Unreachable) return null;
  const omega2 = input?.omega2 ?? 0;
  const alpha2 = input?.alpha2 ?? 0;
  rssrRates(plan, p, omega2, alpha2);
  return poseOf(p, omega2, alpha2, null, plan.unit);
}
