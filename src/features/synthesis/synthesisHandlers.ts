import type { JobHandlers } from '../../shared/jobs/jobTable';
import type { SynthesisJobs } from './jobs';
import { pathStageText } from './jobs';

/** The synthesis page's handlers: a part of a path synthesis's global stage, and the merge of the parts. */
export const synthesisHandlers: JobHandlers<SynthesisJobs> = {
  async pathPart(params, { signal, progress }) {
    // The synthesis numerics load only now: they stay off the worker's first load.
    const { pathSynthesisPart } = await import('../../synthesis');
    const { task, seed, part, parts, rounds, budgetMs } = params;
    return pathSynthesisPart(task, {
      seed,
      part,
      parts,
      rounds,
      budgetMs,
      signal,
      onProgress: (p) => progress(p.fraction, pathStageText(p)),
    });
  },
  async pathMerge(params, { signal }) {
    const { mergePathCandidates } = await import('../../synthesis');
    const deadline = params.budgetMs === undefined ? Infinity : Date.now() + params.budgetMs;
    return mergePathCandidates(params.task, params.parts, deadline, signal);
  },
  async ninePointPart(params, { signal, progress }) {
    const { ninePointSynthesis } = await import('../../synthesis');
    const { points, start, end, retrack } = params;
    // The stage is the real roots found so far (a number as text).
    return ninePointSynthesis(points, {
      signal,
      paths: { start, end },
      retrack,
      onProgress: ({ done, total, found }) => progress(done / total, String(found)),
    });
  },
};
