import type { PathCandidate } from '../../../synthesis/globalSearch';
import { POLISH_SHARE } from '../../../synthesis/pathSynthesis';
import type { PathTask } from '../../../synthesis/types';
import type { PathMergeParams, PathPartParams } from '../jobs';

/**
 * Wall-clock budget of a run on the page (ms), the bench's (bench:synthesis): the parts search for all but
 * POLISH_SHARE of it, then the merge polishes for the rest. No round count caps a run (issue 34 item 6): the budget
 * governs it, and a run ends sooner only by an exact fit (then two rounds more) or by Stop.
 */
export const PATH_BUDGET_MS = 10_000;
/** Time the merge's polish may take past its share of the budget (ms), as pathSynthesis allows (MERGE_MS). */
const MERGE_SLACK_MS = 200;

/**
 * The job parameters of part `part` of `parts` of a run: no `rounds` (the search goes on while the budget lasts) and
 * budgetMs = (1 − POLISH_SHARE) · budgetMs (default PATH_BUDGET_MS), as pathSynthesis splits its own budget.
 */
export function pathPartParams(
  task: PathTask,
  seed: number,
  part: number,
  parts: number,
  budgetMs = PATH_BUDGET_MS,
): PathPartParams {
  return { task, seed, part, parts, budgetMs: (1 - POLISH_SHARE) * budgetMs };
}

/**
 * The merge's parameters: unbounded (so deterministic) when every part ended by its own rule (an exact fit), else
 * the polish gets the run's last POLISH_SHARE of budgetMs (default PATH_BUDGET_MS) and MERGE_SLACK_MS, as
 * pathSynthesis gives its own.
 */
export function pathMergeParams(
  task: PathTask,
  parts: PathCandidate[][],
  complete: boolean,
  budgetMs = PATH_BUDGET_MS,
): PathMergeParams {
  return complete ? { task, parts } : { task, parts, budgetMs: POLISH_SHARE * budgetMs + MERGE_SLACK_MS };
}
