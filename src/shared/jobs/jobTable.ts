/**
 * A job table: what a feature can ask a worker to do. The table (contract) is light and lives in the feature:
 * each job's name, its params and result types, and how the client treats its calls. The handlers (the heavy
 * code) are a separate object typed by the table, registered by the worker entry and loaded by the main-thread
 * fallback on demand, so the client's bundle carries the contract only.
 */

/** How a channel treats a new call while one is in flight: 'latest' (one in flight, one waiting) or 'queue' (all sent). */
export type ChannelMode = 'latest' | 'queue';

/** What happens to a latest channel's call in flight when a newer one comes: still delivered, or dropped (and cancelled). */
export type InFlightPolicy = 'deliver' | 'drop';

/** How the client treats the calls of one job. */
export interface JobPolicy<P> {
  /**
   * 'latest' (default): each channel has at most one call in flight and one waiting; a newer call supersedes the
   * waiting one (it resolves to null at once), so a dragged slider builds no backlog and the last value is always
   * solved. 'queue': every call is sent at once and each is answered (a pipeline, e.g. GIF frames).
   */
  mode?: ChannelMode;
  /** Latest channels only (default 'drop'): 'deliver' keeps the call in flight when a newer one waits. */
  inFlight?: InFlightPolicy;
  /** Watchdog budget of one call (ms); for a job that reports progress, the time allowed between two reports. */
  budgetMs?(params: P): number;
  /** Buffers of the params moved (not copied) to the worker; a call that transferred them cannot be resent. */
  transfer?(params: P): Transferable[];
}

/** One job of a table: its policy, and (type-level only) what it is asked and what it answers. */
export interface JobSpec<P extends object, R> extends JobPolicy<P> {
  /** Never set: carries the params and result types so a client can infer them from the table. */
  readonly types?: { params: P; result: R };
}

/** Any job spec: the constraint of a table's entries. */
export type AnyJobSpec = JobSpec<object, unknown>;

/** A table of jobs by name: the constraint `T extends JobTable<T>` accepts any object of job specs. */
export type JobTable<T> = { readonly [K in keyof T]: AnyJobSpec };

/** The job names of a table. */
export type JobName<T> = keyof T & string;

/** What a job is asked. */
export type JobParams<S> = S extends JobSpec<infer P, unknown> ? P : never;

/** What a job answers (awaited; null when the call was superseded or cancelled). */
export type JobResult<S> = S extends JobSpec<object, infer R> ? R : never;

/** What a running job can do besides answering: report progress, and see its cancel (the signal aborts). */
export interface JobContext {
  /** Aborted when the client cancels or supersedes the call, or the main-thread stand-in is terminated. */
  signal: AbortSignal;
  /** Reports progress: fraction in [0, 1] and the stage being computed; also keeps the watchdog quiet. */
  progress(fraction: number, stage: string): void;
}

/** The code of one job: params in, result (or its promise) out; throws for bad input (the worker answers an error). */
export type JobHandler<P, R> = (params: P, context: JobContext) => R | Promise<R>;

/** The handlers of a table: one per job, with the job's params and result types. */
export type JobHandlers<T> = { readonly [K in keyof T]: JobHandler<JobParams<T[K]>, JobResult<T[K]>> };

/** Any handler table, as the worker side serves it (names checked at run time). */
export type AnyJobHandlers = Readonly<Record<string, JobHandler<never, unknown>>>;

/** A job spec with params P and result R: `job<CycleParams, CycleResponse>({ inFlight: 'deliver' })`. */
export function job<P extends object, R>(policy: JobPolicy<P> = {}): JobSpec<P, R> {
  return { ...policy };
}

/** Two tables (specs or handlers) as one; throws when a name is in both (a worker serves each name once). */
export function combineJobs<A extends object, B extends object>(a: A, b: B): A & B {
  for (const name of Object.keys(b)) if (name in a) throw new Error(`job ${JSON.stringify(name)} is in both tables`);
  return { ...a, ...b };
}
