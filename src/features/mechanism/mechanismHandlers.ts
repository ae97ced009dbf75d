import type { JobHandlers } from '../../shared/jobs/jobTable';
import type { MechanismJobs } from './jobs';

/** The mechanism page's handler: sweepMechanism, loaded on the first call so the worker's first load stays small. */
export const mechanismHandlers: JobHandlers<MechanismJobs> = {
  async mechSweep({ spec, inputs, rates }) {
    const { sweepMechanism } = await import('../../mechanism');
    return sweepMechanism(spec, inputs, rates ? { omega: 1, alpha: 0 } : undefined);
  },
};
