import type { JobHandlers } from '../shared/jobs/jobTable';
import { combineJobs } from '../shared/jobs/jobTable';
import type { LabJobs } from '../features/lab/jobs';
import type { SimulatorJobs } from '../features/simulator/jobs';
import type { SynthesisJobs } from '../features/synthesis/jobs';
import { computeCycle, computePoint, computeTable } from './compute';

/** The simulator's handlers: the solves of compute.ts (they throw for bad input; the worker answers an error). */
export const simulatorHandlers: JobHandlers<SimulatorJobs> = {
  cycle: computeCycle,
  point: computePoint,
  table: computeTable,
};

/** The lab's handler: the work-precision study, yielding between stages so a cancel can arrive. */
export const labHandlers: JobHandlers<LabJobs> = {
  async lab(params, { signal, progress }) {
    // The study and the 40-digit reference load only now: they stay off the worker's first load.
    const [{ runWorkPrecision }, { referencePose }] = await Promise.all([
      import('../study/workPrecision'),
      import('../study/reference'),
    ]);
    return runWorkPrecision(params.linkage, {
      branch: params.branch,
      stepDeg: params.stepDeg,
      now: () => performance.now(),
      reference: referencePose,
      onProgress: progress,
      pause: () => new Promise((resolve) => setTimeout(resolve, 0)),
      isCancelled: () => signal.aborted,
    });
  },
};

/** The synthesis page's handlers: a part of a path synthesis's global stage, and the merge of the parts. */
export const synthesisHandlers: JobHandlers<SynthesisJobs> = {
  async pathPart(params, { signal, progress }) {
    // The synthesis numerics load only now: they stay off the worker's first load.
    const { pathSynthesisPart } = await import('../synthesis');
    const { task, seed, part, parts, rounds, budgetMs } = params;
    return pathSynthesisPart(task, {
      seed,
      part,
      parts,
      rounds,
      budgetMs,
      signal,
      onProgress: ({ fraction, best }) => progress(fraction, String(best)),
    });
  },
  async pathMerge(params) {
    const { mergePathCandidates } = await import('../synthesis');
    return mergePathCandidates(params.task, params.parts);
  },
};

/**
 * Every job the solver worker serves: each feature's handlers, registered here (the composition root of the
 * solver's jobs). The worker serves it (solver.worker.ts); the main-thread fallback loads and serves the same.
 */
export const solverHandlers = combineJobs(combineJobs(simulatorHandlers, labHandlers), synthesisHandlers);
