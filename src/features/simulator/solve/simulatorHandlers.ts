import type { JobHandlers } from '../../../shared/jobs/jobTable';
import type { SimulatorJobs } from '../jobs';
import { computeCycle, computePoint, computeTable } from './compute';

/** The simulator's handlers: the solves of compute.ts (they throw for bad input; the worker answers an error). */
export const simulatorHandlers: JobHandlers<SimulatorJobs> = {
  cycle: computeCycle,
  point: computePoint,
  table: computeTable,
};
