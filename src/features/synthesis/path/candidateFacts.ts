import { PI, TWO_PI, radToDeg, wrapAngle } from '../../../solver/angles';
import { classify } from '../../../solver/classify';
import { solveClosedForm } from '../../../solver/closedForm';
import type { LinkageType } from '../../../solver/types';
import { placedCouplerPoint } from '../../../synthesis/placed';
import type { PathSolution, PlacedFourBar } from '../../../synthesis/types';
import type { PathDefect } from '../synthesisMessages';

/** A transmission angle below this (degrees, the usual design rule) is a defect. */
export const LOW_TRANSMISSION_DEG = 30;
/** |S + L − P − Q| below this share of the longest link is a near-change-point design (it can switch branch). */
export const CHANGE_POINT_SHARE = 1e-3;
/** A transmission angle below this (degrees) is a near-toggle: the output can lock (reported instead of low μ). */
export const TOGGLE_DEG = 5;
/** Defects that rank a candidate last: it passes the targets, but the linkage will not run dependably. */
export const RANK_LAST: readonly PathDefect[] = ['change-point', 'toggle'];
/** A target missed by more than this fraction of the targets' size is a defect. */
export const MISS_FRACTION = 0.01;
/** Samples of a coupler curve over the motion (one turn, or one reachable interval). */
const CURVE_SAMPLES = 360;

/** The input's motion: a full turn, or back and forth over the reachable interval holding the targets (radians). */
export interface MotionRange {
  full: boolean;
  lo: number;
  hi: number;
}

/** What the results list says about one design: type, transmission, defects, and the curve and motion to draw. */
export interface CandidateFacts {
  type: LinkageType;
  grashof: boolean;
  /** Smallest min(μ, 180° − μ) over the motion, degrees. */
  muMinDeg: number;
  defects: { kind: PathDefect; value: number }[];
  motion: MotionRange;
  /** The coupler curve over the motion (length unit); NaN where it cannot assemble (a gap). */
  curve: { x: Float64Array; y: Float64Array };
}

/** The input's motion of a design that passes θ2 = theta2 (radians): a full turn for a crank, else its interval. */
export function motionRange(design: PlacedFourBar, theta2: number): MotionRange {
  const c = classify(design.links);
  if (c.inputIsCrank || c.inputRange.full) return { full: true, lo: 0, hi: TWO_PI };
  for (const iv of c.inputRange.intervals) {
    // The interval holding θ2 (mod 2π); a hair inside its ends, where the loop still closes.
    const k = Math.ceil((iv.lo - theta2) / TWO_PI);
    const t = theta2 + k * TWO_PI;
    if (t <= iv.hi + 1e-12) {
      const pad = 1e-6 * (iv.hi - iv.lo);
      return { full: false, lo: iv.lo + pad, hi: iv.hi - pad };
    }
  }
  const iv = c.inputRange.intervals[0] ?? { lo: theta2, hi: theta2 };
  return { full: false, lo: iv.lo, hi: iv.hi };
}

/** θ2 (radians) along the motion at phase s in [0, 1): once round a full turn, else there and back. */
export function theta2AtPhase(m: MotionRange, s: number): number {
  const f = s - Math.floor(s);
  if (m.full) return m.lo + f * (m.hi - m.lo);
  return m.lo + ((1 - Math.cos(TWO_PI * f)) / 2) * (m.hi - m.lo);
}

/** The coupler curve of a design over its motion: samples + 1 points, NaN where it does not assemble. */
export function couplerCurve(design: PlacedFourBar, m: MotionRange, samples = CURVE_SAMPLES) {
  const x = new Float64Array(samples + 1);
  const y = new Float64Array(samples + 1);
  for (let i = 0; i <= samples; i++) {
    const p = placedCouplerPoint(design, m.lo + ((m.hi - m.lo) * i) / samples);
    x[i] = p ? p.x : NaN;
    y[i] = p ? p.y : NaN;
  }
  return { x, y };
}

/** Smallest min(μ, π − μ) over the motion (degrees); NaN when it never assembles. */
function minTransmissionDeg(design: PlacedFourBar, m: MotionRange): number {
  let least = Infinity;
  for (let i = 0; i <= CURVE_SAMPLES; i++) {
    const a = solveClosedForm(design.links, m.lo + ((m.hi - m.lo) * i) / CURVE_SAMPLES, design.branch);
    if (!a) continue;
    const mu = Math.abs(wrapAngle(a.theta4 - a.theta3));
    least = Math.min(least, mu, PI - mu);
  }
  return Number.isFinite(least) ? radToDeg(least) : NaN;
}

/** |S + L − P − Q| as a share of the longest link L (0 at a change point). */
export function grashofGap(design: PlacedFourBar): number {
  const r = [design.links.r1, design.links.r2, design.links.r3, design.links.r4].sort((a, b) => a - b);
  return Math.abs(r[0] + r[3] - r[1] - r[2]) / r[3];
}

/** True when the facts rank a candidate last (a near-change-point or near-toggle design). */
export function ranksLast(f: CandidateFacts): boolean {
  return f.defects.some((d) => RANK_LAST.includes(d.kind));
}

/**
 * The facts of one design for the targets: its Grashof type, the smallest transmission angle over its motion, its
 * defects (an input that cannot turn fully, near a change point, μ below 5° (a toggle) or else below 30°, a target
 * missed by more than 1 % of the targets' size) and
 * its coupler curve over the motion.
 */
export function placedFourBarFacts(
  design: PlacedFourBar,
  theta2: number,
  maxDistance: number,
  size: number,
): CandidateFacts {
  const c = classify(design.links);
  const motion = motionRange(design, theta2);
  const muMinDeg = minTransmissionDeg(design, motion);
  const defects: CandidateFacts['defects'] = [];
  if (!c.inputIsCrank) defects.push({ kind: 'not-crank', value: 0 });
  const gap = grashofGap(design);
  if (gap < CHANGE_POINT_SHARE) defects.push({ kind: 'change-point', value: gap });
  if (muMinDeg < TOGGLE_DEG) defects.push({ kind: 'toggle', value: muMinDeg });
  else if (!(muMinDeg >= LOW_TRANSMISSION_DEG)) defects.push({ kind: 'low-transmission', value: muMinDeg });
  if (maxDistance > MISS_FRACTION * size) defects.push({ kind: 'misses', value: maxDistance });
  return { type: c.type, grashof: c.grashof, muMinDeg, defects, motion, curve: couplerCurve(design, motion) };
}

/** The facts of a path solution (see placedFourBarFacts); size is the targets' size (length unit). */
export function candidateFacts(s: PathSolution, size: number): CandidateFacts {
  return placedFourBarFacts(s.design, s.theta2[0] ?? 0, s.maxDistance, size);
}
