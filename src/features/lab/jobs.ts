import type { Branch, Linkage } from '../../solver/types';
import type { LabResult } from '../../study/workPrecision';
import { job } from '../../shared/jobs/jobTable';

/** The solver lab's work-precision study of a linkage (long: progress messages, cancellable). */
export interface LabParams {
  linkage: Linkage;
  branch: Branch;
  stepDeg: number;
}

/** Time allowed between two progress reports of a study (ms): a stage on a slow phone, with room to spare. */
export const LAB_STAGE_MS = 20_000;

/** The lab's jobs: the study answers null when cancelled; a newer study supersedes (and cancels) a running one. */
export const labJobs = {
  /** The work-precision study, with progress per stage. */
  lab: job<LabParams, LabResult | null>({ inFlight: 'drop', budgetMs: () => LAB_STAGE_MS }),
};

/** The lab's job table. */
export type LabJobs = typeof labJobs;
