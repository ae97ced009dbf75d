/**
 * The global stage of path synthesis: rounds of random screening, each followed by exact local solves.
 *
 * A round draws shapes (r1..r4 and the coupler point) within the bounds and the input constraint, assigns the
 * targets to input angles (by arc length along the sampled coupler curve for free timing, from a random start for
 * a step, as given otherwise), fits the placement and the scale in closed form (a similarity Procrustes fit,
 * clamped to the bounds), and keeps the best few by Σd². Each kept start is then solved by the bounded
 * Levenberg–Marquardt method on the exact model. Round r draws from a stream seeded by (seed, r) alone, so rounds
 * are independent work items: a pool of workers can run rounds part, part + parts, … and merge what they find.
 */
import { PI, TWO_PI, inputRange } from '../solver';
import { levenbergMarquardtSteps } from './levenbergMarquardt';
import { MODEL_SIZE, couplerLocal } from './pathModel';
import { createPathProblem, pathLayout, sweepWithinRange, turnsFully } from './pathProblem';
import type { NormalisedTask } from './pathTask';
import { createRandom, mixSeed } from './random';

/** A local minimum found by the global stage, in normalised units (plain data: it can cross a worker boundary). */
export interface PathCandidate {
  /** +1 open, −1 crossed. */
  sigma: number;
  /** Turning direction of free timing (±1). */
  dir: number;
  /** The variables (layout of pathProblem.ts). */
  x: number[];
  /** Σd² in normalised units. */
  f: number;
  /** The global round that found it (the merge keeps the rounds before an exact fit's cut-off). */
  round: number;
}

/** Shapes screened per round. */
export const SAMPLES_PER_ROUND = 400;
/** Screened shapes solved by Levenberg–Marquardt per round. */
export const STARTS_PER_ROUND = 4;
/** Shapes screened between two pauses of a round's steps. */
const SCREEN_PAUSE = 10;
/** Curve samples per shape for free timing's arc-length assignment. */
const CURVE_SAMPLES = 40;
/** Iteration cap of one local solve in the global stage. */
export const LOCAL_ITERATIONS = 150;
/**
 * Iterations more for the round's best start when its local solve was stopped by LOCAL_ITERATIONS: a best fit along
 * a long flat valley (cabrera-5-timed: 270 to 490 iterations) is then reached within the round, not only by the
 * final polish, which a short budget on a busy machine can cut short (issue 34 item 6).
 */
export const ROUND_BEST_ITERATIONS = 1000;
/** Capped starts of a round that go on (the best only: each more costs ~1000 iterations and found nothing more). */
const ROUND_CONTINUED = 1;
/** Σd² (normalised) at which a fit counts as exact and the solve stops: far below 1e-20 of the size². */
export const EXACT_F = 1e-28;

interface Shape {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
  u: number;
  v: number;
}

function logUniform(rand: () => number, a: number, b: number): number {
  return a * Math.exp(rand() * Math.log(b / a));
}

/** A random shape within the task's sampling range, bounds and input constraint; null after repeated misses. */
function sampleShape(t: NormalisedTask, rand: () => number): Shape | null {
  const a = t.sampleMin;
  const b = t.sampleMax;
  for (let tries = 0; tries < 40; tries++) {
    const r1 = logUniform(rand, a, b);
    let r2 = logUniform(rand, a, b);
    const r3 = logUniform(rand, a, b);
    const r4 = logUniform(rand, a, b);
    if (t.crank && rand() < 0.75) {
      // A crank-rocker built directly: r2 the shortest with r2 + L <= P + Q.
      const L = Math.max(r1, r3, r4);
      const lim = Math.min(b, r1 + r3 + r4 - 2 * L);
      if (lim <= a) continue;
      r2 = logUniform(rand, a, lim) * (1 - 1e-6);
    }
    if (t.crank && !turnsFully(r1, r2, r3, r4)) continue;
    const radius = Math.min(t.coupler, 1.5 * Math.max(r3, r2));
    const rho = radius * Math.sqrt(rand());
    const phi = TWO_PI * rand();
    return { r1, r2, r3, r4, u: rho * Math.cos(phi), v: rho * Math.sin(phi) };
  }
  return null;
}

/** The span of input angles the shape can sweep without a limit: a full turn, or one reachable interval. */
function inputSpan(s: Shape, rand: () => number): { lo: number; hi: number; full: boolean } | null {
  if (turnsFully(s.r1, s.r2, s.r3, s.r4)) {
    const lo = TWO_PI * rand() - PI;
    return { lo, hi: lo + TWO_PI, full: true };
  }
  const range = inputRange(s);
  if (range.full) {
    const lo = TWO_PI * rand() - PI;
    return { lo, hi: lo + TWO_PI, full: true };
  }
  const ivs = range.intervals.filter((iv) => iv.hi - iv.lo > 1e-6);
  if (ivs.length === 0) return null;
  const iv = ivs[Math.floor(rand() * ivs.length)];
  const margin = 1e-4 * (iv.hi - iv.lo);
  return { lo: iv.lo + margin, hi: iv.hi - margin, full: false };
}

/** Cumulative chord fractions of the targets (0 … 1); equal steps when they all coincide. */
function chordFractions(t: NormalisedTask): Float64Array {
  const phi = new Float64Array(t.n);
  for (let i = 1; i < t.n; i++) phi[i] = phi[i - 1] + Math.hypot(t.tx[i] - t.tx[i - 1], t.ty[i] - t.ty[i - 1]);
  const total = phi[t.n - 1];
  for (let i = 0; i < t.n; i++) phi[i] = total > 0 ? phi[i] / total : t.n > 1 ? i / (t.n - 1) : 0;
  return phi;
}

/**
 * Input angles for the targets by arc length along the coupler curve over the span (free timing): a random
 * stretch of the curve (a quarter to all of it) from a random start, travelled in direction dir.
 */
function arcAssign(
  s: Shape,
  sigma: number,
  span: { lo: number; hi: number; full: boolean },
  phi: Float64Array,
  dir: number,
  rand: () => number,
  out: Float64Array,
): boolean {
  const N = CURVE_SAMPLES;
  const pts = new Float64Array(2 * (N + 1));
  const model = new Float64Array(MODEL_SIZE);
  const th = new Float64Array(N + 1);
  for (let j = 0; j <= N; j++) {
    th[j] = span.lo + ((span.hi - span.lo) * j) / N;
    if (!couplerLocal(s.r1, s.r2, s.r3, s.r4, s.u, s.v, th[j], sigma, model)) return false;
    pts[2 * j] = model[0];
    pts[2 * j + 1] = model[1];
  }
  const cum = new Float64Array(N + 1);
  for (let j = 1; j <= N; j++) {
    cum[j] = cum[j - 1] + Math.hypot(pts[2 * j] - pts[2 * j - 2], pts[2 * j + 1] - pts[2 * j - 1]);
  }
  const C = cum[N];
  if (!(C > 0)) return false;
  const w = (0.25 + 0.75 * rand()) * C;
  const a0 = span.full ? rand() * C : rand() * (C - w);
  const thetaAt = (arc: number): number => {
    const q = span.full ? Math.floor(arc / C) : 0;
    const a = Math.min(C, Math.max(0, arc - q * C));
    let j = 1;
    while (j < N && cum[j] < a) j++;
    const seg = cum[j] - cum[j - 1];
    const f = seg > 0 ? (a - cum[j - 1]) / seg : 0;
    return th[j - 1] + f * (th[j] - th[j - 1]) + q * (span.hi - span.lo);
  };
  const n = phi.length;
  for (let i = 0; i < n; i++) {
    const arc = span.full ? a0 + dir * phi[i] * w : dir > 0 ? a0 + phi[i] * w : a0 + (1 - phi[i]) * w;
    out[i] = thetaAt(arc);
  }
  // Keep the order strict in the direction of travel (interpolation can tie at a cusp).
  for (let i = 1; i < n; i++) if (dir * (out[i] - out[i - 1]) < 0) out[i] = out[i - 1];
  if (dir * (out[n - 1] - out[0]) > TWO_PI * (1 + 1e-12)) return false;
  return true;
}

/** One screened start: its variables and Σd² (normalised). */
interface Start {
  x: Float64Array;
  f: number;
  sigma: number;
  dir: number;
}

/**
 * Fits placement and scale of shape s with the input at th to the targets (closed form), writes the variables into
 * x and returns Σd², or Infinity where it cannot be placed within the bounds.
 */
function placeShape(
  t: NormalisedTask,
  s: Shape,
  sigma: number,
  th: Float64Array,
  dir: number,
  x: Float64Array,
): number {
  const n = t.n;
  const model = new Float64Array(MODEL_SIZE);
  const px = new Float64Array(n);
  const py = new Float64Array(n);
  let mx = 0;
  let my = 0;
  let tmx = 0;
  let tmy = 0;
  for (let i = 0; i < n; i++) {
    if (!couplerLocal(s.r1, s.r2, s.r3, s.r4, s.u, s.v, th[i], sigma, model)) return Infinity;
    px[i] = model[0];
    py[i] = model[1];
    mx += px[i];
    my += py[i];
    tmx += t.tx[i];
    tmy += t.ty[i];
  }
  mx /= n;
  my /= n;
  tmx /= n;
  tmy /= n;
  let kLo = t.lenMin / Math.min(s.r1, s.r2, s.r3, s.r4);
  let kHi = t.lenMax / Math.max(s.r1, s.r2, s.r3, s.r4);
  const rho = Math.hypot(s.u, s.v);
  if (rho > 0) kHi = Math.min(kHi, t.coupler / rho);
  kLo = Math.max(kLo, 0);
  if (!(kLo <= kHi)) return Infinity;
  let k: number;
  let angle: number;
  let ox: number;
  let oy: number;
  if (t.placement) {
    angle = t.placement.angle;
    const c = Math.cos(angle);
    const sn = Math.sin(angle);
    let num = 0;
    let den = 0;
    for (let i = 0; i < n; i++) {
      const qx = t.tx[i] - t.placement.x;
      const qy = t.ty[i] - t.placement.y;
      num += (c * qx + sn * qy) * px[i] + (-sn * qx + c * qy) * py[i];
      den += px[i] * px[i] + py[i] * py[i];
    }
    k = den > 0 ? num / den : 1;
    k = Math.min(kHi, Math.max(kLo, k));
    ox = t.placement.x;
    oy = t.placement.y;
  } else {
    // Similarity Procrustes: k e^{iα} = Σ conj(p − p̄)(T − T̄) / Σ|p − p̄|².
    let re = 0;
    let im = 0;
    let den = 0;
    for (let i = 0; i < n; i++) {
      const ax = px[i] - mx;
      const ay = py[i] - my;
      const bx = t.tx[i] - tmx;
      const by = t.ty[i] - tmy;
      re += ax * bx + ay * by;
      im += ax * by - ay * bx;
      den += ax * ax + ay * ay;
    }
    angle = Math.atan2(im, re);
    k = den > 0 ? Math.hypot(re, im) / den : 1;
    k = Math.min(kHi, Math.max(kLo, k));
    const c = Math.cos(angle);
    const sn = Math.sin(angle);
    ox = Math.min(t.pivotMax.x, Math.max(t.pivotMin.x, tmx - k * (c * mx - sn * my)));
    oy = Math.min(t.pivotMax.y, Math.max(t.pivotMin.y, tmy - k * (sn * mx + c * my)));
  }
  const c = Math.cos(angle);
  const sn = Math.sin(angle);
  let f = 0;
  for (let i = 0; i < n; i++) {
    const ex = ox + k * (c * px[i] - sn * py[i]) - t.tx[i];
    const ey = oy + k * (sn * px[i] + c * py[i]) - t.ty[i];
    f += ex * ex + ey * ey;
  }
  const lay = pathLayout(t);
  if (lay.place >= 0) {
    x[lay.place] = ox;
    x[lay.place + 1] = oy;
    x[lay.place + 2] = angle;
  }
  const L = lay.links;
  x[L] = k * s.r1;
  x[L + 1] = k * s.r2;
  x[L + 2] = k * s.r3;
  x[L + 3] = k * s.r4;
  x[L + 4] = k * Math.hypot(s.u, s.v);
  x[L + 5] = Math.atan2(s.v, s.u);
  const T = lay.timing;
  if (t.timing === 'step') x[T] = th[0];
  else if (t.timing === 'free') {
    x[T] = th[0];
    for (let i = 1; i < n; i++) x[T + i] = dir * (th[i] - th[i - 1]);
  }
  return f;
}

/** Screens SAMPLES_PER_ROUND random shapes and returns the best `keep` starts, best first. */
function* screen(t: NormalisedTask, rand: () => number, samples: number, keep: number): Generator<void, Start[], void> {
  const best: Start[] = [];
  const phi = chordFractions(t);
  const th = new Float64Array(t.n);
  const m = pathLayout(t).m;
  for (let sIdx = 0; sIdx < samples; sIdx++) {
    // A pause every few shapes: with many targets the arc-length assignment alone takes milliseconds per shape.
    if (sIdx % SCREEN_PAUSE === SCREEN_PAUSE - 1) yield;
    const shape = sampleShape(t, rand);
    if (!shape) continue;
    const sigma = rand() < 0.5 ? 1 : -1;
    const dir = t.timing === 'free' ? (rand() < 0.5 ? 1 : -1) : 1;
    const span = inputSpan(shape, rand);
    if (!span) continue;
    if (t.timing === 'free') {
      if (!arcAssign(shape, sigma, span, phi, dir, rand, th)) continue;
    } else if (t.timing === 'step') {
      const sweep = (t.n - 1) * t.step;
      if (span.full) th[0] = span.lo + (span.hi - span.lo) * rand();
      else {
        const room = span.hi - span.lo - Math.abs(sweep);
        if (room <= 0) continue;
        th[0] = (sweep >= 0 ? span.lo : span.lo - sweep) + room * rand();
      }
      for (let i = 1; i < t.n; i++) th[i] = th[0] + i * t.step;
    } else {
      th.set(t.given);
      if (!span.full) {
        let a = Infinity;
        let b = -Infinity;
        for (const v of th) {
          a = Math.min(a, v);
          b = Math.max(b, v);
        }
        if (!sweepWithinRange(shape.r1, shape.r2, shape.r3, shape.r4, a, b)) continue;
      }
    }
    const x = new Float64Array(m);
    const f = placeShape(t, shape, sigma, th, dir, x);
    if (!(f < Infinity)) continue;
    if (best.length < keep || f < best[best.length - 1].f) {
      best.push({ x, f, sigma, dir });
      best.sort((p, q) => p.f - q.f);
      if (best.length > keep) best.pop();
    }
  }
  return best;
}

/** Work counters of the global stage. */
export interface RoundStats {
  /** Residual evaluations of the local solves plus screened shapes. */
  evaluations: number;
}

/**
 * Round `round` of the global stage for seed (deterministic in both) as steps: screening, then a local solve of
 * each kept start, the generator pausing after each so the caller can yield to the event loop or stop. Once
 * Date.now() passes deadline or the signal is aborted (also checked inside each local solve), the starts not yet
 * solved are returned as they were placed: feasible designs, just not polished.
 */
export function* pathRoundSteps(
  t: NormalisedTask,
  seed: number,
  round: number,
  deadline = Infinity,
  signal?: { readonly aborted: boolean },
): Generator<void, { candidates: PathCandidate[]; stats: RoundStats }, void> {
  const rand = createRandom(mixSeed(seed, round));
  const starts = yield* screen(t, rand, SAMPLES_PER_ROUND, STARTS_PER_ROUND);
  const candidates: PathCandidate[] = [];
  /** Whether each candidate's solve was stopped by LOCAL_ITERATIONS short of an exact fit. */
  const capped: boolean[] = [];
  let evaluations = SAMPLES_PER_ROUND;
  for (const s of starts) {
    yield;
    if (Date.now() > deadline || signal?.aborted) {
      candidates.push({ sigma: s.sigma, dir: s.dir, x: Array.from(s.x), f: s.f, round });
      capped.push(false);
      continue;
    }
    const problem = createPathProblem(t, s.sigma, s.dir);
    const r = yield* levenbergMarquardtSteps(problem.lsq, s.x, {
      maxIterations: LOCAL_ITERATIONS,
      fTarget: EXACT_F,
      deadline,
      signal,
    });
    evaluations += r.evaluations;
    if (Number.isFinite(r.f)) {
      candidates.push({ sigma: s.sigma, dir: s.dir, x: Array.from(r.x), f: r.f, round });
      capped.push(r.iterations >= LOCAL_ITERATIONS && r.f > EXACT_F);
    }
  }
  // Starts whose solve was cut off by the cap go on (a solve that stopped by itself has converged), best first: a
  // function of the round alone, so the work stays independent of how rounds are dealt to parts.
  const order = candidates.map((_, i) => i).filter((i) => capped[i]);
  order.sort((a, b) => candidates[a].f - candidates[b].f);
  for (const i of order.slice(0, ROUND_CONTINUED)) {
    yield;
    if (Date.now() > deadline || signal?.aborted) break;
    const c = candidates[i];
    const problem = createPathProblem(t, c.sigma, c.dir);
    const r = yield* levenbergMarquardtSteps(problem.lsq, Float64Array.from(c.x), {
      maxIterations: ROUND_BEST_ITERATIONS,
      fTarget: EXACT_F,
      deadline,
      signal,
    });
    evaluations += r.evaluations;
    if (r.f < c.f) candidates[i] = { ...c, x: Array.from(r.x), f: r.f };
  }
  return { candidates, stats: { evaluations } };
}

/** Runs round `round` of the global stage at once (pathRoundSteps without pauses). */
export function runPathRound(
  t: NormalisedTask,
  seed: number,
  round: number,
  deadline = Infinity,
): { candidates: PathCandidate[]; stats: RoundStats } {
  const steps = pathRoundSteps(t, seed, round, deadline);
  for (;;) {
    const next = steps.next();
    if (next.done) return next.value;
  }
}
