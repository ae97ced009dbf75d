import { GROUND, mobility, sweepMechanism, validateSpec } from '../../mechanism';
import type { MechanismSpec, MechanismSweep } from '../../mechanism';
import { PI } from '../../solver/angles';

/** Input step of the drawn grid: 1° for a pin input (so the CSV's rows are on it), 1/360 of the range for a slider. */
export const STEPS_PER_TURN = 360;

/** The input grid: inputs k·step for k = kLo … kHi (0 exactly at k = 0), radians for a pin, length for a slider. */
export interface InputGrid {
  kind: 'R' | 'P';
  step: number;
  kLo: number;
  kHi: number;
  inputs: Float64Array;
}

/** Why a linkage does not run: not a mobility-1 linkage (mobility ≠ 1, no input, loose links), or stuck where drawn. */
export type MechProblem =
  | { code: 'mobility'; mobility: number }
  | { code: 'noInput' }
  | { code: 'invalid'; detail: string }
  | { code: 'singular' };

/** The linkage on the grid: its poses (positions only), the run Play moves over, whether the input turns fully. */
export interface MechAnalysis {
  spec: MechanismSpec;
  mobility: number;
  problem: MechProblem | null;
  grid: InputGrid | null;
  sweep: MechanismSweep | null;
  /** Grid indices [first, last] of the assembled run that holds the drawn pose (input 0). */
  run: [number, number] | null;
  /** A pin input that assembles over the whole turn: Play wraps instead of rocking. */
  fullTurn: boolean;
  /** The run's ends, refined to LIMIT_TOLERANCE of the grid's span where the linkage stops (withRefinedLimits). */
  limits: [number, number] | null;
}

/** The kind of the spec's input joint, or null when none is chosen (or it is not a joint). */
export function inputKind(spec: MechanismSpec): 'R' | 'P' | null {
  return spec.joints.find((j) => j.id === spec.input.joint)?.kind ?? null;
}

/** The largest distance between two drawn points of the spec (its size; 1 for one point or none). */
export function specSize(spec: MechanismSpec): number {
  const pts = [...spec.joints, ...(spec.points ?? [])];
  let size = 0;
  for (const a of pts) for (const b of pts) size = Math.max(size, Math.hypot(a.x - b.x, a.y - b.y));
  return size > 0 ? size : 1;
}

/**
 * The input grid of a spec: a pin input over [−π, π] in 1° steps, a slider input over ± the linkage's size in 360
 * steps; the sweep finds a rocking input's limits itself, to within a step.
 */
export function inputGrid(spec: MechanismSpec): InputGrid | null {
  const kind = inputKind(spec);
  if (!kind) return null;
  const lo = kind === 'R' ? -PI : -specSize(spec);
  const hi = -lo;
  const step = kind === 'R' ? PI / 180 : (hi - lo) / STEPS_PER_TURN;
  // Rounded so that the ends land on whole steps despite rounding (−π/(π/180) is −180 give or take an ulp).
  const kLo = Math.ceil(lo / step - 1e-9);
  const kHi = Math.floor(hi / step + 1e-9);
  const inputs = new Float64Array(kHi - kLo + 1);
  for (let k = kLo; k <= kHi; k++) inputs[k - kLo] = k * step;
  return { kind, step, kLo, kHi, inputs };
}

/** Why validateSpec refuses a spec, sorted into what the page tells the person to do. */
export function mechProblem(spec: MechanismSpec): MechProblem | null {
  if (!spec.joints.some((j) => j.id === spec.input.joint)) return { code: 'noInput' };
  const m = mobility(spec);
  if (m !== 1) return { code: 'mobility', mobility: m };
  try {
    validateSpec(spec);
    return null;
  } catch (e) {
    return { code: 'invalid', detail: (e as Error).message };
  }
}

/** The indices [first, last] of the assembled run of ok around index i0 (null when i0 is not assembled). */
export function assembledRun(ok: ArrayLike<number>, i0: number): [number, number] | null {
  if (!ok[i0]) return null;
  let a = i0;
  let b = i0;
  while (a > 0 && ok[a - 1]) a--;
  while (b < ok.length - 1 && ok[b + 1]) b++;
  return [a, b];
}

/**
 * Analyses a spec for the page: its mobility and what stops it, and when it runs, its poses on the input grid
 * (positions only: the rates come from the worker) and the run Play moves over.
 */
export function analyseMechanism(spec: MechanismSpec, refine = true): MechAnalysis {
  const m = spec.links.includes(GROUND) ? mobility(spec) : NaN;
  const problem = mechProblem(spec);
  const none = { spec, mobility: m, grid: null, sweep: null, run: null, fullTurn: false, limits: null };
  if (problem) return { ...none, problem };
  const grid = inputGrid(spec)!;
  const sweep = sweepMechanism(spec, grid.inputs);
  const run = assembledRun(sweep.ok, -grid.kLo);
  if (!run) return { ...none, grid, sweep, problem: { code: 'singular' } };
  const fullTurn = grid.kind === 'R' && run[0] === 0 && run[1] === grid.inputs.length - 1;
  const analysis = { spec, mobility: m, problem: null, grid, sweep, run, fullTurn, limits: runEnds(grid, run) };
  return refine ? withRefinedLimits(analysis) : analysis;
}

/**
 * The analysis with a rocking input's limits refined (refineLimits: tens of sweeps, up to about 0.1 s on a six-bar),
 * or itself where the input turns fully or does not run. The page refines once its edits settle, not per drag move.
 */
export function withRefinedLimits(a: MechAnalysis): MechAnalysis {
  if (!a.grid || !a.run || a.fullTurn) return a;
  return { ...a, limits: refineLimits(a.spec, a.grid, a.run) };
}

/** The input range Play moves over: the run's ends (a full turn: [−π, π]). */
export function runRange(a: MechAnalysis): [number, number] | null {
  if (!a.grid || !a.run) return null;
  return [a.grid.inputs[a.run[0]], a.grid.inputs[a.run[1]]];
}

/** Linear interpolation of a series on the grid at input t (NaN off the grid); on a sample (1e-9 of a step), its value. */
export function valueAt(a: Pick<MechAnalysis, 'grid'>, values: ArrayLike<number>, t: number): number {
  if (!a.grid) return NaN;
  const u = t / a.grid.step - a.grid.kLo;
  const i = Math.max(0, Math.min(values.length - 2, Math.floor(u)));
  const f = u - i;
  if (!(f >= -1e-9 && f <= 1 + 1e-9)) return NaN;
  // On a sample the other may be missing (the end of a rocking run).
  if (Math.abs(f) <= 1e-9) return values[i];
  if (Math.abs(f - 1) <= 1e-9) return values[i + 1];
  return values[i] + (values[i + 1] - values[i]) * f;
}

/** How closely refineLimits finds a limit: this fraction of the grid's span (2π for a pin input). */
export const LIMIT_TOLERANCE = 1e-9;

const runEnds = (grid: InputGrid, run: [number, number]): [number, number] => [
  grid.inputs[run[0]],
  grid.inputs[run[1]],
];

/**
 * Where a rocking input stops, to LIMIT_TOLERANCE of the grid's span: between the run's last assembled sample and
 * the next one (not assembled), bisection on assembly, each trial a sweep from the drawn pose through the input
 * known to assemble to the midpoint (so it stays on the drawn branch). An end of the run at the grid's end stays.
 */
export function refineLimits(spec: MechanismSpec, grid: InputGrid, run: [number, number]): [number, number] {
  const n = grid.inputs.length;
  const tol = LIMIT_TOLERANCE * (grid.inputs[n - 1] - grid.inputs[0]);
  const refine = (ok: number, bad: number) => {
    let [a, b] = [ok, bad];
    while (Math.abs(b - a) > tol) {
      const mid = (a + b) / 2;
      if (sweepMechanism(spec, Float64Array.of(a, mid)).ok[1]) a = mid;
      else b = mid;
    }
    return a;
  };
  const [lo, hi] = runEnds(grid, run);
  return [
    run[0] > 0 ? refine(lo, grid.inputs[run[0] - 1]) : lo,
    run[1] < n - 1 ? refine(hi, grid.inputs[run[1] + 1]) : hi,
  ];
}
