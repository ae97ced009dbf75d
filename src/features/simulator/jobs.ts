import type { Branch, Linkage } from '../../solver/types';
import { job } from '../../shared/jobs/jobTable';
import type {
  CouplerSpec,
  CycleResponse,
  MethodChoice,
  PointResponse,
  TableParams,
  TableResponse,
} from '../../shared/solution';

/** The cycle the view draws: classification, both branches on the view grid (NR statistics), coupler curves. */
export interface CycleParams {
  linkage: Linkage;
  /** Intervals per cycle the user chose; the view grid has min(samples, VIEW_SAMPLES_MAX) of them. */
  samples: number;
  coupler: CouplerSpec;
  solver: MethodChoice;
  /** The branch the view shows; the other is swept only when otherBranch (ghost or plots show it) or the input rocks. */
  branch: Branch;
  otherBranch: boolean;
  /** Coupler curves only when the trace is shown. */
  curves: boolean;
}

/** One pose at theta2 (radians) on a branch, with NR runs from the continuation and cold starts. */
export interface PointParams {
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

/** Watchdog budget of a solve (ms): baseMs + perPointMs x an upper bound of the points it solves. */
export const SOLVE_BUDGET = { baseMs: 1500, perPointMs: 0.02 };

/** The budget for this many points (ms). */
function solveBudgetMs(points: number): number {
  return SOLVE_BUDGET.baseMs + SOLVE_BUDGET.perPointMs * points;
}

/** Samples of a request, 0 when they are not a number (the worker will answer that with an error). */
const samplesOf = (p: { samples: unknown }) => Number(p.samples) || 0;

/**
 * The simulator's jobs. The cycle and the point deliver their answer in flight even when a newer call waits:
 * it is newer than what the views show, and dropping it would leave a drag with no update until the worker
 * keeps up. A table in flight is dropped by a newer one (an export must not download twice).
 */
export const simulatorJobs = {
  /** Both branches of the cycle at view resolution (both when otherBranch), with coupler curves. */
  cycle: job<CycleParams, CycleResponse>({
    inFlight: 'deliver',
    budgetMs: (p) => solveBudgetMs(2 * (samplesOf(p) + 1)),
  }),
  /** One pose and its NR runs. */
  point: job<PointParams, PointResponse>({ inFlight: 'deliver', budgetMs: () => solveBudgetMs(8) }),
  /** The whole samples + 1 table of one branch; one channel per consumer (the summary, the CSV export). */
  table: job<TableParams, TableResponse>({ inFlight: 'drop', budgetMs: (p) => solveBudgetMs(samplesOf(p)) }),
};

/** The simulator's job table. */
export type SimulatorJobs = typeof simulatorJobs;
