/**
 * Independent 60-digit oracle for the design metrics: dead centres, rocker swing, time ratio,
 * transmission-angle extremes and instant centres.
 *
 * As in reference.ts, every double input is taken as the exact binary value it holds and the geometry is
 * evaluated with decimal.js at 60 significant digits. The derivations deliberately differ from the
 * solver's (half-angle forms of signed sums, cancellation-free identities for differences):
 * - dead centre: B is the intersection of the circles |O2 B| = d and |O4 B| = r4 in coordinates
 *   (x = (r1^2 + d^2 - r4^2) / (2 r1), y = +-sqrt(d^2 - x^2)); of the two candidates the one whose pose
 *   has sign(sin(theta4 - theta3)) = sigma is kept; the angles are read off with atan2;
 * - swing and time ratio: plain differences of those 60-digit angles (60 digits absorb the cancellation);
 * - transmission: the reachable band cU <= cos theta2 <= cL (reference.ts referenceLimits) and
 *   mu = acos((r3^2 + r4^2 - s^2) / (2 r3 r4)) at the band's ends;
 * - instant centres: Cramer's rule on the two lines through the joint points.
 * Nothing here imports from src.
 */
import Decimal from 'decimal.js';
import { exact, exactAngle } from './reference';
import type { LinkLengths, Sigma } from './reference';

const D = Decimal.clone({ precision: 60, rounding: Decimal.ROUND_HALF_EVEN, minE: -9e15, maxE: 9e15 });
type Dec = InstanceType<typeof D>;

const PI: Dec = D.acos(-1);
const TWO_PI: Dec = PI.times(2);
/** Rounding of the 60-digit arithmetic itself, when a quantity must be exactly 0. */
const FUZZ: Dec = new D('1e-50');

/** A dead centre as the oracle finds it (rad, rounded once to double, wrapped to (-pi, pi]). */
export interface ReferenceDeadCentre {
  theta2: number;
  theta4: number;
}

/** Oracle dead centres, swing (rad) and time ratio of a crank-rocker on branch sigma. */
export interface ReferenceStroke {
  extended: ReferenceDeadCentre;
  folded: ReferenceDeadCentre;
  swing: number;
  timeRatio: number;
}

/** a wrapped to (-pi, pi] in 60 digits. */
function wrap(a: Dec): Dec {
  let w = a.minus(TWO_PI.times(a.plus(PI).div(TWO_PI).floor()));
  if (w.lessThanOrEqualTo(PI.neg())) w = w.plus(TWO_PI);
  if (w.greaterThan(PI)) w = w.minus(TWO_PI);
  return w;
}

/** a - b wrapped to (-pi, pi] in 60 digits. */
function diff(a: Dec, b: Dec): Dec {
  return wrap(a.minus(b));
}

function clampUnit(c: Dec): Dec {
  return D.max(-1, D.min(1, c));
}

/**
 * True when the input (r2) is the strictly shortest link and S + L <= P + Q: the crank turns fully and
 * the rocker rocks (Grashof crank-rocker, or its change-point limit).
 */
export function referenceIsCrankRocker(l: LinkLengths): boolean {
  const r = [l.r1, l.r2, l.r3, l.r4].map(exact);
  if (!(r[1].lessThan(r[0]) && r[1].lessThan(r[2]) && r[1].lessThan(r[3]))) return false;
  const sorted = [...r].sort((a, b) => a.comparedTo(b));
  return sorted[0].plus(sorted[3]).lessThanOrEqualTo(sorted[1].plus(sorted[2]));
}

/** One dead centre: B on |O2 B| = |e| and |O4 B| = r4, theta3 = theta2 (e = r2 + r3) or theta2 + pi (e = r2 - r3). */
function deadCentre(r1: Dec, r4: Dec, e: Dec, extended: boolean, sigma: Sigma): { t2: Dec; t4: Dec } {
  const d = e.abs();
  const x = r1.pow(2).plus(d.pow(2)).minus(r4.pow(2)).div(r1.times(2));
  const h2 = d.pow(2).minus(x.pow(2));
  if (h2.lessThan(d.pow(2).times(FUZZ).neg())) throw new Error('oracle: dead-centre triangle does not close');
  const h = D.max(h2, 0).sqrt();
  let best: { t2: Dec; t4: Dec; side: Dec } | null = null;
  for (const y of [h, h.neg()]) {
    // theta2 points along O2 B when e > 0, away from it when e < 0.
    const t2 = e.greaterThan(0) ? D.atan2(y, x) : D.atan2(y.neg(), x.neg());
    const t3 = extended ? t2 : t2.plus(PI);
    const t4 = D.atan2(y, x.minus(r1));
    const side = D.sin(t4.minus(t3)).times(sigma);
    if (!best || side.greaterThan(best.side)) best = { t2: wrap(t2), t4: wrap(t4), side };
  }
  return best!;
}

/** Oracle dead centres, rocker swing and time ratio on branch sigma; null when not a crank-rocker. */
export function referenceStroke(l: LinkLengths, sigma: Sigma): ReferenceStroke | null {
  if (!referenceIsCrankRocker(l)) return null;
  const [r1, r2, r3, r4] = [l.r1, l.r2, l.r3, l.r4].map(exact);
  const ext = deadCentre(r1, r4, r2.plus(r3), true, sigma);
  const fold = deadCentre(r1, r4, r2.minus(r3), false, sigma);
  // Crank angle from the extended to the folded dead centre one way round, and the rest of the turn.
  let one = fold.t2.minus(ext.t2).mod(TWO_PI);
  if (one.isNegative()) one = one.plus(TWO_PI);
  const other = TWO_PI.minus(one);
  const timeRatio = D.max(one, other).div(D.min(one, other));
  return {
    extended: { theta2: ext.t2.toNumber(), theta4: ext.t4.toNumber() },
    folded: { theta2: fold.t2.toNumber(), theta4: fold.t4.toNumber() },
    swing: diff(fold.t4, ext.t4).abs().toNumber(),
    timeRatio: timeRatio.toNumber(),
  };
}

/** Oracle transmission-angle extremes (rad); theta2 values are the non-negative representatives. */
export interface ReferenceTransmission {
  min: number;
  max: number;
  theta2AtMin: number;
  theta2AtMax: number;
  /** cos of theta2AtMin and theta2AtMax, for the limit tolerance of tolerance.ts. */
  cosAtMin: number;
  cosAtMax: number;
}

/** Transmission angle mu (60 digits) where cos theta2 = c. */
function muAtCos(r1: Dec, r2: Dec, r3: Dec, r4: Dec, c: Dec): Dec {
  const s2 = r1.pow(2).plus(r2.pow(2)).minus(r1.times(r2).times(2).times(c));
  const cosMu = r3.pow(2).plus(r4.pow(2)).minus(s2).div(r3.times(r4).times(2));
  // At a limit cos mu is +-1 up to the 60-digit rounding, which acos would turn into ~1e-30 rad.
  if (cosMu.minus(1).abs().lessThan(FUZZ)) return new D(0);
  if (cosMu.plus(1).abs().lessThan(FUZZ)) return PI;
  return D.acos(clampUnit(cosMu));
}

/**
 * Extremes of mu over the reachable input angles: the loop closes iff cU <= cos theta2 <= cL with
 * cU = (r1^2 + r2^2 - (r3 + r4)^2) / (2 r1 r2), cL = (r1^2 + r2^2 - (r3 - r4)^2) / (2 r1 r2), and mu is
 * monotone in cos theta2 (through s^2), so it is extreme where cos theta2 is: min(cL, 1) and max(cU, -1).
 * Null when nothing assembles.
 */
export function referenceTransmission(l: LinkLengths): ReferenceTransmission | null {
  const [r1, r2, r3, r4] = [l.r1, l.r2, l.r3, l.r4].map(exact);
  const den = r1.times(r2).times(2);
  const base = r1.pow(2).plus(r2.pow(2));
  const cU = base.minus(r3.plus(r4).pow(2)).div(den);
  const cL = base.minus(r3.minus(r4).pow(2)).div(den);
  if (cU.greaterThan(cL) || cU.greaterThan(1) || cL.lessThan(-1)) return null;
  const cMin = D.min(cL, 1); // largest cos: smallest s, smallest mu
  const cMax = D.max(cU, -1);
  return {
    min: muAtCos(r1, r2, r3, r4, cMin).toNumber(),
    max: muAtCos(r1, r2, r3, r4, cMax).toNumber(),
    theta2AtMin: D.acos(cMin).toNumber(),
    theta2AtMax: D.acos(cMax).toNumber(),
    cosAtMin: cMin.toNumber(),
    cosAtMax: cMax.toNumber(),
  };
}

/** An oracle instant centre with the sine of the angle between its two lines (to judge conditioning). */
export interface ReferenceCenter {
  x: number;
  y: number;
  /** Sine of the angle between the two lines (0: parallel, no point). */
  sinBetween: number;
}

/** Intersection of the line through p1, p2 with the line through q1, q2 (Cramer), or null if parallel. */
function intersect(p1: Dec[], p2: Dec[], q1: Dec[], q2: Dec[]): { x: Dec; y: Dec; sin: Dec } | null {
  const ux = p2[0].minus(p1[0]);
  const uy = p2[1].minus(p1[1]);
  const vx = q2[0].minus(q1[0]);
  const vy = q2[1].minus(q1[1]);
  const det = ux.times(vy).minus(uy.times(vx));
  const sin = det.div(D.hypot(ux, uy).times(D.hypot(vx, vy)));
  if (det.isZero()) return null;
  // p1 + t u = q1 + w v  =>  t = ((q1 - p1) x v) / (u x v)
  const t = q1[0].minus(p1[0]).times(vy).minus(q1[1].minus(p1[1]).times(vx)).div(det);
  return { x: p1[0].plus(t.times(ux)), y: p1[1].plus(t.times(uy)), sin };
}

/**
 * Oracle instant centres of the pose given (theta2, theta3, theta4 taken as exact): I13 where the line
 * O2 A meets the line O4 B (B = O4 + r4 (cos t4, sin t4)), I24 where the line A B (B = A + r3 (cos t3,
 * sin t3)) meets the ground line through O2 and O4 (parameterised along the ground, so y is exactly 0).
 * Null only when the lines are exactly parallel.
 */
export function referenceInstantCenters(
  l: LinkLengths,
  theta2: number,
  theta3: number,
  theta4: number,
): { I13: ReferenceCenter | null; I24: ReferenceCenter | null } {
  const [r1, r2, r3, r4] = [l.r1, l.r2, l.r3, l.r4].map(exact);
  const [t2, t3, t4] = [theta2, theta3, theta4].map(exactAngle);
  const O2 = [new D(0), new D(0)];
  const O4 = [r1, new D(0)];
  const A = [r2.times(D.cos(t2)), r2.times(D.sin(t2))];
  const Bfrom4 = [r1.plus(r4.times(D.cos(t4))), r4.times(D.sin(t4))];
  const Bfrom3 = [A[0].plus(r3.times(D.cos(t3))), A[1].plus(r3.times(D.sin(t3)))];
  const toCenter = (p: { x: Dec; y: Dec; sin: Dec } | null): ReferenceCenter | null =>
    p && { x: p.x.toNumber(), y: p.y.toNumber(), sinBetween: p.sin.toNumber() };
  return { I13: toCenter(intersect(O2, A, O4, Bfrom4)), I24: toCenter(intersect(O2, O4, A, Bfrom3)) };
}
