/**
 * What the Motion mode shows for its poses: the synthesis module's method for their count, run on the main thread
 * (each is closed form: microseconds to a tenth of a millisecond, docs/synthesis.md), and every expected failure
 * turned into a problem code the page says in words.
 */
import { PI, angleDiff, classify, degToRad } from '../../../solver';
import type { LinkageType, Point } from '../../../solver';
import {
  approximateMotion,
  burmesterCurves,
  burmesterFourBars,
  burmesterPoints,
  threePositionConstruction,
  threePositionSynthesis,
  toPlane,
  twoPositionRocker,
} from '../../../synthesis';
import type {
  ApproxDyad,
  BurmesterPair,
  MotionDefect,
  PivotConstruction,
  PlacedFourBar,
  Pose,
  PoseError,
  ThreePositionGiven,
  TwoPositionRocker,
} from '../../../synthesis';
import type { PoseDeg, SynMotionState } from '../../../shared/state/slices/synMotionSlice';

/** A design the mode offers: the placed four-bar, θ2 at each pose (radians), its defects and its type. */
export interface MotionCandidate {
  design: PlacedFourBar;
  theta2: number[];
  defects: MotionDefect[];
  type: LinkageType;
  /** Five or more poses: the Burmester points or least-squares dyads it is made of (crank's, rocker's; 0-based). */
  pairs?: [number, number];
  /** Six or more poses: its error at each pose (approximateMotion's), and their root mean square (length unit). */
  errors?: PoseError[];
  rms?: number;
}

/** Why a method has no design (said in words by the page). */
export type MotionProblem =
  | { code: 'collinear'; pivot: 'A' | 'B' | 'O2' | 'O4' }
  | { code: 'coincident' }
  | { code: 'degenerate' }
  | { code: 'noRotation' }
  | { code: 'halfTurn' }
  | { code: 'atPole' }
  | { code: 'noCrankPivot'; ground: number; rocker: number }
  | { code: 'noBurmester' }
  | { code: 'noApprox' }
  /** Six or more poses: the least-squares fit found fewer than the two distinct dyads a four-bar is made of. */
  | { code: 'fewDyads'; found: number }
  | { code: 'pickTwo'; picked: number };

/** Two poses: the pole they turn about (the rocker pivot O4) and the crank-rockers that swing it between them. */
export interface TwoPoseOutcome {
  count: 2;
  pole: Point | null;
  rocker: number;
  ground: number;
  results: TwoPositionRocker[];
  chosen: MotionCandidate | null;
  problem: MotionProblem | null;
}

/** Three poses: the two constructions (in the plane at pose 1, each with its circle's centre found) and the design. */
export interface ThreePoseOutcome {
  count: 3;
  construction: (PivotConstruction & { centre: Point })[];
  chosen: MotionCandidate | null;
  problem: MotionProblem | null;
}

/** Four poses: the centre-point and circle-point curves (the circle points in the plane at pose 1), the dyads picked. */
export interface FourPoseOutcome {
  count: 4;
  curves: BurmesterPair[][];
  dyads: BurmesterPair[];
  chosen: MotionCandidate | null;
  problem: MotionProblem | null;
}

/** Five poses: the Burmester points and the four-bars they make. */
export interface FivePoseOutcome {
  count: 5;
  points: BurmesterPair[];
  fourBars: MotionCandidate[];
  chosen: MotionCandidate | null;
  problem: MotionProblem | null;
}

/** Six to twenty poses (count 6 stands for all of them): the least-squares dyads and their four-bars. */
export interface ManyPoseOutcome {
  count: 6;
  dyads: ApproxDyad[];
  fourBars: MotionCandidate[];
  chosen: MotionCandidate | null;
  problem: MotionProblem | null;
}

/** What the Motion mode shows for its poses. */
export type MotionOutcome = TwoPoseOutcome | ThreePoseOutcome | FourPoseOutcome | FivePoseOutcome | ManyPoseOutcome;

/** Samples of the centre-point curve per closed branch: about a pixel apart on a phone-sized canvas. */
export const CURVE_SAMPLES = 600;

/** The synthesis module's pose (radians) of a page pose (degrees). */
export function toPose(p: PoseDeg): Pose {
  return { x: p.x, y: p.y, angle: degToRad(p.angleDeg) };
}

const candidate = (design: PlacedFourBar, theta2: number[], defects: MotionDefect[]): MotionCandidate => ({
  design,
  theta2,
  defects,
  type: classify(design.links).type,
});

/**
 * The pivots a three-pose construction draws, in the plane at pose 1 (threePositionConstruction, the synthesis
 * module's): for moving pivots each one's three positions in the plane, whose circle's centre is its fixed pivot; for
 * fixed pivots (kinematic inversion) each one's three positions seen from the coupler, carried to the plane by pose 1,
 * whose circle's centre is its moving pivot at pose 1. Stops at the first pivot with no circle, named in the problem.
 */
export function threePoseConstruction(
  poses: readonly [Pose, Pose, Pose],
  given: ThreePositionGiven,
): Pick<ThreePoseOutcome, 'construction' | 'problem'> {
  const construction: ThreePoseOutcome['construction'] = [];
  // The fixed pivots' construction is in the coupler frame: drawn in the plane at pose 1.
  const shown = (q: Point) => ('moving' in given ? q : toPlane(poses[0], q));
  for (const c of threePositionConstruction(poses, given)) {
    if (!c.centre) return { construction, problem: { code: 'collinear', pivot: c.given } };
    construction.push({ ...c, points: c.points.map(shown) as [Point, Point, Point], centre: shown(c.centre) });
  }
  return { construction, problem: null };
}

/** Three poses: the construction and the four-bar (threePositionSynthesis's, the synthesis module's own). */
function threePoses(poses: Pose[], s: SynMotionState): ThreePoseOutcome {
  const three: [Pose, Pose, Pose] = [poses[0], poses[1], poses[2]];
  const pivots: [Point, Point] = [s.pivots[0], s.pivots[1]];
  const given: ThreePositionGiven = s.pivotChoice === 'moving' ? { moving: pivots } : { fixed: pivots };
  const { construction, problem } = threePoseConstruction(three, given);
  if (problem) return { count: 3, construction, chosen: null, problem };
  try {
    const d = threePositionSynthesis(three, given);
    return { count: 3, construction, chosen: candidate(d.design, d.theta2, d.defects), problem: null };
  } catch {
    return { count: 3, construction, chosen: null, problem: { code: 'coincident' } };
  }
}

/** The dyad of the sampled curves nearest to a picked point (by its centre). */
export function nearestDyad(curves: readonly BurmesterPair[][], at: Point): BurmesterPair | null {
  let best: BurmesterPair | null = null;
  let bestD = Infinity;
  for (const curve of curves) {
    for (const pair of curve) {
      const d = Math.hypot(pair.center.x - at.x, pair.center.y - at.y);
      if (d < bestD) {
        bestD = d;
        best = pair;
      }
    }
  }
  return best;
}

/** Four poses: the curves, the dyads nearest the picks, and the four-bar of two dyads. */
function fourPoses(poses: Pose[], s: SynMotionState): FourPoseOutcome {
  let curves: BurmesterPair[][];
  try {
    curves = burmesterCurves(poses, { samples: CURVE_SAMPLES });
  } catch {
    return { count: 4, curves: [], dyads: [], chosen: null, problem: { code: 'degenerate' } };
  }
  const dyads = s.dyadPicks.map((p) => nearestDyad(curves, p)).filter((d): d is BurmesterPair => d !== null);
  if (dyads.length < 2)
    return { count: 4, curves, dyads, chosen: null, problem: { code: 'pickTwo', picked: dyads.length } };
  const [bar] = burmesterFourBars(poses, dyads);
  if (!bar) return { count: 4, curves, dyads, chosen: null, problem: { code: 'coincident' } };
  return { count: 4, curves, dyads, chosen: candidate(bar.design, bar.theta2, bar.defects), problem: null };
}

/** Five poses: the Burmester points and their four-bars (fewest defects, then smallest, first), the chosen one. */
function fivePoses(poses: Pose[], s: SynMotionState): FivePoseOutcome {
  let points: BurmesterPair[];
  try {
    points = burmesterPoints(poses);
  } catch {
    return { count: 5, points: [], fourBars: [], chosen: null, problem: { code: 'degenerate' } };
  }
  const size = (c: MotionCandidate) => c.design.links.r1 + c.design.links.r2 + c.design.links.r3 + c.design.links.r4;
  // Fewest defects first, then the most compact: a far Burmester point makes a linkage few would build.
  const fourBars = burmesterFourBars(poses, points)
    .map((b) => ({ ...candidate(b.design, b.theta2, b.defects), pairs: b.pairs }))
    .sort((a, b) => a.defects.length - b.defects.length || size(a) - size(b));
  if (!fourBars.length) return { count: 5, points, fourBars, chosen: null, problem: { code: 'noBurmester' } };
  return { count: 5, points, fourBars, chosen: fourBars[Math.min(s.choice, fourBars.length - 1)], problem: null };
}

/** Six to twenty poses: approximateMotion's dyads and four-bars (fewest defects, then smallest rms), the chosen one. */
function manyPoses(poses: Pose[], s: SynMotionState): ManyPoseOutcome {
  let out: ReturnType<typeof approximateMotion>;
  try {
    out = approximateMotion(poses);
  } catch {
    return { count: 6, dyads: [], fourBars: [], chosen: null, problem: { code: 'degenerate' } };
  }
  const fourBars = out.fourBars.map((b) => ({
    ...candidate(b.design, b.theta2, b.defects),
    pairs: b.pairs,
    errors: b.errors,
    rms: b.rms,
  }));
  if (!fourBars.length) {
    // Fewer than two dyads is not two dyads whose pivots coincide: say which it is.
    const problem: MotionProblem =
      out.dyads.length < 2 ? { code: 'fewDyads', found: out.dyads.length } : { code: 'noApprox' };
    return { count: 6, dyads: out.dyads, fourBars, chosen: null, problem };
  }
  const chosen = fourBars[Math.min(s.choice, fourBars.length - 1)];
  return { count: 6, dyads: out.dyads, fourBars, chosen, problem: null };
}

/**
 * The pole of two poses: the one point the displacement from pose 1 to pose 2 leaves in place, so the body turns
 * about it; c = (P2 − e^{iΔ} P1) / (1 − e^{iΔ}), Δ the turn wrapped to (−π, π]. Null without a turn.
 */
export function rotationPole(a: Pose, b: Pose): { pole: Point; turn: number } | null {
  const turn = angleDiff(b.angle, a.angle);
  if (!(Math.abs(turn) > 1e-9)) return null;
  const c = Math.cos(turn);
  const s = Math.sin(turn);
  // Numerator and denominator as complex numbers; 1 − e^{iΔ} = (2 sin²(Δ/2), −sin Δ) without cancellation.
  const nx = b.x - (c * a.x - s * a.y);
  const ny = b.y - (s * a.x + c * a.y);
  const h = Math.sin(turn / 2);
  const dx = 2 * h * h;
  const dy = -s;
  const d2 = dx * dx + dy * dy;
  return { pole: { x: (nx * dx + ny * dy) / d2, y: (ny * dx - nx * dy) / d2 }, turn };
}

/** Two poses: the body is a rocker turning about the poses' pole, driven between them by a crank (Norton ch. 5). */
function twoPoses(poses: Pose[], s: SynMotionState): TwoPoseOutcome {
  const none = { results: [], chosen: null };
  const r = rotationPole(poses[0], poses[1]);
  if (!r) return { count: 2, pole: null, rocker: 0, ground: 0, ...none, problem: { code: 'noRotation' } };
  const { pole, turn } = r;
  const rocker = Math.hypot(poses[0].x - pole.x, poses[0].y - pole.y);
  const ground = s.groundLength ?? 2 * rocker;
  if (!(Math.abs(turn) < PI - 1e-9)) return { count: 2, pole, rocker, ground, ...none, problem: { code: 'halfTurn' } };
  if (!(rocker > 1e-12 * Math.hypot(pole.x, pole.y, 1))) {
    return { count: 2, pole, rocker, ground, ...none, problem: { code: 'atPole' } };
  }
  const results = twoPositionRocker({
    O4: pole,
    rocker,
    startAngle: Math.atan2(poses[0].y - pole.y, poses[0].x - pole.x),
    swing: turn,
    ground,
    timeRatio: s.timeRatio,
  });
  if (!results.length) {
    return { count: 2, pole, rocker, ground, results, chosen: null, problem: { code: 'noCrankPivot', ground, rocker } };
  }
  const pick = results[Math.min(s.choice, results.length - 1)];
  // The rocker's two positions are its dead centres: the crank reaches them in order by construction.
  return {
    count: 2,
    pole,
    rocker,
    ground,
    results,
    chosen: candidate(pick.design, [...pick.theta2], []),
    problem: null,
  };
}

/** The Motion mode's outcome for the slice's poses and choices. */
export function solveMotion(s: SynMotionState): MotionOutcome {
  const poses = s.poses.map(toPose);
  switch (poses.length) {
    case 2:
      return twoPoses(poses, s);
    case 3:
      return threePoses(poses, s);
    case 4:
      return fourPoses(poses, s);
    case 5:
      return fivePoses(poses, s);
    default:
      return manyPoses(poses, s);
  }
}
