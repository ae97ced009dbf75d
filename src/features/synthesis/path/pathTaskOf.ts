import { degToRad } from '../../../solver/angles';
import type { Point } from '../../../solver/kinematics';
import type { PathTask } from '../../../synthesis/types';
import type { PivotBox, SynPathState } from '../../../shared/state/appState';

/** The bounds a path task gets when the page leaves them to the targets' size (length unit). */
export interface PathBounds {
  length: number;
  coupler: number;
  pivot: PivotBox;
}

/** x rounded to two significant digits, up (a default bound reads as a round number and stays outside). */
function roundUp2(x: number): number {
  if (!(x > 0)) return 1;
  const p = 10 ** (Math.floor(Math.log10(x)) - 1);
  return Math.ceil(x / p) * p;
}

/** Centre (centroid) and size (largest distance from it; 1 when all targets coincide) of the targets. */
export function targetsExtent(targets: readonly Point[]): { centre: Point; size: number } {
  if (targets.length === 0) return { centre: { x: 0, y: 0 }, size: 1 };
  let cx = 0;
  let cy = 0;
  for (const p of targets) {
    cx += p.x;
    cy += p.y;
  }
  cx /= targets.length;
  cy /= targets.length;
  let size = 0;
  for (const p of targets) size = Math.max(size, Math.hypot(p.x - cx, p.y - cy));
  return { centre: { x: cx, y: cy }, size: size > 0 ? size : 1 };
}

/**
 * Default bounds from the targets' size s (the largest distance from their centroid): links up to 5 s, the coupler
 * offset up to 3 s (both rounded up to two significant digits), O2 in a box reaching at least 4 s from the centroid
 * (edges on a round grid).
 */
export function defaultPathBounds(targets: readonly Point[]): PathBounds {
  const { centre, size } = targetsExtent(targets);
  const reach = 4 * size;
  // The box's edges on a round grid (half a unit of reach's second digit), outward, without float dust.
  const step = 5 * 10 ** (Math.floor(Math.log10(reach)) - 1);
  const lo = (v: number) => Number((Math.floor((v - reach) / step) * step).toPrecision(12));
  const hi = (v: number) => Number((Math.ceil((v + reach) / step) * step).toPrecision(12));
  return {
    length: roundUp2(5 * size),
    coupler: roundUp2(3 * size),
    pivot: { min: { x: lo(centre.x), y: lo(centre.y) }, max: { x: hi(centre.x), y: hi(centre.y) } },
  };
}

/** The bounds the task uses: the page's where set, else the defaults from the targets. */
export function pathBoundsOf(s: SynPathState): PathBounds {
  const d = defaultPathBounds(s.targets);
  return { length: s.boundLength ?? d.length, coupler: s.boundCoupler ?? d.coupler, pivot: s.pivotBox ?? d.pivot };
}

/** The path synthesis task of the page's state (angles to radians; given θ2 missing for a target count as 0). */
export function pathTaskOf(s: SynPathState): PathTask {
  const b = pathBoundsOf(s);
  const timing: PathTask['timing'] =
    s.timing === 'step'
      ? { kind: 'step', step: degToRad(s.timingStepDeg) }
      : s.timing === 'given'
        ? { kind: 'given', theta2: s.targets.map((_, i) => degToRad(s.givenTheta2Deg[i] ?? 0)) }
        : { kind: 'free' };
  return {
    targets: s.targets.map((p) => ({ x: p.x, y: p.y })),
    timing,
    bounds: { length: [0, b.length], coupler: b.coupler, pivot: b.pivot },
    input: s.input,
  };
}

/**
 * True when two path tasks are the same task: the same targets, timing, bounds and input, number for number.
 * Answers belong to the task they were computed for: any edit makes them out of date.
 */
export function samePathTask(a: PathTask, b: PathTask): boolean {
  return JSON.stringify(a) === JSON.stringify(b);
}
