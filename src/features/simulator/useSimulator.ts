import { useMemo } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../../shared/state/appState';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { CycleResponse, PointResponse } from '../../shared/solution';
import type { SolvedPlot } from './usePlotSeries';
import { usePlotSeries } from './usePlotSeries';
import type { FirstAnswers } from './useSolver';
import { useCycle, usePoint } from './useSolver';
import type { SimulatorJobs } from './jobs';
import { useThrottledValue } from '../../shared/hooks/useThrottledValue';

/** How often the worker's pose answer follows a dragged length or coupler point, ms. */
const POINT_FOLLOW_MS = 100;

/** Which views a layout shows for a state: only what shows is solved for. */
export interface ShownViews {
  /** The linkage canvas is on screen (the full app hides it on the lab page). */
  stage: boolean;
  /** Device-pixel width of the visible angle plots; 0 when none is visible. */
  plotPixels: number;
  /** A panel shows the NR runs (numbers panel or convergence plot). */
  newton: boolean;
}

/** The simulator's state, its dispatcher and the latest answers for the state. */
export interface Simulator {
  state: AppState;
  dispatch: Dispatch<Action>;
  cycle: CycleResponse | null;
  cycleError: string | null;
  point: PointResponse | null;
  /** The plotted cycle, solved on the main thread for the state's lengths; null when no plot shows. */
  plot: SolvedPlot | null;
}

/**
 * The answers of the solver client (the simulator's jobs; null until it starts) for the app state (kept by the
 * app, with undo: app/useAppHistory.ts), handed back with the state and its dispatcher: the cycle
 * and the point at theta2, requested for what shownFor(state) says is on screen (latest wins), and the plotted
 * cycle, solved on the main thread in the same render as the state.
 */
export function useSimulator(
  state: AppState,
  dispatch: Dispatch<Action>,
  shownFor: (state: AppState) => ShownViews,
  client: JobRunner<SimulatorJobs> | null,
  firstAnswers: FirstAnswers | null = null,
): Simulator {
  const { stage, plotPixels, newton } = shownFor(state);
  const solver = useMemo(
    () => ({ method: state.solver.method, tol: state.solver.tol }),
    [state.solver.method, state.solver.tol],
  );
  // Rates only for a visible rate plot, for ω2 as set: the plots flip ω3 and ω4 with the direction themselves.
  const ratePlot = plotPixels > 0 && state.display.plotKind !== 'angles';
  const rates = useMemo(
    () => (ratePlot ? { omega2: state.motion.omega2RadPerS, alpha2: state.motion.alpha2RadPerS2 } : null),
    [ratePlot, state.motion.omega2RadPerS, state.motion.alpha2RadPerS2],
  );
  const cycleNeeds = useMemo(
    () => ({
      solver,
      branch: state.design.branch,
      otherBranch: state.display.showGhost,
      curves: state.display.showTrace && stage,
    }),
    [solver, state.design.branch, state.display.showGhost, state.display.showTrace, stage],
  );
  const plot = usePlotSeries(state.design.linkage, {
    plotPixels,
    branch: state.design.branch,
    otherBranch: state.display.showGhost,
    solver,
    rates,
  });
  // The worker's pose answer feeds the numbers and the NR runs only: the canvas draws a pose solved on the
  // main thread (useLinkagePose), ghost included, so the worker need not solve the ghost.
  const pointNeeds = useMemo(() => ({ solver, ghost: false, newton }), [solver, newton]);
  const { cycle, error } = useCycle(
    client,
    state.design.linkage,
    state.solver.samples,
    state.design.coupler,
    cycleNeeds,
    firstAnswers?.cycle,
  );
  // The canvas draws every frame from a pose solved on the main thread; the worker's answer only feeds the
  // numbers and the NR plot, which follow the state (a few times a second while playing, see useAnimation).
  // While a length or P is dragged the pose request follows a few times a second (the cycle goes first).
  const pointLinkage = useThrottledValue(state.design.linkage, POINT_FOLLOW_MS);
  const pointCoupler = useThrottledValue(state.design.coupler, POINT_FOLLOW_MS);
  const point = usePoint(
    client,
    pointLinkage,
    state.design.branch,
    state.motion.theta2Deg,
    state.solver.samples,
    pointCoupler,
    pointNeeds,
    firstAnswers?.point,
  );
  return { state, dispatch, cycle, cycleError: error, point, plot };
}
