import type { JobHandlers } from '../../shared/jobs/jobTable';
import type { MechanismJobs } from './jobs';

/**
 * The mechanism page's handler: sweepMechanism, and solveMechForces when the forces are asked, loaded on the first
 * call so the worker's first load stays small.
 */
export const mechanismHandlers: JobHandlers<MechanismJobs> = {
  async mechSweep({ spec, inputs, rates, forces }) {
    const [{ sweepMechanism }, { solveMechForces }] = await Promise.all([
      import('../../mechanism'),
      import('./mechForces'),
    ]);
    const sweep = sweepMechanism(spec, inputs, rates ? { omega: 1, alpha: 0 } : undefined);
    return forces ? { ...sweep, forces: solveMechForces(spec, inputs, forces) } : sweep;
  },
};
