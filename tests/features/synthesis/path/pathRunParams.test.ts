/**
 * The page's path-synthesis run is governed by its budget (issue 34 item 6): no round count caps a part, so a part
 * searches until its share of the budget is spent, and it keeps the page's worker answering (progress, abort) as it
 * does. Driven through the worker's own handlers with the parameters the page sends.
 */
import { describe, expect, it } from 'vitest';
import { readPathStage } from '../../../../src/features/synthesis/jobs';
import { PATH_BUDGET_MS, pathMergeParams, pathPartParams } from '../../../../src/features/synthesis/path/pathRunParams';
import { synthesisHandlers } from '../../../../src/features/synthesis/synthesisHandlers';
import { POLISH_SHARE } from '../../../../src/synthesis';
import { BENCHMARK_CASES } from '../../../synthesis/benchmarkCases';

/** The prescribed-timing semicircle: no four-bar fits it exactly, so only the budget or a round count ends a run. */
const timed = BENCHMARK_CASES.find((c) => c.id === 'semicircle-6-timed')!.task;

describe('pathPartParams', () => {
  it('sends no round count and the run’s budget less the polish’s share', () => {
    const p = pathPartParams(timed, 7, 1, 4);
    expect('rounds' in p).toBe(false);
    expect(p).toEqual({ task: timed, seed: 7, part: 1, parts: 4, budgetMs: (1 - POLISH_SHARE) * PATH_BUDGET_MS });
    // The bench's budget (bench/synthesis.bench.ts), so the page is judged by the bench's table.
    expect(PATH_BUDGET_MS).toBe(10_000);
  });

  it('lets a part search until its budget is spent, not a round count, reporting as it goes', async () => {
    // 400 parts: the old cap of 400 rounds a run left each part one round, a fraction of a second.
    const budgetMs = 3000;
    const params = pathPartParams(timed, 1, 0, 400, budgetMs);
    const stamps: number[] = [];
    const context = {
      signal: new AbortController().signal,
      progress: (_f: number, stage: string) => {
        stamps.push(Date.now());
        expect(readPathStage(stage).best).toBeGreaterThan(0);
      },
    };
    // The event loop's longest stall during the part: what keeps a worker's abort and progress prompt.
    let last = Date.now();
    let stall = 0;
    const timer = setInterval(() => {
      stall = Math.max(stall, Date.now() - last);
      last = Date.now();
    }, 5);
    const t0 = Date.now();
    const result = await Promise.resolve(synthesisHandlers.pathPart(params, context)).finally(() =>
      clearInterval(timer),
    );
    const elapsed = Date.now() - t0;
    expect(result.complete).toBe(false);
    // More than the cap's one round (a round here takes 30 to 900 ms, idle to a load of 15 on two cores).
    expect(result.rounds).toBeGreaterThan(1);
    // It ran its budget (the last round may end past it: one round's screening and solves, a few hundred ms at most
    // on a machine shared by many jobs).
    expect(elapsed).toBeGreaterThanOrEqual(params.budgetMs);
    expect(elapsed).toBeLessThan(params.budgetMs + 3000);
    expect(stamps.length).toBe(result.rounds);
    expect(stall).toBeLessThan(1000);
  });
});

describe('pathMergeParams', () => {
  it('leaves the merge unbounded after an exact fit (deterministic) and gives it the polish’s share otherwise', () => {
    expect(pathMergeParams(timed, [[]], true)).toEqual({ task: timed, parts: [[]] });
    expect(pathMergeParams(timed, [[]], false).budgetMs).toBe(POLISH_SHARE * PATH_BUDGET_MS + 200);
  });
});
