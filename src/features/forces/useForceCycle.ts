import { useMemo } from 'react';
import type { AppState } from '../../shared/state/appState';
import type { CycleForcesView } from './forceCycleData';
import { cycleForces } from './forceCycleData';
import { useForceSetup } from './useForceSetup';

/**
 * One crank turn of forces at the state's n samples (cycleForces), solved on the main thread (a few hundred
 * nanoseconds a sample) and remade only when the design, the forces, the input motion, the branch or n change:
 * not while θ2 moves.
 */
export function useForceCycle(
  state: Pick<AppState, 'design' | 'motion' | 'forces' | 'solver'>,
): CycleForcesView | null {
  const setup = useForceSetup(state);
  const branch = state.design.branch;
  const samples = state.solver.samples;
  return useMemo(() => cycleForces(setup, branch, samples), [setup, branch, samples]);
}
