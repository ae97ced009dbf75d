import type { JobClientOptions, WorkerLike } from '../shared/jobs/jobClient';
import { JobClient } from '../shared/jobs/jobClient';
import { combineJobs } from '../shared/jobs/jobTable';
import { createMainThreadWorker } from '../shared/jobs/mainThread';
import type { WorkerPool } from '../shared/jobs/workerPool';
import { createWorkerPool } from '../shared/jobs/workerPool';
import { labJobs } from '../features/lab/jobs';
import { simulatorJobs } from '../features/simulator/jobs';
import { synthesisJobs } from '../features/synthesis/jobs';
import { mechanismJobs } from '../features/mechanism/jobs';

/** Every job of the solver worker: the simulator's, the lab's and synthesis's tables (handlers: solverHandlers.ts). */
export const solverJobs = combineJobs(combineJobs(combineJobs(simulatorJobs, labJobs), synthesisJobs), mechanismJobs);

/** The solver worker's job table. */
export type SolverJobs = typeof solverJobs;

/** The app's one solver client: the simulator's and the lab's jobs over the solver worker. */
export type SolverClient = JobClient<SolverJobs>;

/** Starts the module worker that serves solverHandlers (matched by scripts/viteInlineWorker.ts: keep it as is). */
function startSolverWorker(): WorkerLike {
  const worker = new Worker(new URL('./solver.worker.ts', import.meta.url), { type: 'module' });
  return worker as unknown as WorkerLike;
}

/** A worker started before the page's first render, waiting for the first client, and whether it already failed. */
let prestarted: { worker: WorkerLike; failed: boolean } | null = null;

/**
 * Starts the solver worker now, before the page renders: on a slow phone its script loads and compiles while React
 * renders the first frame, instead of after it (about half a second of the first load at 4x CPU, bench:ui). The
 * first createSolverWorker takes it. Where a worker cannot start, nothing happens and the client falls back later.
 */
export function prestartSolverWorker(): void {
  if (prestarted || typeof Worker === 'undefined') return;
  try {
    const entry = { worker: startSolverWorker(), failed: false };
    // An error before a client listens (a script that cannot load) would be lost: note it, so the client starts afresh.
    entry.worker.addEventListener('error', () => (entry.failed = true));
    prestarted = entry;
  } catch {
    prestarted = null;
  }
}

/** The solver worker for a client: the one prestartSolverWorker started, if it is waiting and sound, else a new one. */
export function createSolverWorker(): WorkerLike {
  const early = prestarted;
  prestarted = null;
  if (early && !early.failed) return early.worker;
  early?.worker.terminate();
  return startSolverWorker();
}

/** Serves the same handlers on the main thread, loaded on demand so the solver stays out of the main bundle. */
export function createSolverFallback(): WorkerLike {
  return createMainThreadWorker(() => import('./solverHandlers').then((m) => m.solverHandlers));
}

/**
 * The solver client: the module worker, restarted once when it stops, then the main thread (options override
 * the worker, the fallback, the watchdog and the mode callback, for tests and the status line).
 */
export function createSolverClient(options: Partial<JobClientOptions> = {}): SolverClient {
  return new JobClient(solverJobs, {
    createWorker: createSolverWorker,
    createFallback: createSolverFallback,
    restarts: 1,
    ...options,
  });
}

/**
 * A pool of size solver workers (default: cores − 1, at least 1), each a client of its own new worker with the
 * usual restart and main-thread fallback: the synthesis page runs the parts of a path synthesis on it.
 */
export function createSolverPool(size?: number): WorkerPool<SolverJobs> {
  return createWorkerPool((): SolverClient => createSolverClient({ createWorker: startSolverWorker }), size);
}
