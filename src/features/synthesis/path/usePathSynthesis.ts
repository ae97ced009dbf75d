import { useCallback, useEffect, useRef, useState } from 'react';
import type { JobRunner } from '../../../shared/jobs/jobClient';
import type { PathCandidate } from '../../../synthesis/globalSearch';
import type { PathSolution, PathTask } from '../../../synthesis/types';
import type { SynthesisJobs } from '../jobs';
import { readPathStage } from '../jobs';
import { pathMergeParams, pathPartParams } from './pathRunParams';

/** A pool of solver workers running the synthesis jobs (createSolverPool in the app). */
export interface SynthesisPool extends JobRunner<SynthesisJobs> {
  readonly size: number;
  dispose(): void;
}

/**
 * Where a run is: not started, running, finished (with answers), stopping (merging what was found before Stop),
 * stopped (with the answers found before Stop), cancelled (stopped before anything was found) or failed.
 */
export type PathRunStatus = 'idle' | 'running' | 'done' | 'stopping' | 'stopped' | 'cancelled' | 'failed';

/** A run's state: its status, progress (fraction 0 … 1, best Σd² so far), the answers and what it took. */
export interface PathRunState {
  status: PathRunStatus;
  progress: { fraction: number; best: number } | null;
  solutions: PathSolution[] | null;
  /** The task the answers are for (they stay when the task is edited, until the next run). */
  task: PathTask | null;
  error: string | null;
  elapsedMs: number;
  workers: number;
}

const IDLE: PathRunState = {
  status: 'idle',
  progress: null,
  solutions: null,
  task: null,
  error: null,
  elapsedMs: 0,
  workers: 0,
};

/** The last finished run, kept across the page's unmounts (switching to the simulator and back). */
let lastRun: PathRunState = IDLE;

/** The last finished path synthesis (the Nine points mode compares its answer with the exact ones). */
export function lastPathRun(): PathRunState {
  return lastRun;
}

/**
 * Runs a path synthesis on a pool of workers: the global stage's rounds dealt to pool.size parts (pathPart, seed and
 * parts fixed) for the run's budget (PATH_BUDGET_MS: no round count caps it), then merged (pathMerge). A run that
 * ends by an exact fit is deterministic for a seed and pool size; one that ends by the budget is a prefix of that
 * work. cancel() (Stop) aborts
 * every part and terminates the pool's workers, so no worker computes on; the candidates the parts reported so far
 * are then merged on a new pool into the answers (status stopped), or the run is cancelled when none was found yet.
 * The pool is made on the first run (again after a stop) and disposed with the page.
 */
export function usePathSynthesis(createPool: () => SynthesisPool) {
  const [state, setState] = useState<PathRunState>(lastRun);
  const pool = useRef<SynthesisPool | null>(null);
  const abort = useRef<AbortController | null>(null);
  /** The run under way: its task and each part's candidates so far (from its progress), for a stop. */
  const current = useRef<{ task: PathTask; start: number; found: PathCandidate[][] } | null>(null);

  useEffect(
    () => () => {
      abort.current?.abort();
      pool.current?.dispose();
      pool.current = null;
    },
    [],
  );

  const cancel = useCallback(() => {
    abort.current?.abort();
    abort.current = null;
    // A worker sees the abort only between two rounds of the search, and one round can take hundreds of ms on a
    // slow phone: stop the workers outright. The next run makes a new pool.
    pool.current?.dispose();
    pool.current = null;
    const run = current.current;
    current.current = null;
    const found = run ? run.found.flat() : [];
    if (!run || found.length === 0) {
      setState((s) => (s.status === 'running' ? { ...s, status: 'cancelled', progress: null } : s));
      return;
    }
    setState((s) => (s.status === 'running' ? { ...s, status: 'stopping', progress: null } : s));
    // The merge of what the parts found: a few dozen polishes on a fresh worker, cancellable like a run.
    const controller = new AbortController();
    abort.current = controller;
    const p = createPool();
    pool.current = p;
    p.run('pathMerge', pathMergeParams(run.task, run.found, false), { signal: controller.signal })
      .result.then((merged) => {
        if (controller.signal.aborted || merged === null) return;
        const stopped: PathRunState = {
          status: 'stopped',
          progress: null,
          solutions: merged,
          task: run.task,
          error: null,
          elapsedMs: performance.now() - run.start,
          workers: p.size,
        };
        lastRun = stopped;
        setState(stopped);
      })
      .catch((e: unknown) => {
        if (controller.signal.aborted) return;
        setState((s) => ({ ...s, status: 'failed', error: e instanceof Error ? e.message : String(e) }));
      })
      .finally(() => {
        if (abort.current === controller) abort.current = null;
      });
  }, [createPool]);

  const run = useCallback(
    async (task: PathTask, seed: number) => {
      abort.current?.abort();
      const controller = new AbortController();
      abort.current = controller;
      if (!pool.current) pool.current = createPool();
      const p = pool.current;
      const parts = p.size;
      const start = performance.now();
      const fractions = new Array<number>(parts).fill(0);
      const bests = new Array<number>(parts).fill(Infinity);
      const found: PathCandidate[][] = Array.from({ length: parts }, () => []);
      current.current = { task, start, found };
      setState((s) => ({
        ...s,
        status: 'running',
        progress: { fraction: 0, best: Infinity },
        error: null,
        workers: parts,
      }));
      const onProgress = (i: number) => (fraction: number, stage: string) => {
        if (controller.signal.aborted) return;
        fractions[i] = fraction;
        const reported = readPathStage(stage);
        bests[i] = Math.min(bests[i], reported.best);
        if (reported.candidates.length > 0) found[i] = reported.candidates;
        const progress = { fraction: fractions.reduce((a, b) => a + b, 0) / parts, best: Math.min(...bests) };
        setState((s) => (s.status === 'running' ? { ...s, progress } : s));
      };
      try {
        const results = await Promise.all(
          Array.from(
            { length: parts },
            (_, part) =>
              p.run('pathPart', pathPartParams(task, seed, part, parts), {
                signal: controller.signal,
                onProgress: onProgress(part),
              }).result,
          ),
        );
        if (controller.signal.aborted || results.some((r) => r === null)) return;
        const complete = results.every((r) => r!.complete);
        const merged = await p.run(
          'pathMerge',
          pathMergeParams(
            task,
            results.map((r) => r!.candidates),
            complete,
          ),
          { signal: controller.signal },
        ).result;
        if (controller.signal.aborted || merged === null) return;
        current.current = null;
        const done: PathRunState = {
          status: 'done',
          progress: null,
          solutions: merged,
          task,
          error: null,
          elapsedMs: performance.now() - start,
          workers: parts,
        };
        lastRun = done;
        setState(done);
      } catch (e) {
        if (controller.signal.aborted) return;
        current.current = null;
        setState((s) => ({
          ...s,
          status: 'failed',
          progress: null,
          error: e instanceof Error ? e.message : String(e),
        }));
      } finally {
        if (abort.current === controller) abort.current = null;
      }
    },
    [createPool],
  );

  return { ...state, run, cancel };
}
