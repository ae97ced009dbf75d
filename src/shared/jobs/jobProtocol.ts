import type { JobName, JobParams, JobResult } from './jobTable';

/** Run a job: job is its name in the table, params its only argument. */
export type RunRequest<T> = {
  [K in JobName<T>]: { type: 'run'; id: number; job: K; params: JobParams<T[K]> };
}[JobName<T>];

/** Cancel the call with this id: its handler's signal aborts (a call no longer running ignores it). */
export interface CancelRequest {
  type: 'cancel';
  id: number;
}

/** Every message the client sends to a worker serving table T. */
export type JobRequest<T> = RunRequest<T> | CancelRequest;

/** A job's answer: value is what its handler returned (its buffers transferred). */
export type ResultResponse<T> = {
  [K in JobName<T>]: { type: 'result'; id: number; job: K; value: JobResult<T[K]> };
}[JobName<T>];

/** Progress of a long call: fraction in [0, 1] and the stage being computed. */
export interface ProgressResponse {
  type: 'progress';
  id: number;
  fraction: number;
  stage: string;
}

/** A call failed: the message names what was wrong; job is the request's job as received. */
export interface ErrorResponse {
  type: 'error';
  /** The request's id, or -1 when it had none. */
  id: number;
  /** The request's job name ('unknown' when it had none), never a guess. */
  job: string;
  message: string;
}

/** Every message a worker serving table T sends: exactly one result or error per run, progress in between. */
export type JobResponse<T> = ResultResponse<T> | ProgressResponse | ErrorResponse;

/** A response as the worker side sends it, before the client reads it by its table. */
export type AnyJobResponse =
  { type: 'result'; id: number; job: string; value: unknown } | ProgressResponse | ErrorResponse;

/** A request as a worker receives it, before its job name is checked against the table served. */
export type AnyJobRequest = { type: 'run'; id: number; job: string; params: object } | CancelRequest;
