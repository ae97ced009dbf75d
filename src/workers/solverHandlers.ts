import { combineJobs } from '../shared/jobs/jobTable';
import { labHandlers } from '../features/lab/labHandlers';
import { simulatorHandlers } from '../features/simulator/solve/simulatorHandlers';
import { synthesisHandlers } from '../features/synthesis/synthesisHandlers';
import { mechanismHandlers } from '../features/mechanism/mechanismHandlers';

/**
 * Every job the solver worker serves: each feature's handlers (in its own folder), registered here (the composition
 * root of the solver's jobs). The worker serves it (solver.worker.ts); the main-thread fallback loads and serves the same.
 */
export const solverHandlers = combineJobs(
  combineJobs(combineJobs(simulatorHandlers, labHandlers), synthesisHandlers),
  mechanismHandlers,
);
