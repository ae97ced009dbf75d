import type { JobHandlers } from '../../shared/jobs/jobTable';
import type { LabJobs } from './jobs';

/** The lab's handler: the work-precision study, yielding between stages so a cancel can arrive. */
export const labHandlers: JobHandlers<LabJobs> = {
  async lab(params, { signal, progress }) {
    // The study and the 40-digit reference load only now: they stay off the worker's first load.
    const [{ runWorkPrecision }, { referencePose }] = await Promise.all([
      import('../../study/workPrecision'),
      import('../../study/reference'),
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
