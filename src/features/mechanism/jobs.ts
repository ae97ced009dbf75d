import type { MechanismForces, MechanismSpec, MechanismSweep } from '../../mechanism';
import { job } from '../../shared/jobs/jobTable';
import type { MechForcesJob } from './mechForces';

/**
 * A sweep of a linkage over inputs (rad or length), with its rates at ω = 1, α = 0 when asked, and the forces
 * over the same inputs when forces is given (solveMechForces).
 */
export interface MechSweepParams {
  spec: MechanismSpec;
  inputs: Float64Array;
  rates: boolean;
  forces?: MechForcesJob;
}

/** A sweep, with the forces when they were asked (SI: N, N·m). */
export type MechSweepResult = MechanismSweep & { forces?: MechanismForces };

/** The mechanism page's jobs: a sweep (the plots' rates and forces, the CSV's table); a newer call drops an older one. */
export const mechanismJobs = {
  mechSweep: job<MechSweepParams, MechSweepResult>({ inFlight: 'drop', budgetMs: () => 20_000 }),
};

/** The mechanism page's job table. */
export type MechanismJobs = typeof mechanismJobs;
