import type { MechanismSpec, MechanismSweep } from '../../mechanism';
import { job } from '../../shared/jobs/jobTable';

/** A sweep of a linkage over inputs (rad or length), with its rates at ω = 1, α = 0 when asked. */
export interface MechSweepParams {
  spec: MechanismSpec;
  inputs: Float64Array;
  rates: boolean;
}

/** The mechanism page's jobs: a sweep (the plots' rates, the CSV's table); a newer call drops an older one. */
export const mechanismJobs = {
  mechSweep: job<MechSweepParams, MechanismSweep>({ inFlight: 'drop', budgetMs: () => 20_000 }),
};

/** The mechanism page's job table. */
export type MechanismJobs = typeof mechanismJobs;
