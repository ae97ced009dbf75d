import type { LabResult } from '../lab/workPrecision';
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

/** Solver work one response cost: points solved (closed form or NR) and NR iterations. */
export interface WorkCount {
  points: number;
  iterations: number;
}

/** Coupler point for the worker: distance from A (length unit) and angle from AB (radians). */
export interface CouplerSpec {
  distance: number;
  angleRad: number;
}

/** Ask for the whole cycle: classification and a sweep of both branches at samples + 1 points from 0 to 360 degrees. */
export interface CycleRequest {
  type: 'cycle';
  id: number;
  linkage: Linkage;
  samples: number;
  coupler: CouplerSpec;
  solver: MethodChoice;
  /** The branch the view shows; the other is swept only when otherBranch (ghost or plots show it) or the input rocks. */
  branch: Branch;
  otherBranch: boolean;
  /** Coupler curves only when the trace is shown. */
  curves: boolean;
  /** Device-pixel width of the angle plots; 0 when no plot is visible (no plot sampling at all). */
  plotPixels: number;
}

/** Ask for one pose at theta2 (radians) on a branch, with NR runs from the continuation and cold starts. */
export interface PointRequest {
  type: 'point';
  id: number;
  linkage: Linkage;
  branch: Branch;
  theta2Rad: number;
  /** Step of the cycle (radians): the continuation start is the solution one step back. */
  stepRad: number;
  coupler: CouplerSpec;
  solver: MethodChoice;
  /** Solve the other branch (the ghost) only when it is drawn; run NR only when a panel shows it. */
  ghost: boolean;
  newton: boolean;
}

/** Ask for the solver lab's work-precision study of a linkage (long: progress messages, cancellable). */
export interface LabRequest {
  type: 'lab';
  id: number;
  linkage: Linkage;
  branch: Branch;
  stepDeg: number;
}

/** Cancel the lab request with this id (it answers with result null). */
export interface CancelRequest {
  type: 'cancel';
  id: number;
}

/** Every request the main thread can send. */
export type SolverRequest = CycleRequest | PointRequest | LabRequest | CancelRequest;

/** One branch of the swept cycle; angles in radians wrapped to (-pi, pi], NaN where status is not 'ok'. */
export interface BranchCycle {
  theta3: Float64Array;
  theta4: Float64Array;
  iterations: Int32Array;
  residual: Float64Array;
  /** Status of each point as a code: an index into POINT_STATUSES ('ok', 'unreachable', 'singular', 'failed'). */
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

/** Angle plot samples: an adaptive theta2 grid (about one sample per plot pixel, refined at limits and fast turns). */
export interface PlotSeries {
  theta2Deg: Float64Array;
  /** Radians wrapped to (-pi, pi], NaN in gaps; null when that branch is not shown. */
  open: { theta3: Float64Array; theta4: Float64Array } | null;
  crossed: { theta3: Float64Array; theta4: Float64Array } | null;
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

/** The cycle answer: classification, input angles in degrees, both branches and the coupler curves. */
export interface CycleResponse {
  type: 'cycle';
  id: number;
  /** The request's linkage and coupler point, so the cycle is always labelled with what it was solved for. */
  linkage: Linkage;
  coupler: CouplerSpec;
  classification: Classification;
  samples: number;
  theta2Deg: Float64Array;
  open: BranchCycle;
  crossed: BranchCycle;
  curves: CouplerCurve[];
  /** Plot samples, or null when no plot is visible. */
  plot: PlotSeries | null;
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

/** The point answer: the pose on the requested branch (null when it cannot assemble), the other branch, two NR runs. */
export interface PointResponse {
  type: 'point';
  id: number;
  /** The request's linkage and coupler point, so a pose is always drawn with the lengths it was solved for. */
  linkage: Linkage;
  coupler: CouplerSpec;
  theta2Rad: number;
  branch: Branch;
  pose: PoseAngles | null;
  ghost: PoseAngles | null;
  /** NR from the solution one cycle step back (or null when that point cannot assemble). */
  continuation: NewtonSummary | null;
  /** NR from the report's fixed first guess. */
  cold: NewtonSummary | null;
  solver: MethodChoice;
  work: WorkCount;
}

/** Progress of a lab request: fraction in [0, 1] and the stage being computed. */
export interface LabProgressResponse {
  type: 'lab-progress';
  id: number;
  fraction: number;
  stage: string;
}

/** The lab's answer; result null when it was cancelled. */
export interface LabResponse {
  type: 'lab';
  id: number;
  result: LabResult | null;
}

/** The worker could not answer a request: the message names what was wrong. */
export interface ErrorResponse {
  type: 'error';
  id: number;
  requestType: SolverRequest['type'];
  message: string;
}

/** Every answer the worker can send. */
export type SolverResponse = CycleResponse | PointResponse | LabResponse | LabProgressResponse | ErrorResponse;
