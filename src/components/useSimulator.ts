import { useMemo, useReducer } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../state/appState';
import { reducer } from '../state/appState';
import type { SolverClient, SolverMode } from '../worker/client';
import type { CycleResponse, PointResponse } from '../worker/protocol';
import { useCycle, usePoint, useSolverClient } from './useSolver';

/** Which views a layout shows for a state: only what shows is solved for. */
export interface ShownViews {
  /** The linkage canvas is on screen (the full app hides it on the lab page). */
  stage: boolean;
  /** Device-pixel width of the visible angle plots; 0 when none is visible. */
  plotPixels: number;
  /** A panel shows the NR runs (numbers panel or convergence plot). */
  newton: boolean;
}

/** The simulator's state, its dispatcher, the solver client and the latest answers for the state. */
export interface Simulator {
  state: AppState;
  dispatch: Dispatch<Action>;
  client: SolverClient | null;
  solverMode: SolverMode;
  cycle: CycleResponse | null;
  cycleError: string | null;
  point: PointResponse | null;
}

/**
 * The simulator's state (the app reducer, starting from initial) and the solver's answers for it: the cycle
 * and the point at theta2, requested for what shownFor(state) says is on screen (latest wins).
 */
export function useSimulator(initial: AppState, shownFor: (state: AppState) => ShownViews): Simulator {
  const [state, dispatch] = useReducer(reducer, initial);
  const { client, mode } = useSolverClient();
  const { stage, plotPixels, newton } = shownFor(state);
  const solver = useMemo(() => ({ method: state.method, tol: state.tol }), [state.method, state.tol]);
  const cycleNeeds = useMemo(
    () => ({
      solver,
      branch: state.branch,
      otherBranch: state.showGhost,
      curves: state.showTrace && stage,
      plotPixels,
    }),
    [solver, state.branch, state.showGhost, state.showTrace, stage, plotPixels],
  );
  const pointNeeds = useMemo(
    () => ({ solver, ghost: state.showGhost && stage, newton }),
    [solver, state.showGhost, stage, newton],
  );
  const { cycle, error } = useCycle(client, state.linkage, state.samples, state.coupler, cycleNeeds);
  const point = usePoint(
    client,
    state.linkage,
    state.branch,
    state.theta2Deg,
    state.samples,
    state.coupler,
    pointNeeds,
  );
  return { state, dispatch, client, solverMode: mode, cycle, cycleError: error, point };
}
