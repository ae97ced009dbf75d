/**
 * Screening a motion-generation design: the input angle that puts the coupler at each pose, and the defects that
 * make a design useless even though its coupler can occupy every pose (Sandor & Erdman, "Advanced Mechanism
 * Design", §3.9 on branch and order defects; Waldron's circuit defect).
 */
import { TWO_PI, inputRange, wrapAngle } from '../solver';
import type { Point } from '../solver';
import { inputMotion } from './functionGeneration';
import type { PlacedFourBar } from './types';

/**
 * Defects of a motion-generation design: 'order' (no one-way turn of the input, within one turn and without
 * leaving its reachable range, reaches the poses in the given order), 'branch' (the poses are not all on the
 * design's branch) and 'not-crank' (the input cannot turn fully: information, not a failure).
 */
export type MotionDefect = 'order' | 'branch' | 'not-crank';

/** The crank and coupler pins A and B at one pose, in the task's plane. */
export interface PinPair {
  A: Point;
  B: Point;
}

/**
 * θ2 at each pose (radians, from the design's ground line, wrapped to (−π, π]) and the design's defects, from the
 * pins' positions at every pose (the design's own branch is that of the first pose). Assumes a valid design.
 */
export function screenPoses(
  design: PlacedFourBar,
  pins: readonly PinPair[],
): { theta2: number[]; defects: MotionDefect[] } {
  const { O2, groundAngle } = design;
  const O4 = { x: O2.x + design.links.r1 * Math.cos(groundAngle), y: O2.y + design.links.r1 * Math.sin(groundAngle) };
  const theta2 = pins.map(({ A }) => wrapAngle(Math.atan2(A.y - O2.y, A.x - O2.x) - groundAngle));
  const defects: MotionDefect[] = [];
  if (!inOrder(design, theta2)) defects.push('order');
  // Open: B left of the ray A→O4 (cross(O4 − A, B − A) ≥ 0), as fourBarFromJoints and the solver read it.
  const branchOf = ({ A, B }: PinPair) =>
    (O4.x - A.x) * (B.y - A.y) - (O4.y - A.y) * (B.x - A.x) >= 0 ? 'open' : 'crossed';
  if (pins.some((p) => branchOf(p) !== design.branch)) defects.push('branch');
  if (!inputRange(design.links).full) defects.push('not-crank');
  return { theta2, defects };
}

/** Whether turning the input one way (either way) from θ2[0] meets θ2[1], θ2[2], … in order within one turn, assembled. */
function inOrder(design: PlacedFourBar, theta2: readonly number[]): boolean {
  const mod = (v: number) => v - TWO_PI * Math.floor(v / TWO_PI);
  for (const s of [1, -1]) {
    let travel = 0;
    for (let i = 1; i < theta2.length; i++) travel += mod(s * (theta2[i] - theta2[i - 1]));
    if (travel >= TWO_PI) continue;
    const [lo, hi] = s > 0 ? [theta2[0], theta2[0] + travel] : [theta2[0] - travel, theta2[0]];
    if (inputMotion(design.links, lo, hi).assembles) return true;
  }
  return false;
}
