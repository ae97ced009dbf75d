/**
 * Burmester theory (Sandor & Erdman, "Advanced Mechanism Design", ch. 3; McCarthy, "Geometric Design of
 * Linkages", ch. 5): the dyads (a centre point fixed in the plane, a circle point fixed in the coupler) whose
 * circle point stays on a circle about the centre through four or five coupler poses.
 *
 * Standard-form dyad: with W the crank (centre → circle point) and Z the coupler vector (circle point → pose point)
 * at pose 1, as complex numbers, pose j is reached when W e^{iβj} + Z e^{iαj} = Pj − P1 + W + Z, i.e.
 *   W (e^{iβj} − 1) + Z (e^{iαj} − 1) = δj,  αj = φj − φ1, δj = Pj − P1.
 * Four poses give three such equations, linear in (W, Z); they have a solution only when the 3×3 determinant of
 * [e^{iβj} − 1, e^{iαj} − 1, δj] vanishes: Δ1 + Δ2 e^{iβ2} + Δ3 e^{iβ3} + Δ4 e^{iβ4} = 0 with Δ2 = a3 δ4 − a4 δ3,
 * Δ3 = a4 δ2 − a2 δ4, Δ4 = a2 δ3 − a3 δ2 (aj = e^{iαj} − 1) and Δ1 = −(Δ2 + Δ3 + Δ4). That closure is itself a
 * four-bar loop, the compatibility linkage: driven through β2 by the solver's closed form on both branches, it
 * traces the whole centre-point curve, each β giving (W, Z) and so a centre m = P1 − W − Z and its circle point.
 * With a fifth pose a second closure (rows 2, 3, 5) must hold with the same β2, β3. Both are linear in e^{iβ3}
 * once β2 is fixed, so eliminating β3 leaves one trigonometric polynomial of degree 4 in β2 (see burmesterPoints):
 * its real roots, isolated exactly on the equivalent degree-8 polynomial in tan(β2/2), give every real Burmester
 * pair, each polished by Newton on the four circle conditions |Pj + Rj c − m|² = |P1 + R1 c − m|², j = 2..5.
 */
import { PI, TWO_PI, inputRange, solveClosedForm, wrapAngle } from '../solver';
import type { Branch, Linkage, Point } from '../solver';
import { solveSquare } from './dense';
import { cauchyBound, realRoots } from './realRoots';
import { screenPoses } from './defects';
import type { MotionDefect } from './defects';
import { fourBarFromJoints } from './placed';
import { toPlane } from './poseFrame';
import type { PlacedFourBar, Pose } from './types';
import { checkArray, checkPoint, checkPose, show } from './validate';

/** A Burmester dyad: the centre point in the plane and the circle point in the coupler frame (length unit). */
export interface BurmesterPair {
  center: Point;
  circle: Point;
}

/** Default samples of burmesterCurves (per closed branch of the compatibility linkage). */
export const DEFAULT_CURVE_SAMPLES = 200;

/** Centres farther than this many pose scales from the first pose are left out of the curves (the curve's asymptote). */
export const CURVE_FAR = 1e3;

type Complex = [number, number];
const mul = (a: Complex, b: Complex): Complex => [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]];
const sub = (a: Complex, b: Complex): Complex => [a[0] - b[0], a[1] - b[1]];
const div = (a: Complex, b: Complex): Complex => {
  const d = b[0] * b[0] + b[1] * b[1];
  return [(a[0] * b[0] + a[1] * b[1]) / d, (a[1] * b[0] - a[0] * b[1]) / d];
};
const cis = (t: number): Complex => [Math.cos(t), Math.sin(t)];
const expm1i = (t: number): Complex => {
  // e^{it} − 1 = (−2 sin²(t/2), sin t) without the cancellation of cos t − 1 at small t.
  const s = Math.sin(t / 2);
  return [-2 * s * s, Math.sin(t)];
};
const abs = (a: Complex) => Math.hypot(a[0], a[1]);
const arg = (a: Complex) => Math.atan2(a[1], a[0]);

/** Poses moved to the first pose's point and divided by their spread, so every length below is about 1. */
interface Normalised {
  origin: Point;
  scale: number;
  alpha: number[];
  delta: Complex[];
  angle1: number;
}

function normalise(poses: readonly Pose[]): Normalised {
  const origin = { x: poses[0].x, y: poses[0].y };
  let scale = 0;
  for (const p of poses) scale = Math.max(scale, Math.hypot(p.x - origin.x, p.y - origin.y));
  if (!(scale > 0)) throw new Error(`poses must not all share one point: every pose point is ${show(origin)}`);
  return {
    origin,
    scale,
    alpha: poses.map((p) => p.angle - poses[0].angle),
    delta: poses.map((p): Complex => [(p.x - origin.x) / scale, (p.y - origin.y) / scale]),
    angle1: poses[0].angle,
  };
}

/** The compatibility linkage of poses 1–4 (normalised): its lengths and the angles mapping β to its θ. */
interface Compatibility {
  links: Linkage;
  /** θ2 = β2 + off2, θ3 = β3 + off3, θ4 = β4 + off4 (radians). */
  off2: number;
  off3: number;
  off4: number;
  a: Complex[];
  delta: Complex[];
}

function compatibility(n: Normalised): Compatibility {
  const a = n.alpha.map(expm1i);
  const d = n.delta;
  const D2 = sub(mul(a[2], d[3]), mul(a[3], d[2]));
  const D3 = sub(mul(a[3], d[1]), mul(a[1], d[3]));
  const D4 = sub(mul(a[1], d[2]), mul(a[2], d[1]));
  const G: Complex = [D2[0] + D3[0] + D4[0], D2[1] + D3[1] + D4[1]];
  const lengths = [abs(G), abs(D2), abs(D3), abs(D4)];
  if (!lengths.every((v) => v > 1e-14)) {
    throw new Error(
      `poses are degenerate for Burmester theory (a link of the compatibility linkage vanishes: the poses do not rotate, or three are related by one rotation), got lengths ${show(lengths)}`,
    );
  }
  const gamma = arg(G);
  return {
    links: { r1: lengths[0], r2: lengths[1], r3: lengths[2], r4: lengths[3] },
    off2: arg(D2) - gamma,
    off3: arg(D3) - gamma,
    off4: arg(D4) + PI - gamma,
    a,
    delta: d,
  };
}

/** The dyad (normalised m and coupler-frame circle point c, frame of pose 1 not yet applied) at compatibility θ2. */
interface DyadPoint {
  m: Complex;
  /** −Z: the circle point relative to P1, in the plane's axes at pose 1. */
  cz: Complex;
}

function dyadAt(k: Compatibility, theta2: number, branch: Branch): DyadPoint | null {
  const s = solveClosedForm(k.links, theta2, branch);
  if (!s) return null;
  const x = [[0, 0] as Complex, expm1i(theta2 - k.off2), expm1i(s.theta3 - k.off3), expm1i(s.theta4 - k.off4)];
  // Any two of the three (consistent) equations fix W and Z: take the best-conditioned pair.
  let best: [number, number] = [1, 2];
  let bestDet = -1;
  for (const [j, l] of [
    [1, 2],
    [1, 3],
    [2, 3],
  ] as const) {
    const det = abs(sub(mul(x[j], k.a[l]), mul(x[l], k.a[j])));
    if (det > bestDet) {
      bestDet = det;
      best = [j, l];
    }
  }
  const [j, l] = best;
  const det = sub(mul(x[j], k.a[l]), mul(x[l], k.a[j]));
  if (!(abs(det) > 0)) return null;
  const W = div(sub(mul(k.delta[j], k.a[l]), mul(k.delta[l], k.a[j])), det);
  const Z = div(sub(mul(x[j], k.delta[l]), mul(x[l], k.delta[j])), det);
  return { m: [-W[0] - Z[0], -W[1] - Z[1]], cz: [-Z[0], -Z[1]] };
}

/** One closed traversal of the compatibility linkage: θ2 values with the branch each is solved on. */
type Loop = { theta2: number; branch: Branch }[];

/**
 * The closed loops of the compatibility linkage, each sampled at `samples` inputs plus a last one that closes the
 * loop (the same pose as the first), so that neighbours in the list are neighbours on the curve.
 */
function loops(links: Linkage, samples: number): Loop[] {
  const range = inputRange(links);
  const out: Loop[] = [];
  if (range.full) {
    for (const branch of ['open', 'crossed'] as const) {
      out.push(Array.from({ length: samples + 1 }, (_, i) => ({ theta2: -PI + (TWO_PI * i) / samples, branch })));
    }
    return out;
  }
  // Out on the open branch from one limit to the other, back on the crossed: the branches meet at the limits.
  for (const iv of range.intervals) {
    const half = Math.max(2, Math.ceil(samples / 2));
    const loop: Loop = [];
    for (let i = 0; i < half; i++) loop.push({ theta2: iv.lo + ((iv.hi - iv.lo) * i) / half, branch: 'open' });
    for (let i = 0; i <= half; i++) loop.push({ theta2: iv.hi - ((iv.hi - iv.lo) * i) / half, branch: 'crossed' });
    out.push(loop);
  }
  return out;
}

/** A normalised dyad in the caller's units: centre in the plane, circle point in pose 1's coupler frame. */
function toPair(n: Normalised, m: Complex, cz: Complex): BurmesterPair {
  const c = Math.cos(n.angle1);
  const s = Math.sin(n.angle1);
  return {
    center: { x: n.origin.x + n.scale * m[0], y: n.origin.y + n.scale * m[1] },
    circle: { x: n.scale * (c * cz[0] + s * cz[1]), y: n.scale * (-s * cz[0] + c * cz[1]) },
  };
}

/**
 * Throws when two poses are the same (point within 1e-12 of the poses' spread, angle within 1e-12 rad modulo a
 * turn): five poses with a repeat are a four-pose problem, whose dyads are the curves' one-parameter family.
 */
function checkDistinct(poses: readonly Pose[]): void {
  let spread = 0;
  for (const p of poses) spread = Math.max(spread, Math.hypot(p.x - poses[0].x, p.y - poses[0].y));
  for (let i = 0; i < poses.length; i++) {
    for (let j = i + 1; j < poses.length; j++) {
      const same =
        Math.hypot(poses[i].x - poses[j].x, poses[i].y - poses[j].y) <= 1e-12 * spread &&
        Math.abs(wrapAngle(poses[i].angle - poses[j].angle)) <= 1e-12;
      if (same) {
        throw new Error(
          `poses[${i}] and poses[${j}] are the same pose: five poses with a repeat are four, whose dyads are a one-parameter family (burmesterCurves), got ${show(poses[j])}`,
        );
      }
    }
  }
}

/** Throws unless poses holds exactly `count` valid poses. */
function checkPoses(poses: readonly Pose[], count: number): void {
  checkArray('poses', poses, count, count);
  poses.forEach((p, i) => checkPose(`poses[${i}]`, p));
}

/**
 * The centre-point curve of four poses, sampled: one polyline per branch, each point a centre (plane) with its circle
 * point (pose 1's coupler frame, i.e. the frame of every pose: origin at the pose point, turned by its angle).
 * samples (default 200, integer 8 to 100000) is the number of inputs per closed branch of the compatibility
 * linkage; centres beyond CURVE_FAR pose scales are left out, splitting the branch there. Throws for bad input
 * and degenerate poses (all at one point, or not rotating).
 */
export function burmesterCurves(poses: readonly Pose[], options: { samples?: number } = {}): BurmesterPair[][] {
  checkPoses(poses, 4);
  const samples = options.samples ?? DEFAULT_CURVE_SAMPLES;
  if (!Number.isInteger(samples) || samples < 8 || samples > 100000) {
    throw new Error(`options.samples must be an integer from 8 to 100000, got ${show(samples)}`);
  }
  const n = normalise(poses);
  const k = compatibility(n);
  const curves: BurmesterPair[][] = [];
  for (const loop of loops(k.links, samples)) {
    const points = loop.map(({ theta2, branch }) => {
      const d = dyadAt(k, theta2, branch);
      return d && abs(d.m) <= CURVE_FAR ? toPair(n, d.m, d.cz) : null;
    });
    const runs: BurmesterPair[][] = [];
    let run: BurmesterPair[] = [];
    points.forEach((p, i) => {
      // A branch through the centre's point at infinity is split there, however coarse the sampling: the two
      // samples either side lie far out in opposite directions and must not be joined by a chord.
      if (i > 0 && run.length && throughInfinity(k, loop[i - 1], loop[i])) {
        runs.push(run);
        run = [];
      }
      if (p) run.push(p);
      else if (run.length) {
        runs.push(run);
        run = [];
      }
    });
    // The last sample closes the loop onto the first: a run reaching the end continues into the first run.
    if (run.length && runs.length && points[0]) runs[0] = [...run, ...runs[0].slice(1)];
    else if (run.length) runs.push(run);
    curves.push(...runs.filter((r) => r.length > 1));
  }
  return curves;
}

/**
 * Whether the compatibility linkage passes the centre's point at infinity between two neighbouring samples: the
 * crank rotation β2 = θ2 − off2 crosses 0 between them, on the branch where β3 = θ3 − off3 is 0 there too (then
 * every β is 0: the trivial solution of the closure, where the dyad becomes a slider and W, Z are unbounded). On
 * the other branch β2 = 0 is an ordinary, finite centre.
 */
function throughInfinity(
  k: Compatibility,
  p: { theta2: number; branch: Branch },
  q: { theta2: number; branch: Branch },
): boolean {
  if (p.branch !== q.branch) return false;
  const a = wrapAngle(p.theta2 - k.off2);
  const b = wrapAngle(q.theta2 - k.off2);
  if (!((a <= 0 && b >= 0) || (a >= 0 && b <= 0)) || Math.abs(a - b) > PI) return false;
  const s = solveClosedForm(k.links, k.off2, p.branch);
  // At the trivial solution θ3 − off3 is 0 to rounding of the compatibility linkage's closed form; on the other
  // branch it is of the order of the linkage's angles.
  return s !== null && Math.abs(wrapAngle(s.theta3 - k.off3)) < 1e-6;
}

/**
 * The poses reordered so that the first two differ most in angle (|sin(Δφ/2)| largest). The answer does not depend on
 * the order, but the eliminant's parameter is the crank's turn between the first two poses, and its spurious roots
 * β = 0 and β = α2 crowd the true ones when α2 is small.
 */
function leadingPair(poses: readonly Pose[]): Pose[] {
  let best = [0, 1];
  let bestSin = -1;
  for (let i = 0; i < poses.length; i++) {
    for (let j = i + 1; j < poses.length; j++) {
      const s = Math.abs(Math.sin((poses[j].angle - poses[i].angle) / 2));
      if (s > bestSin) {
        bestSin = s;
        best = [i, j];
      }
    }
  }
  return [poses[best[0]], poses[best[1]], ...poses.filter((_, k) => k !== best[0] && k !== best[1])];
}

/** Samples of the degree-4 trigonometric eliminant (any N ≥ 9 recovers its coefficients exactly; 16 wraps by halves). */
const ELIMINANT_SAMPLES = 16;

/**
 * Every real Burmester pair of five poses (0, 2 or 4): centre in the plane, circle point in the coupler frame. The
 * circle point stays on its circle about the centre through all five poses to rounding. Throws for bad input and
 * degenerate poses (all at one point, or not rotating).
 */
export function burmesterPoints(poses: readonly Pose[]): BurmesterPair[] {
  checkPoses(poses, 5);
  checkDistinct(poses);
  const n = normalise(leadingPair(poses));
  const { a, delta: d } = compatibility(n);
  // The two compatibility equations (rows 2, 3, 4 and rows 2, 3, 5 of the dyad equations):
  //   Δ1 + Δ2 z2 + Δ3 z3 = −Δ4 z4,  Δ1' + Δ2' z2 + Δ3' z3 = −Δ5' z5,  zj = e^{iβj}.
  const row = (j: number, l: number, m: number): Complex[] => {
    const D2 = sub(mul(a[l], d[m]), mul(a[m], d[l]));
    const D3 = sub(mul(a[m], d[j]), mul(a[j], d[m]));
    const D4 = sub(mul(a[j], d[l]), mul(a[l], d[j]));
    return [[-(D2[0] + D3[0] + D4[0]), -(D2[1] + D3[1] + D4[1])], D2, D3, D4];
  };
  const E = row(1, 2, 3);
  const F = row(1, 2, 4);
  // |Δ1 + Δ2 z2 + Δ3 z3|² = |Δ4|² is linear in z3 = x + iy once z2 is fixed: Re(conj(A) Δ3 z3) = h with
  // A = Δ1 + Δ2 z2, h = (|Δ4|² − |Δ3|² − |A|²) / 2. The two such lines meet at (x, y) by Cramer; x² + y² = 1 is
  // the eliminant G(β2) = (q1 h2 − q2 h1)² + (p1 h2 − p2 h1)² − (q1 p2 − p1 q2)², a trigonometric polynomial of
  // degree 4 (each p, q, h is of degree 1) whose real roots are the Burmester points' β2, besides the spurious
  // β = 0 (the centre at infinity) and βj = αj (the dyad turning with the coupler), which have no dyad.
  const lines = (z2: Complex) => {
    const out = [E, F].map(([D1, D2, D3, D4]) => {
      const A = [D1[0] + D2[0] * z2[0] - D2[1] * z2[1], D1[1] + D2[0] * z2[1] + D2[1] * z2[0]] as Complex;
      const u = mul([A[0], -A[1]], D3);
      return { p: u[0], q: u[1], h: (abs(D4) ** 2 - abs(D3) ** 2 - abs(A) ** 2) / 2 };
    });
    const [l1, l2] = out;
    return { x: l1.q * l2.h - l2.q * l1.h, y: l1.p * l2.h - l2.p * l1.h, det: l1.q * l2.p - l1.p * l2.q };
  };
  const G = (beta: number) => {
    const { x, y, det } = lines(cis(beta));
    return x * x + y * y - det * det;
  };
  const values = Array.from({ length: ELIMINANT_SAMPLES }, (_, k) => G((TWO_PI * k) / ELIMINANT_SAMPLES));
  // Put the largest |G| at t = ∞ (β = β0 + π) so that the polynomial in t = tan((β − β0)/2) keeps its degree.
  let top = 0;
  values.forEach((v, k) => {
    if (Math.abs(v) > Math.abs(values[top])) top = k;
  });
  const half = ELIMINANT_SAMPLES / 2;
  const beta0 = (TWO_PI * (top + half)) / ELIMINANT_SAMPLES;
  const shifted = values.map((_, k) => values[(top + half + k) % ELIMINANT_SAMPLES]);
  const roots = realRoots(...trigToPoly(shifted)).map((t) => beta0 + 2 * Math.atan(t));

  const R = n.alpha.map(cis);
  const found: DyadPoint[] = [];
  for (const beta2 of roots) {
    const z2 = cis(beta2);
    const { x, y, det } = lines(z2);
    if (!(Math.abs(det) > 0)) continue;
    const z3: Complex = [x / det, y / det];
    const len = abs(z3);
    const z = [[0, 0], z2, [z3[0] / len, z3[1] / len]] as Complex[];
    // z4 and z5 from the two closures (each |·| is 1 at a root), for the best-conditioned pair of rows.
    for (const [D1, D2, D3, D4] of [E, F]) {
      const s: Complex = [D1[0] + mul(D2, z[1])[0] + mul(D3, z[2])[0], D1[1] + mul(D2, z[1])[1] + mul(D3, z[2])[1]];
      const w = div([-s[0], -s[1]], D4);
      z.push([w[0] / abs(w), w[1] / abs(w)]);
    }
    const start = dyadFrom(
      z.map((v): Complex => [v[0] - 1, v[1]]),
      a,
      d,
    );
    const root = start && polish(d, R, start);
    if (
      root &&
      !found.some((f) => abs(sub(f.m, root.m)) + abs(sub(f.cz, root.cz)) < 1e-7 * (1 + abs(root.m) + abs(root.cz)))
    ) {
      found.push(root);
    }
  }
  return found.map((f) => toPair(n, f.m, f.cz));
}

/**
 * The polynomial (ascending coefficients) P(t) = (1 + t²)⁴ G(β0 + 2 atan t) of a degree-4 trigonometric polynomial
 * G given by N equispaced samples G(β0 + 2πk/N), with the interval that holds its real roots (Cauchy's bound).
 */
function trigToPoly(samples: readonly number[]): [number[], number, number] {
  const N = samples.length;
  const deg = 4;
  const a = new Array<number>(deg + 1).fill(0);
  const b = new Array<number>(deg + 1).fill(0);
  for (let k = 0; k <= deg; k++) {
    for (let j = 0; j < N; j++) {
      const phi = (TWO_PI * j * k) / N;
      a[k] += samples[j] * Math.cos(phi);
      b[k] += samples[j] * Math.sin(phi);
    }
    a[k] *= (k === 0 ? 1 : 2) / N;
    b[k] *= 2 / N;
  }
  // e^{ikφ} = (1 + it)^{2k} / (1 + t²)^k with t = tan(φ/2).
  const poly = new Array<number>(2 * deg + 1).fill(0);
  let w: Complex[] = [[1, 0]];
  for (let k = 0; k <= deg; k++) {
    let q = [1];
    for (let i = 0; i < deg - k; i++) q = [...q, 0, 0].map((v, j) => v + (j >= 2 ? q[j - 2] : 0));
    for (let i = 0; i < w.length; i++) {
      for (let j = 0; j < q.length; j++) poly[i + j] += (a[k] * w[i][0] + b[k] * w[i][1]) * q[j];
    }
    for (let r = 0; r < 2; r++) {
      const next: Complex[] = w.map((v) => [v[0], v[1]]);
      next.push([0, 0]);
      for (let i = 0; i < w.length; i++) {
        next[i + 1][0] -= w[i][1];
        next[i + 1][1] += w[i][0];
      }
      w = next;
    }
  }
  const bound = cauchyBound(poly);
  return [poly, -bound, bound];
}

/** The dyad from the rotations xj = e^{iβj} − 1 of rows j = 1..4 (poses 2..5), by the best-conditioned pair. */
function dyadFrom(x: Complex[], a: Complex[], d: Complex[]): DyadPoint | null {
  let best: [number, number] = [1, 2];
  let bestDet = -1;
  for (let j = 1; j < x.length; j++) {
    for (let l = j + 1; l < x.length; l++) {
      const det = abs(sub(mul(x[j], a[l]), mul(x[l], a[j])));
      if (det > bestDet) {
        bestDet = det;
        best = [j, l];
      }
    }
  }
  const [j, l] = best;
  const det = sub(mul(x[j], a[l]), mul(x[l], a[j]));
  if (!(abs(det) > 1e-12)) return null;
  const W = div(sub(mul(d[j], a[l]), mul(d[l], a[j])), det);
  const Z = div(sub(mul(x[j], d[l]), mul(x[l], d[j])), det);
  return { m: [-W[0] - Z[0], -W[1] - Z[1]], cz: [-Z[0], -Z[1]] };
}

/**
 * Newton on the four circle conditions F_j = |Pj + Rj c − m|² − |c − m|² (j = 2..5, normalised, P1 = 0, R1 = 1)
 * from a start near a root; the root when F is at rounding level and m stays finite, else null.
 */
function polish(P: Complex[], R: Complex[], start: DyadPoint): DyadPoint | null {
  let m: Complex = [...start.m];
  let c: Complex = [...start.cz];
  const residuals = (): { F: number[]; J: number[][] } => {
    const u1 = sub(c, m);
    const F: number[] = [];
    const J: number[][] = [];
    for (let j = 1; j <= 4; j++) {
      const rc = mul(R[j], c);
      const uj: Complex = [P[j][0] + rc[0] - m[0], P[j][1] + rc[1] - m[1]];
      F.push(uj[0] ** 2 + uj[1] ** 2 - u1[0] ** 2 - u1[1] ** 2);
      // ∂/∂m = −2 uj + 2 u1; ∂/∂c = 2 Rjᵀ uj − 2 u1.
      const [cr, sr] = R[j];
      J.push([
        -2 * uj[0] + 2 * u1[0],
        -2 * uj[1] + 2 * u1[1],
        2 * (cr * uj[0] + sr * uj[1]) - 2 * u1[0],
        2 * (-sr * uj[0] + cr * uj[1]) - 2 * u1[1],
      ]);
    }
    return { F, J };
  };
  let last = Infinity;
  for (let it = 0; it < 30; it++) {
    const { F, J } = residuals();
    const size = 1 + abs(m) ** 2 + abs(c) ** 2;
    const norm = Math.max(...F.map(Math.abs)) / size;
    if (norm <= 4 * Number.EPSILON || (it > 3 && norm >= last)) {
      return norm <= 1e-12 && abs(m) < 1e6 && abs(c) < 1e6 ? { m, cz: c } : null;
    }
    last = norm;
    const step = solveSquare(J, F);
    if (!step) return null;
    m = [m[0] - step[0], m[1] - step[1]];
    c = [c[0] - step[2], c[1] - step[3]];
  }
  return null;
}

/** A four-bar made of two Burmester pairs, with the θ2 that puts it at each pose and its defects. */
export interface BurmesterFourBar {
  /** Indices into the pairs: the crank's dyad and the rocker's. */
  pairs: [number, number];
  design: PlacedFourBar;
  theta2: number[];
  defects: MotionDefect[];
}

/**
 * The four-bars made of every two of the pairs (up to 6 from 4 pairs), placed at the poses with P at the coupler
 * frame's origin, each screened as a three-position result ('order', 'branch', 'not-crank'). Either dyad of two
 * may drive: the one whose four-bar has fewer defects is the crank (on a tie, the one with the shorter crank), so
 * a Grashof crank-rocker comes out driven by its crank. Pairs whose pivots coincide are skipped. Throws for bad
 * poses or pairs, naming them.
 */
export function burmesterFourBars(poses: readonly Pose[], pairs: readonly BurmesterPair[]): BurmesterFourBar[] {
  checkArray('poses', poses, 2);
  poses.forEach((p, i) => checkPose(`poses[${i}]`, p));
  if (!Array.isArray(pairs)) throw new Error(`pairs must be an array of {center, circle}, got ${show(pairs)}`);
  pairs.forEach((q, i) => {
    if (typeof q !== 'object' || q === null) throw new Error(`pairs[${i}] must be {center, circle}, got ${show(q)}`);
    checkPoint(`pairs[${i}].center`, q.center);
    checkPoint(`pairs[${i}].circle`, q.circle);
  });
  const out: BurmesterFourBar[] = [];
  for (let i = 0; i < pairs.length; i++) {
    for (let j = i + 1; j < pairs.length; j++) {
      const options = [fourBarOf(poses, pairs, i, j), fourBarOf(poses, pairs, j, i)].filter(
        (b): b is BurmesterFourBar => b !== null,
      );
      options.sort((a, b) => a.defects.length - b.defects.length || a.design.links.r2 - b.design.links.r2);
      if (options.length) out.push(options[0]);
    }
  }
  return out;
}

/** The four-bar driven by pair i's dyad with pair j's as the rocker, screened; null when two pivots coincide. */
function fourBarOf(
  poses: readonly Pose[],
  pairs: readonly BurmesterPair[],
  i: number,
  j: number,
): BurmesterFourBar | null {
  const crank = pairs[i];
  const rocker = pairs[j];
  const pins = poses.map((p) => ({ A: toPlane(p, crank.circle), B: toPlane(p, rocker.circle) }));
  let design: PlacedFourBar;
  try {
    design = fourBarFromJoints({ O2: crank.center, A: pins[0].A, B: pins[0].B, O4: rocker.center, P: poses[0] }).design;
  } catch {
    return null;
  }
  return { pairs: [i, j], design, ...screenPoses(design, pins) };
}
