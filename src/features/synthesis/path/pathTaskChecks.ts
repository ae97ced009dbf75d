import type { Point } from '../../../solver/kinematics';
import type { PathSolution, PathTask } from '../../../synthesis/types';
import type { SynPathState } from '../../../shared/state/appState';
import { targetsExtent } from './pathTaskOf';
import { TWO_PI } from '../../../solver/angles';

/** Share of the targets' size within which a candidate counts as passing every target (issue 34 item 3). */
export const PASS_SHARE = 0.01;

/** The target (1-based) whose given θ2 is missing, when the timing is given; null when every target has one. */
export function missingTheta2(s: SynPathState): number | null {
  if (s.timing !== 'given') return null;
  for (let i = 0; i < s.targets.length; i++) {
    const a = s.givenTheta2Deg[i];
    if (a === undefined || !Number.isFinite(a)) return i + 1;
  }
  return null;
}

/**
 * Why no design in a task's bounds can meet it, where a short argument shows it (length unit, radians):
 * - span: |O2P| ≤ r2 + |AP| ≤ reach = longest link + coupler offset, so no two targets can be more than 2 reach apart;
 * - pivot-far: a target farther than reach from every point of the crank pivot's box (1-based target);
 * - same-theta2: two targets (1-based) at different places given one θ2 (mod 2π): one input angle, one place.
 */
export type PathTaskReason =
  | { kind: 'span'; reach: number; span: number }
  | { kind: 'pivot-far'; target: number; reach: number; distance: number }
  | { kind: 'same-theta2'; a: number; b: number; theta2: number };

/** Largest distance between two of the points (0 for fewer than two). */
function spanOf(points: readonly Point[]): number {
  let span = 0;
  for (let i = 0; i < points.length; i++)
    for (let j = i + 1; j < points.length; j++)
      span = Math.max(span, Math.hypot(points[i].x - points[j].x, points[i].y - points[j].y));
  return span;
}

/** Distance from p to the box (0 inside). */
function distanceToBox(p: Point, box: { min: Point; max: Point }): number {
  const dx = Math.max(box.min.x - p.x, 0, p.x - box.max.x);
  const dy = Math.max(box.min.y - p.y, 0, p.y - box.max.y);
  return Math.hypot(dx, dy);
}

/** The reasons (PathTaskReason) a task cannot be met within its bounds that a short argument shows; [] for none. */
export function pathTaskReasons(task: PathTask): PathTaskReason[] {
  const out: PathTaskReason[] = [];
  const length = task.bounds?.length?.[1];
  const coupler = task.bounds?.coupler;
  if (length !== undefined && coupler !== undefined) {
    const reach = length + coupler;
    const span = spanOf(task.targets);
    if (span > 2 * reach) out.push({ kind: 'span', reach, span });
    const box = task.bounds?.pivot;
    if (box) {
      let far = -1;
      let farDistance = reach;
      task.targets.forEach((p, i) => {
        const d = distanceToBox(p, box);
        if (d > farDistance) {
          far = i;
          farDistance = d;
        }
      });
      if (far >= 0) out.push({ kind: 'pivot-far', target: far + 1, reach, distance: farDistance });
    }
  }
  if (task.timing.kind === 'given') {
    const th = task.timing.theta2;
    const size = targetsExtent(task.targets).size;
    search: for (let i = 0; i < th.length; i++) {
      for (let j = i + 1; j < th.length; j++) {
        const turn = (th[j] - th[i]) / TWO_PI;
        const apart = Math.hypot(task.targets[i].x - task.targets[j].x, task.targets[i].y - task.targets[j].y);
        // The same angle to rounding (1e-12 of a turn), at places apart by more than rounding of the size.
        if (Math.abs(turn - Math.round(turn)) < 1e-12 && apart > 1e-9 * size) {
          out.push({ kind: 'same-theta2', a: i + 1, b: j + 1, theta2: th[i] });
          break search;
        }
      }
    }
  }
  return out;
}

/** True when no answer passes within PASS_SHARE of the targets' size of every target (or there is none). */
export function noneClose(task: PathTask, solutions: readonly PathSolution[]): boolean {
  const size = targetsExtent(task.targets).size;
  return !solutions.some((s) => s.maxDistance <= PASS_SHARE * size);
}
