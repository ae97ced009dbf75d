/**
 * The solver's answers (cycle, point, table) and the plotted series: what the worker sends back or the main thread
 * solves, read by several features (simulator, export) and kits (charts, linkage), so it lives here rather than in
 * one feature. The requests and policies of the jobs are
 * declared by their features (features/simulator/jobs.ts, features/lab/jobs.ts); only the table request is
 * here too, because the export asks for the table as the simulator does.
 */
import type { JobSpec } from './jobs/jobTable';
import type { InputMotion } from '../solver/rates';
import type {
  Angles,
  Branch,
  Classification,
  IterationRecord,
  Linkage,
  NewtonStatus,
  SweepMethod,
} from '../solver/types';

/** The solver method and NR tolerance the main view uses (chosen in the solver lab); tol null = the method's default. */
export interface MethodChoice {
  method: SweepMethod;
  tol: number | null;
}

/** Solver work one answer cost: points solved (closed form or NR) and NR iterations. */
export interface WorkCount {
  points: number;
  iterations: number;
}

/** Coupler point for the worker: distance from A (length unit) and angle from AB (radians). */
export interface CouplerSpec {
  distance: number;
  angleRad: number;
}

/** The full samples + 1 point table of one branch (the cycle CSV's columns and the cycle summary). */
export interface TableParams {
  linkage: Linkage;
  samples: number;
  branch: Branch;
  solver: MethodChoice;
  /** Rates, transmission angle and the coupler point's motion per row (the CSV export asks); absent or null: none. */
  motion?: { input: InputMotion; coupler: CouplerSpec } | null;
}

/** One branch of the swept view grid; angles in radians wrapped to (-pi, pi], NaN where status is not 'ok'. */
export interface BranchCycle {
  theta3: Float64Array;
  theta4: Float64Array;
  iterations: Int32Array;
  residual: Float64Array;
  /** Status of each point as a code: an index into the solver's POINT_STATUSES ('ok', 'unreachable', 'singular', 'failed'). */
  statusCodes: Uint8Array;
  /** Coupler point P along the cycle (length unit), NaN where not assembled. */
  px: Float64Array;
  py: Float64Array;
  totalIterations: number;
  branchCorrections: number;
  okCount: number;
  /** True when this branch was not swept (not shown): arrays are NaN, okCount 0. */
  skipped: boolean;
}

/** Rates along a plot or a table (rad/s, rad/s²); NaN where not assembled or at a limit position. */
export interface RateSeries {
  omega3: Float64Array;
  omega4: Float64Array;
  alpha3: Float64Array;
  alpha4: Float64Array;
}

/** One branch's plot samples: angles in radians wrapped to (-pi, pi], NaN in gaps, and the rates when asked. */
export interface PlotBranch {
  theta3: Float64Array;
  theta4: Float64Array;
  /** Present when the request asked for rates. */
  rates?: RateSeries | null;
}

/**
 * Plot samples: an adaptive theta2 grid (about one sample per plot pixel, refined at limits and fast turns). Solved
 * on the main thread (shared/charts/plotSeries.ts, usePlotSeries), not asked of the worker.
 */
export interface PlotSeries {
  theta2Deg: Float64Array;
  /** Null when that branch is not shown. */
  open: PlotBranch | null;
  crossed: PlotBranch | null;
}

/** A closed coupler curve (length unit); closed when its first and last points coincide or it rocks between limits. */
export interface CouplerCurve {
  x: Float64Array;
  y: Float64Array;
  /** The branch P was on at the first point; a rocking input's curve switches branch at the limits. */
  branch: Branch;
  /** True when the curve goes through both branches (the input rocks between limits). */
  rocking: boolean;
  /** The input interval (radians) of a rocking circuit; NaN for a full-turn branch curve. */
  loRad: number;
  hiRad: number;
}

/**
 * The cycle answer, at view resolution: theta2Deg and both branches on a uniform grid of
 * min(samples, VIEW_SAMPLES_MAX) intervals (the whole samples + 1 table is the separate table request).
 */
export interface CycleResponse {
  /** The request's linkage and coupler point, so the cycle is always labelled with what it was solved for. */
  linkage: Linkage;
  coupler: CouplerSpec;
  classification: Classification;
  /** Intervals per cycle the user chose (the table's size), not the view grid's. */
  samples: number;
  /** The view grid, degrees 0..360: theta2Deg.length - 1 = min(samples, VIEW_SAMPLES_MAX) intervals. */
  theta2Deg: Float64Array;
  open: BranchCycle;
  crossed: BranchCycle;
  curves: CouplerCurve[];
  solver: MethodChoice;
  work: WorkCount;
  elapsedMs: number;
}

/** One NR run for the panel and the convergence plot; angles in radians, residuals in the length unit. */
export interface NewtonSummary {
  start: 'continuation' | 'cold';
  guess: Angles;
  status: NewtonStatus;
  iterations: number;
  residual: number;
  detJ: number;
  theta3: number;
  theta4: number;
  /** True when NR ended on the requested branch. */
  onBranch: boolean;
  /** Absolute tolerance NR stopped at (length unit): the solver's relative tolerance times r1 + r2 + r3 + r4. */
  tolerance: number;
  log: IterationRecord[];
}

/** A pose: angles in radians (wrapped) and the transmission angle in radians [0, pi]. */
export interface PoseAngles {
  theta2: number;
  theta3: number;
  theta4: number;
  mu: number;
}

/** A pose solved at theta2: the inputs it was solved for, and the angles on the branch and on the other one. */
export interface SolvedPose {
  /** The request's linkage and coupler point, so a pose is always drawn with the lengths it was solved for. */
  linkage: Linkage;
  coupler: CouplerSpec;
  theta2Rad: number;
  branch: Branch;
  /** The pose on the branch (radians), null when the loop cannot close at theta2. */
  pose: PoseAngles | null;
  /** The other branch's pose (null when it cannot close, or when it was not asked for). */
  ghost: PoseAngles | null;
}

/** The point answer: the pose on the requested branch (null when it cannot assemble), the other branch, two NR runs. */
export interface PointResponse extends SolvedPose {
  /** NR from the solution one cycle step back (or null when that point cannot assemble). */
  continuation: NewtonSummary | null;
  /** NR from the fixed first guess of the report (docs/report.md). */
  cold: NewtonSummary | null;
  solver: MethodChoice;
  work: WorkCount;
}

/** The table answer: samples + 1 rows of one branch (theta2 degrees, theta3/theta4 radians wrapped, NaN when not ok). */
export interface TableResponse {
  linkage: Linkage;
  branch: Branch;
  samples: number;
  solver: MethodChoice;
  theta2Deg: Float64Array;
  theta3Rad: Float64Array;
  theta4Rad: Float64Array;
  /** Status of each row as a code: an index into POINT_STATUSES. */
  statusCodes: Uint8Array;
  iterations: Int32Array;
  /** Loop-closure residual of each row (length unit). */
  residual: Float64Array;
  okCount: number;
  totalIterations: number;
  branchCorrections: number;
  work: WorkCount;
  /** Present when the request asked for motion: per row, NaN where not assembled (rates also at a limit). */
  motion?: TableMotion | null;
}

/** Per-row motion of a table: rates, transmission angle (radians in [0, pi]) and the coupler point (length unit). */
export interface TableMotion extends RateSeries {
  /** The input motion the rows were solved for: ω2 (rad/s) and α2 (rad/s²), signed by the direction it turns. */
  input: InputMotion;
  mu: Float64Array;
  px: Float64Array;
  py: Float64Array;
  vpx: Float64Array;
  vpy: Float64Array;
  apx: Float64Array;
  apy: Float64Array;
}

/** The table job as a feature that only asks for tables sees it (the export's CSV, the cycle summary). */
export interface TableJobs {
  table: JobSpec<TableParams, TableResponse>;
}
