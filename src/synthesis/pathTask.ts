/**
 * A path task checked and put in normalised units: targets centred on their centroid and divided by their size,
 * so the search and its tolerances do not depend on the user's unit or origin. Every bound is carried over exactly
 * (scaled); absent bounds become the wide internal defaults below.
 */
import type { Point } from '../solver';
import type { PathTask } from './types';
import { checkArray, checkFiniteNumber, checkPoint, show } from './validate';

/** Timing model of a normalised task: free θ2 per target, a fixed step, or given θ2 (radians). */
export type TimingKind = 'free' | 'step' | 'given';

/** A path task in normalised units (user = centre + scale × normalised). */
export interface NormalisedTask {
  n: number;
  tx: Float64Array;
  ty: Float64Array;
  centre: Point;
  /** Size of the target set in the user's unit (largest distance from the centroid; 1 for a single point). */
  scale: number;
  timing: TimingKind;
  /** θ2 advance per target for 'step' (radians, signed). */
  step: number;
  /** θ2 per target for 'given' (radians). */
  given: Float64Array;
  /** Fixed placement (normalised O2, ground angle in radians), or null when it is free. */
  placement: { x: number; y: number; angle: number } | null;
  /** Length bounds of r1..r4 (normalised); lenMin > 0. */
  lenMin: number;
  lenMax: number;
  /** Largest |AP| (normalised; Infinity when unbounded). */
  coupler: number;
  /** Box of O2 (normalised; infinite when unbounded). */
  pivotMin: Point;
  pivotMax: Point;
  /** True when the input must turn fully ('crank'). */
  crank: boolean;
  /** Sampling ranges of the global stage (normalised), inside the bounds. */
  sampleMin: number;
  sampleMax: number;
}

/**
 * Most targets a path task may have: one Levenberg–Marquardt iteration is dense in the 9 + n variables (about
 * 30 ms at 200 free-timing targets on a desktop core), and the search yields between iterations.
 */
export const MAX_PATH_TARGETS = 200;
/** Smallest and largest target-set size accepted (task's unit). */
export const MIN_TARGET_SIZE = 1e-100;
export const MAX_TARGET_SIZE = 1e100;
/** Lengths below this fraction of the target size are not sampled, and never allowed below it times 1e-6. */
const DEFAULT_MIN = 1e-6;
const DEFAULT_MAX = 1e6;
/** Default sampling range of link lengths when the task gives none (normalised units). */
const SAMPLE_MIN = 0.1;
const SAMPLE_MAX = 6;

/** Throws unless task is a well-formed PathTask, naming the parameter and the value. */
export function checkPathTask(task: unknown): asserts task is PathTask {
  if (typeof task !== 'object' || task === null) throw new Error(`task must be a path task object, got ${show(task)}`);
  const t = task as Record<string, unknown>;
  checkArray('task.targets', t.targets, 1, MAX_PATH_TARGETS);
  (t.targets as unknown[]).forEach((p, i) => checkPoint(`task.targets[${i}]`, p));
  const n = (t.targets as unknown[]).length;
  const timing = t.timing as Record<string, unknown> | undefined;
  if (typeof timing !== 'object' || timing === null) {
    throw new Error(`task.timing must be { kind: 'free' | 'step' | 'given', ... }, got ${show(timing)}`);
  }
  if (timing.kind === 'step') {
    checkFiniteNumber('task.timing.step', timing.step, 'angle in radians');
    if (timing.step === 0) throw new Error(`task.timing.step must be a nonzero angle in radians, got 0`);
  } else if (timing.kind === 'given') {
    checkArray('task.timing.theta2', timing.theta2, n, n);
    (timing.theta2 as unknown[]).forEach((a, i) =>
      checkFiniteNumber(`task.timing.theta2[${i}]`, a, 'angle in radians'),
    );
  } else if (timing.kind !== 'free') {
    throw new Error(`task.timing.kind must be 'free', 'step' or 'given', got ${show(timing.kind)}`);
  }
  if (t.placement !== undefined) {
    const pl = t.placement as Record<string, unknown>;
    if (typeof pl !== 'object' || pl === null) {
      throw new Error(`task.placement must be { O2, groundAngle }, got ${show(t.placement)}`);
    }
    checkPoint('task.placement.O2', pl.O2);
    checkFiniteNumber('task.placement.groundAngle', pl.groundAngle, 'angle in radians');
  }
  if (t.bounds !== undefined) {
    const b = t.bounds as Record<string, unknown>;
    if (typeof b !== 'object' || b === null) throw new Error(`task.bounds must be an object, got ${show(t.bounds)}`);
    if (b.length !== undefined) {
      checkArray('task.bounds.length', b.length, 2, 2);
      const [lo, hi] = b.length as unknown[];
      checkFiniteNumber('task.bounds.length[0]', lo, 'length');
      checkFiniteNumber('task.bounds.length[1]', hi, 'length');
      if (lo < 0) throw new Error(`task.bounds.length[0] must be a length >= 0, got ${lo}`);
      if (!(hi > lo)) throw new Error(`task.bounds.length must have min < max, got [${lo}, ${hi}]`);
    }
    if (b.coupler !== undefined) {
      checkFiniteNumber('task.bounds.coupler', b.coupler, 'length');
      if (b.coupler < 0) throw new Error(`task.bounds.coupler must be a length >= 0, got ${b.coupler}`);
    }
    if (b.pivot !== undefined) {
      const pv = b.pivot as Record<string, unknown>;
      if (typeof pv !== 'object' || pv === null) {
        throw new Error(`task.bounds.pivot must be { min, max }, got ${show(b.pivot)}`);
      }
      checkPoint('task.bounds.pivot.min', pv.min);
      checkPoint('task.bounds.pivot.max', pv.max);
      const mn = pv.min as Point;
      const mx = pv.max as Point;
      if (mn.x > mx.x || mn.y > mx.y) {
        throw new Error(`task.bounds.pivot must have min <= max, got min ${show(mn)} and max ${show(mx)}`);
      }
    }
  }
  if (t.input !== undefined && t.input !== 'crank' && t.input !== 'any') {
    throw new Error(`task.input must be 'crank' or 'any', got ${show(t.input)}`);
  }
  if (t.placement !== undefined && t.bounds !== undefined) {
    const pv = (t.bounds as PathTask['bounds'])?.pivot;
    const O2 = (t.placement as { O2: Point }).O2;
    if (pv && (O2.x < pv.min.x || O2.x > pv.max.x || O2.y < pv.min.y || O2.y > pv.max.y)) {
      throw new Error(`task.placement.O2 ${show(O2)} lies outside task.bounds.pivot ${show(pv)}`);
    }
  }
}

/** The task in normalised units; checks it first (throws as checkPathTask). */
export function normaliseTask(task: PathTask): NormalisedTask {
  checkPathTask(task);
  const n = task.targets.length;
  let cx = 0;
  let cy = 0;
  for (const p of task.targets) {
    cx += p.x;
    cy += p.y;
  }
  cx /= n;
  cy /= n;
  let size = 0;
  for (const p of task.targets) size = Math.max(size, Math.hypot(p.x - cx, p.y - cy));
  if (!(size > 0)) size = Math.max(1, Math.abs(cx), Math.abs(cy));
  // Σd² is reported in the task's unit squared: beyond these sizes it would overflow, or underflow to 0 for every
  // answer (issue 31), so the task is refused rather than ranked on zeros.
  if (!(size >= MIN_TARGET_SIZE && size <= MAX_TARGET_SIZE)) {
    throw new Error(
      `task.targets must span between ${MIN_TARGET_SIZE} and ${MAX_TARGET_SIZE} (largest distance from their centroid), got ${show(size)}: rescale the unit`,
    );
  }
  const tx = new Float64Array(n);
  const ty = new Float64Array(n);
  task.targets.forEach((p, i) => {
    tx[i] = (p.x - cx) / size;
    ty[i] = (p.y - cy) / size;
  });
  const b = task.bounds ?? {};
  if (b.length && !(b.length[1] / size > DEFAULT_MIN)) {
    throw new Error(
      `task.bounds.length[1] must exceed ${DEFAULT_MIN} of the targets' size (${show(size)}): links shorter than that are not searched, got ${show(b.length[1])}`,
    );
  }
  const lenMin = b.length ? Math.max(b.length[0] / size, DEFAULT_MIN) : DEFAULT_MIN;
  const lenMax = b.length ? b.length[1] / size : DEFAULT_MAX;
  const coupler = b.coupler !== undefined ? b.coupler / size : Infinity;
  const pivotMin = b.pivot
    ? { x: (b.pivot.min.x - cx) / size, y: (b.pivot.min.y - cy) / size }
    : { x: -Infinity, y: -Infinity };
  const pivotMax = b.pivot
    ? { x: (b.pivot.max.x - cx) / size, y: (b.pivot.max.y - cy) / size }
    : { x: Infinity, y: Infinity };
  const timing = task.timing;
  const placement = task.placement
    ? { x: (task.placement.O2.x - cx) / size, y: (task.placement.O2.y - cy) / size, angle: task.placement.groundAngle }
    : null;
  return {
    n,
    tx,
    ty,
    centre: { x: cx, y: cy },
    scale: size,
    timing: timing.kind,
    step: timing.kind === 'step' ? timing.step : 0,
    given: Float64Array.from(timing.kind === 'given' ? timing.theta2 : []),
    placement,
    lenMin,
    lenMax,
    coupler,
    pivotMin,
    pivotMax,
    crank: (task.input ?? 'crank') === 'crank',
    sampleMin: Math.max(lenMin, Math.min(SAMPLE_MIN, lenMax / 60)),
    sampleMax: Math.min(lenMax, Math.max(SAMPLE_MAX, lenMin * 60)),
  };
}
