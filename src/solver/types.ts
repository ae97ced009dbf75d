/** Link lengths of a planar four-bar, in any one unit: ground, crank (input), coupler, rocker (output). */
export interface Linkage {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
}

/** Assembly branch: open has sin(theta4 - theta3) > 0 (coupler pin B left of the ray from crank pin A to O4). */
export type Branch = 'open' | 'crossed';

/** Coupler and rocker angles in radians, counter-clockwise from the ground line, wrapped to (-pi, pi]. */
export interface Angles {
  theta3: number;
  theta4: number;
}

/** Linkage type as used by the app (see classify). */
export type LinkageType =
  'crank-rocker' | 'double-crank' | 'double-rocker' | 'change-point' | 'triple-rocker' | 'cannot-assemble';

/** Closed interval of the input angle theta2 in radians, lo <= hi; may extend past pi when it wraps. */
export interface AngleInterval {
  lo: number;
  hi: number;
}

/** Where the crank can go: a full turn, one or two intervals, or nowhere. */
export interface InputRange {
  full: boolean;
  /** Empty when the linkage cannot be assembled at any input angle; one [-pi, pi] interval when full. */
  intervals: AngleInterval[];
}

/** Result of classify: Grashof test, type, Barker class and the input's reachable range. */
export interface Classification {
  grashof: boolean;
  type: LinkageType;
  S: number;
  L: number;
  P: number;
  Q: number;
  /** Barker class as tabulated in Norton, e.g. 'I-2 GCRR', 'II-1 RRR1', 'III-5 S2X'; 'none' when it cannot assemble. */
  barker: string;
  /** True when the crank input turns a full revolution. */
  inputIsCrank: boolean;
  inputRange: InputRange;
}

/** Outcome of one Newton-Raphson solve. */
export type NewtonStatus = 'converged' | 'singular' | 'max-iterations';

/** One row of the NR iteration log; angles in radians (wrapped), residuals in the linkage's length unit. */
export interface IterationRecord {
  iteration: number;
  theta3: number;
  theta4: number;
  f1: number;
  f2: number;
  /** Euclidean norm of (f1, f2). */
  residual: number;
  /** Euclidean norm of the NR step (radians) that followed this row; 0 on the last row. */
  stepNorm: number;
  /** Jacobian determinant r3 r4 sin(theta3 - theta4) at this row. */
  detJ: number;
}

/** Options of solveNewton. */
export interface NewtonOptions {
  /** Tolerance: relative on |f| / (r1 + r2 + r3 + r4), default 1e-13, then polished; with seed, absolute on |f1| and |f2|, default 1e-9. */
  tol?: number;
  /** Iteration cap, an integer from 0 to 100000; default 100 (as in the report, docs/report.md). */
  maxIterations?: number;
  /** Reproduce the report's Algorithm 1 exactly: absolute 1e-9 on |f1| and |f2|, singular at |det J| < 1e-9. */
  seed?: boolean;
  /** Polish to full double precision after the tolerance is met (default true unless seed). */
  polish?: boolean;
  /** Keep the per-iteration log (default true). */
  log?: boolean;
}

/** Result of solveNewton: wrapped angles, status, iteration count, final residual norm and the log. */
export interface NewtonResult extends Angles {
  status: NewtonStatus;
  iterations: number;
  residual: number;
  detJ: number;
  log: IterationRecord[];
}

/** Status of one sweep point. */
export type PointStatus = 'ok' | 'unreachable' | 'singular' | 'failed';

/**
 * Sweep methods: 'closed-form' (the default: stable closed form, fastest), 'closed-form-polish' (plus
 * one NR step), 'newton' (NR continuation with a predictor), 'newton-no-predictor', 'seed' (the
 * report's Algorithm 2).
 */
export type SweepMethod = 'newton' | 'newton-no-predictor' | 'seed' | 'closed-form' | 'closed-form-polish';

/** Options of sweep. */
export interface SweepOptions {
  branch: Branch;
  /** Default 'closed-form' (DEFAULT_SWEEP_METHOD); undefined means the default, anything else not in SWEEP_METHODS throws. */
  method?: SweepMethod;
  /** NR tolerance, positive: relative for the project's NR methods (default 1e-13), absolute for 'seed' (1e-9); unused by the closed form. */
  tol?: number;
  /** NR methods: polish to full precision after the tolerance is met (default true). */
  polish?: boolean;
  /**
   * Input motion (omega2 rad/s, alpha2 rad/s², counter-clockwise positive): when given, the result also carries
   * omega3, omega4, alpha3 and alpha4 (see src/solver/rates.ts); when absent nothing extra is computed.
   */
  rates?: { omega2: number; alpha2: number };
}

/** Result of sweep; angles in radians wrapped to (-pi, pi], NaN where status is not 'ok'. */
export interface SweepResult {
  theta2: Float64Array;
  theta3: Float64Array;
  theta4: Float64Array;
  iterations: Int32Array;
  /** Loop-closure residual norm at each point (length unit), NaN where not 'ok'. */
  residual: Float64Array;
  /** One byte per point: the index of its status in POINT_STATUSES (0 ok, 1 unreachable, 2 singular, 3 failed). */
  statusCodes: Uint8Array;
  /** Status of each point, decoded from statusCodes on first read (a big sweep that never reads it pays nothing). */
  readonly status: PointStatus[];
  totalIterations: number;
  /** Points where NR landed on the other branch and were re-solved on the requested one. */
  branchCorrections: number;
  /** Coupler and rocker angular velocities (rad/s) and accelerations (rad/s²), only when opts.rates was given; NaN where status is not 'ok' and at limit positions. */
  omega3?: Float64Array;
  omega4?: Float64Array;
  alpha3?: Float64Array;
  alpha4?: Float64Array;
}
