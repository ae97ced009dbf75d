import type { JobClient, JobRun, JobRunner, RunOptions } from './jobClient';
import type { JobName, JobParams, JobResult, JobTable } from './jobTable';

/** Workers for a pool on this device: all cores but the one the page runs on, at least one. */
export function defaultPoolSize(): number {
  const cores = typeof navigator === 'undefined' ? 2 : (navigator.hardwareConcurrency ?? 2);
  return Math.max(1, cores - 1);
}

/** A pool of job clients, each over its own worker: a long job split in parts runs on all of them at once. */
export interface WorkerPool<T extends JobTable<T>> extends JobRunner<T> {
  readonly size: number;
  /** Stops every worker; pending calls resolve to null. */
  dispose(): void;
}

/**
 * A pool of `size` clients made by factory(index) (each with its own watchdog, restart and fallback). run()
 * sends a call to the client with the fewest calls pending, so the parts of a split job spread over the
 * workers; it is meant for queue jobs (a latest channel is latest-wins within one client only). A job split
 * in parts is `Promise.all(parts.map((p) => pool.run('job', p, { onProgress, signal }).result))`; aborting
 * the one signal cancels every part.
 */
export function createWorkerPool<T extends JobTable<T>>(
  factory: (index: number) => JobClient<T>,
  size: number = defaultPoolSize(),
): WorkerPool<T> {
  if (!Number.isInteger(size) || size < 1) throw new Error(`size must be a whole number of workers >= 1, got ${size}`);
  const clients = Array.from({ length: size }, (_, i) => factory(i));
  const pending = clients.map(() => 0);
  return {
    size,
    run<K extends JobName<T>>(job: K, params: JobParams<T[K]>, options?: RunOptions): JobRun<JobResult<T[K]>> {
      let k = 0;
      for (let i = 1; i < size; i++) if (pending[i] < pending[k]) k = i;
      pending[k]++;
      const run = clients[k].run(job, params, options);
      const done = () => pending[k]--;
      run.result.then(done, done);
      return run;
    },
    dispose() {
      for (const c of clients) c.dispose();
    },
  };
}
