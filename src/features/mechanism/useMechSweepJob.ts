import { useEffect, useState } from 'react';
import type { MechanismForces, MechanismSweep } from '../../mechanism';
import type { JobRunner } from '../../shared/jobs/jobClient';
import type { MechanismJobs, MechSweepResult } from './jobs';
import type { MechAnalysis } from './mechAnalysis';
import type { MechForcesJob } from './mechForces';

/** The worker's sweep of the page's grid: the rates (ω = 1) and, when asked, the forces; null until it answers. */
export interface MechSweepAnswer {
  rates: MechanismSweep | null;
  forces: MechanismForces | null;
  /** Asked and not answered yet for the linkage and settings shown. */
  pending: boolean;
  /** Why the forces could not be solved (the worker's message), or null. */
  error: string | null;
}

/** The forces' settings as a key: an answer for other settings is not shown. */
const jobKey = (job: MechForcesJob | null) => (job ? JSON.stringify(job) : '');

/**
 * Runs the mechSweep job on the grid of the analysed linkage whenever its rates or its forces are wanted (channel
 * mechRates: a newer call drops an older one), and keeps the answer that belongs to the linkage and settings shown.
 */
export function useMechSweepJob(
  client: JobRunner<MechanismJobs> | null,
  analysis: MechAnalysis,
  wantRates: boolean,
  forces: MechForcesJob | null,
): MechSweepAnswer {
  const key = jobKey(forces);
  const [answer, setAnswer] = useState<{
    analysis: MechAnalysis;
    key: string;
    sweep: MechSweepResult | null;
    error: string | null;
  } | null>(null);
  const want = wantRates || forces !== null;
  useEffect(() => {
    if (!client || !want || !analysis.grid || analysis.problem) return;
    const job: MechForcesJob | null = key ? (JSON.parse(key) as MechForcesJob) : null;
    const run = client.run(
      'mechSweep',
      { spec: analysis.spec, inputs: analysis.grid.inputs, rates: true, ...(job ? { forces: job } : {}) },
      { channel: 'mechRates' },
    );
    run.result
      .then((sweep) => sweep && setAnswer({ analysis, key, sweep, error: null }))
      .catch((e: unknown) => setAnswer({ analysis, key, sweep: null, error: (e as Error).message ?? String(e) }));
    return () => run.cancel();
  }, [client, want, analysis, key]);
  const current = answer && answer.analysis === analysis ? answer : null;
  const forcesHere = current && current.key === key && key !== '' ? current : null;
  return {
    rates: current?.sweep ?? null,
    forces: forcesHere?.sweep?.forces ?? null,
    pending: want && !analysis.problem && (current === null || (key !== '' && forcesHere === null)),
    error: forcesHere?.error ?? null,
  };
}
