import { computeCycle, computePoint, computeTable } from './compute';
import type { SolverApi } from '../shared/jobs/protocol';

/**
 * The solver's one API object. The worker exposes it (solver.worker.ts), and when no worker can run
 * the client serves the same object on the main thread (mainThread.ts). Methods throw for bad input;
 * expose() turns that into an error answer labelled with the request's type.
 */
export const solverApi: SolverApi = {
  cycle: computeCycle,
  point: computePoint,
  table: computeTable,
  /**
   * The work-precision study; yields between stages so a cancel can arrive. Loads the study and the 40-digit
   * reference only now: they stay off the first load.
   */
  async lab(params, task) {
    const [{ runWorkPrecision }, { referencePose }] = await Promise.all([
      import('../study/workPrecision'),
      import('../study/reference'),
    ]);
    return runWorkPrecision(params.linkage, {
      branch: params.branch,
      stepDeg: params.stepDeg,
      now: () => performance.now(),
      reference: referencePose,
      onProgress: task.progress,
      pause: () => new Promise((resolve) => setTimeout(resolve, 0)),
      isCancelled: task.cancelled,
    });
  },
};
