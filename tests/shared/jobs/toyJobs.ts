import { job } from '../../../src/shared/jobs/jobTable';
import type { JobHandlers } from '../../../src/shared/jobs/jobTable';

/** A small table with one job per policy the kit offers, for the kit's own tests. */
export const toyJobs = {
  /** Latest wins, the answer in flight delivered. */
  echo: job<{ n: number }, { n: number }>({ inFlight: 'deliver', budgetMs: () => 100 }),
  /** Latest wins, the call in flight dropped; its params' buffer transferred. */
  sum: job<{ xs: Float64Array }, { total: number; xs: Float64Array }>({
    budgetMs: () => 100,
    transfer: (p) => [p.xs.buffer as ArrayBuffer],
  }),
  /** A long job: progress per stage, stops when cancelled; budget per stage. */
  slow: job<{ stages: number; stageMs?: number }, { stages: number } | null>({ budgetMs: () => 500 }),
  /** A queue: every call sent and answered. */
  step: job<{ i: number }, { i: number }>({ mode: 'queue', budgetMs: () => 100 }),
  /** Always throws. */
  fail: job<{ message: string }, { never: true }>({ budgetMs: () => 100 }),
};

/** The toy table's job types. */
export type ToyJobs = typeof toyJobs;

/** Counters the toy handlers keep, for tests that watch the worker side. */
export const toyStats = { slowStages: 0 };

/** Handlers of the toy table. */
export const toyHandlers: JobHandlers<ToyJobs> = {
  echo: (p) => ({ n: p.n }),
  sum: (p) => ({ total: p.xs.reduce((a, b) => a + b, 0), xs: p.xs.map((x) => 2 * x) }),
  async slow(p, { signal, progress }) {
    for (let i = 0; i < p.stages; i++) {
      progress(i / p.stages, `stage ${i}`);
      toyStats.slowStages++;
      await new Promise((r) => setTimeout(r, p.stageMs ?? 0));
      if (signal.aborted) return null;
    }
    return { stages: p.stages };
  },
  step: (p) => ({ i: p.i }),
  fail: (p) => {
    throw new Error(p.message);
  },
};
