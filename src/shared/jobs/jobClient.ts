import type { AnyJobRequest, AnyJobResponse, ErrorResponse } from './jobProtocol';
import type { ChannelMode, InFlightPolicy, JobName, JobParams, JobResult, JobTable } from './jobTable';
import type { WatchdogOptions } from './watchdog';
import { DEFAULT_WATCHDOG, armTimer } from './watchdog';

/** The part of a Worker the client uses (a real Worker, the main-thread stand-in, or a fake in tests). */
export interface WorkerLike {
  postMessage(message: AnyJobRequest, transfer?: Transferable[]): void;
  addEventListener(type: 'message' | 'error' | 'messageerror', listener: (event: Event) => void): void;
  terminate(): void;
}

/** Where calls run: the first worker, a restarted one, the main thread, or nowhere (no fallback was given). */
export type JobClientMode = 'starting' | 'worker' | 'restarted' | 'main-thread' | 'failed';

/** Why the client left a worker: none ever answered or could start ('unavailable'), or one stopped ('stopped'). */
export type JobClientModeReason = 'unavailable' | 'stopped';

/** Options of a JobClient: the worker, what replaces it, how often it is restarted and the watchdog. */
export interface JobClientOptions {
  /** Makes the worker that serves the table's handlers; a throw counts as a worker that cannot start. */
  createWorker: () => WorkerLike;
  /** Serves the same handlers where no worker runs (createMainThreadWorker); without it the client fails. */
  createFallback?: () => WorkerLike;
  /** Workers started again after one stops (default 1) before the fallback takes over. */
  restarts?: number;
  watchdog?: Partial<WatchdogOptions>;
  /** Called when the mode changes after the first answer (worker) or a failure, with why and a detail for the console. */
  onModeChange?: (mode: JobClientMode, reason: JobClientModeReason | null, detail: string) => void;
}

/** Options of one call. */
export interface RunOptions {
  /** The latest-wins channel (default: the job's name); use one per consumer of the same job. */
  channel?: string;
  /** Progress of a long job: fraction in [0, 1] and the stage (not called once the call is stale). */
  onProgress?: (fraction: number, stage: string) => void;
  /** Aborting it cancels the call, as cancel() does. */
  signal?: AbortSignal;
}

/** A call: its result (null when superseded, cancelled or disposed; rejects with JobError) and its cancel. */
export interface JobRun<R> {
  readonly id: number;
  readonly result: Promise<R | null>;
  /** Resolves the result to null at once; a call in the worker is told to stop (its signal aborts). */
  cancel(): void;
}

/** What a feature needs of a client: running the jobs of its table (a client of a larger table will do). */
export interface JobRunner<T extends JobTable<T>> {
  run<K extends JobName<T>>(job: K, params: JobParams<T[K]>, options?: RunOptions): JobRun<JobResult<T[K]>>;
}

/** Thrown into a call's result when the job answered with an error, or the call could not reach any worker. */
export class JobError extends Error {
  constructor(readonly response: ErrorResponse) {
    super(response.message);
    this.name = 'JobError';
  }
}

interface Call {
  id: number;
  job: string;
  params: object;
  mode: ChannelMode;
  inFlight: InFlightPolicy;
  channel: string;
  budgetMs: number;
  transfer: Transferable[];
  promise: Promise<unknown>;
  resolve: (value: unknown) => void;
  reject: (error: Error) => void;
  onProgress?: (fraction: number, stage: string) => void;
  stale: boolean;
}

/**
 * Main-thread side of a job table, over one worker. A call follows its job's policy: on a latest channel at
 * most one call is in flight and one waits; a newer call supersedes the waiting one (it resolves to null at
 * once), and the one in flight too unless its job delivers in flight answers (a superseded call in flight is
 * told to cancel). A queue job's calls are all sent and all answered. A watchdog gives the worker the summed
 * budgets of what it holds, restarted at every message (so progress keeps a long job alive): when it misses
 * that, errors or cannot be decoded, the client starts a new worker (options.restarts times), then the
 * fallback, resending what was in flight: the newest call of each latest channel and every queued call.
 */
export class JobClient<T extends JobTable<T>> implements JobRunner<T> {
  private worker: WorkerLike | null = null;
  /** Every call sent to the current worker and not answered, by id, in the order sent. */
  private readonly inFlight = new Map<number, Call>();
  /** Each latest channel's call in flight and its waiting call. */
  private readonly busy = new Map<string, Call>();
  private readonly queued = new Map<string, Call>();
  private readonly watchdog: WatchdogOptions;
  private readonly maxRestarts: number;
  private nextId = 1;
  private restarts = 0;
  private heard = false;
  private everHeard = false;
  private disarm = (): void => undefined;
  private disposed = false;
  private modeValue: JobClientMode = 'starting';
  private reasonValue: JobClientModeReason | null = null;
  private failure: string | null = null;

  constructor(
    private readonly table: T,
    private readonly options: JobClientOptions,
  ) {
    this.watchdog = { ...DEFAULT_WATCHDOG, ...options.watchdog };
    this.maxRestarts = options.restarts ?? 1;
    this.start(options.createWorker, 'starting', null, '');
  }

  /** Where calls run now. */
  get mode(): JobClientMode {
    return this.modeValue;
  }

  /** Why the client is not on its first worker (null while it is). */
  get reason(): JobClientModeReason | null {
    return this.reasonValue;
  }

  /** Runs a job of the table with the job's policy; see the class comment. */
  run<K extends JobName<T>>(job: K, params: JobParams<T[K]>, options: RunOptions = {}): JobRun<JobResult<T[K]>> {
    const spec = this.table[job];
    let resolve: Call['resolve'] = () => undefined;
    let reject: Call['reject'] = () => undefined;
    const promise = new Promise<unknown>((res, rej) => {
      resolve = res;
      reject = rej;
    });
    const call: Call = {
      id: this.nextId++,
      job,
      params,
      mode: spec.mode ?? 'latest',
      inFlight: spec.inFlight ?? 'drop',
      channel: options.channel ?? job,
      budgetMs: spec.budgetMs?.(params) ?? this.watchdog.callMs,
      transfer: spec.transfer?.(params) ?? [],
      promise,
      resolve,
      reject,
      onProgress: options.onProgress,
      stale: false,
    };
    const busy = this.busy.get(call.channel);
    if (this.disposed) call.resolve(null);
    else if (this.failure !== null) call.reject(this.channelError(call, this.failure));
    else if (call.mode === 'queue' || !busy) this.send(call);
    else {
      const old = this.queued.get(call.channel);
      if (old) this.supersede(old);
      if (busy.inFlight === 'drop') this.supersede(busy);
      this.queued.set(call.channel, call);
    }
    const { signal } = options;
    if (signal?.aborted) this.supersede(call);
    else signal?.addEventListener('abort', () => this.supersede(call), { once: true });
    return {
      id: call.id,
      result: call.promise as Promise<JobResult<T[K]> | null>,
      cancel: () => this.supersede(call),
    };
  }

  /** Stops the worker; every pending call resolves to null, and so does every later one. */
  dispose(): void {
    this.disposed = true;
    this.disarm();
    this.worker?.terminate();
    this.worker = null;
    for (const c of [...this.inFlight.values(), ...this.queued.values()]) c.resolve(null);
    this.inFlight.clear();
    this.busy.clear();
    this.queued.clear();
  }

  private supersede(call: Call): void {
    if (call.stale) return;
    call.stale = true;
    call.resolve(null);
    if (this.queued.get(call.channel) === call) this.queued.delete(call.channel);
    else if (this.inFlight.get(call.id) === call) this.post({ type: 'cancel', id: call.id });
  }

  private send(call: Call): void {
    this.inFlight.set(call.id, call);
    if (call.mode === 'latest') this.busy.set(call.channel, call);
    const sent = this.post({ type: 'run', id: call.id, job: call.job, params: call.params }, call.transfer);
    if (sent !== true) this.settle(call, { type: 'error', id: call.id, job: call.job, message: sent });
    else this.arm();
  }

  /** Posts to the current worker; true, or why it could not (params that cannot be cloned, a detached buffer). */
  private post(message: AnyJobRequest, transfer: Transferable[] = []): true | string {
    try {
      this.worker?.postMessage(message, transfer);
      return true;
    } catch (e) {
      return `${message.type === 'run' ? message.job : 'cancel'} could not be sent: ${e instanceof Error ? e.message : String(e)}`;
    }
  }

  /** Ends a call with its answer and sends its channel's waiting call. */
  private settle(call: Call, m: AnyJobResponse): void {
    this.inFlight.delete(call.id);
    let next: Call | undefined;
    if (this.busy.get(call.channel) === call) {
      this.busy.delete(call.channel);
      next = this.queued.get(call.channel);
      this.queued.delete(call.channel);
    }
    if (m.type === 'error') call.reject(new JobError(m));
    else call.resolve(m.type === 'result' ? m.value : null);
    if (next) this.send(next);
  }

  private onMessage(from: WorkerLike, m: AnyJobResponse): void {
    if (from !== this.worker || this.disposed) return;
    this.heard = this.everHeard = true;
    if (this.modeValue === 'starting') this.setMode('worker', null, '');
    const call = this.inFlight.get(m.id);
    if (!call) {
      // An answer to a call this worker no longer holds (resent after a restart): nothing to do.
    } else if (m.type === 'progress') {
      if (!call.stale) call.onProgress?.(m.fraction, m.stage);
    } else this.settle(call, m);
    this.arm();
  }

  private arm(): void {
    this.disarm();
    if (this.modeValue === 'main-thread' || this.inFlight.size === 0) return;
    let ms = this.heard ? 0 : this.watchdog.startMs;
    for (const c of this.inFlight.values()) ms += c.budgetMs;
    this.disarm = armTimer(ms, () => this.fail(`no answer within ${Math.round(ms)} ms`));
  }

  private fail(detail: string): void {
    if (this.disposed || this.modeValue === 'main-thread' || this.failure !== null) return;
    this.disarm();
    // Taken before starting the next worker: a start that fails recurses here and must not send them twice.
    const held = [...this.inFlight.values()];
    this.inFlight.clear();
    this.busy.clear();
    const reason = this.everHeard ? 'stopped' : 'unavailable';
    if (this.restarts < this.maxRestarts) {
      this.restarts++;
      this.start(this.options.createWorker, 'restarted', reason, detail);
    } else if (this.options.createFallback) this.start(this.options.createFallback, 'main-thread', reason, detail);
    else return this.giveUp(held, reason, detail);
    if (this.failure !== null) return;
    // Resend what the lost worker held: every queue call, and the newest call of each latest channel (an older
    // one in flight gives way to a waiting one).
    for (const call of held) {
      if (call.mode === 'queue') {
        if (!call.stale) this.send(call);
        continue;
      }
      const newer = this.queued.get(call.channel);
      this.queued.delete(call.channel);
      if (newer) this.supersede(call);
      const next = newer ?? (call.stale ? null : call);
      if (next) this.send(next);
    }
  }

  /** No worker and no fallback: every pending call and every later one rejects with the cause. */
  private giveUp(held: Call[], reason: JobClientModeReason, detail: string): void {
    this.failure = detail;
    try {
      this.worker?.terminate();
    } catch {
      // Dropped either way.
    }
    this.worker = null;
    this.setMode('failed', reason, detail);
    for (const c of [...held, ...this.queued.values()]) c.reject(this.channelError(c, detail));
    this.queued.clear();
  }

  private channelError(call: Call, detail: string): JobError {
    return new JobError({
      type: 'error',
      id: call.id,
      job: call.job,
      message: `no worker can run ${call.job}: ${detail}`,
    });
  }

  private start(create: () => WorkerLike, mode: JobClientMode, reason: JobClientModeReason | null, detail: string) {
    try {
      this.worker?.terminate();
    } catch {
      // A worker that never started may refuse to terminate; it is dropped either way.
    }
    this.worker = null;
    this.heard = false;
    if (mode !== 'starting') this.setMode(mode, reason, detail);
    let w: WorkerLike;
    try {
      w = create();
    } catch (e) {
      if (mode === 'main-thread') throw e;
      this.restarts = this.maxRestarts; // It would not start again either: straight to the fallback.
      return this.fail(`worker could not start: ${e instanceof Error ? e.message : String(e)}`);
    }
    this.worker = w;
    w.addEventListener('message', (e) => this.onMessage(w, (e as MessageEvent<AnyJobResponse>).data));
    w.addEventListener('error', (e) => {
      (e as ErrorEvent).preventDefault?.();
      if (w === this.worker) this.fail(`worker error: ${(e as ErrorEvent).message || 'the script did not load'}`);
    });
    w.addEventListener('messageerror', () => w === this.worker && this.fail('a worker message could not be decoded'));
  }

  private setMode(mode: JobClientMode, reason: JobClientModeReason | null, detail: string): void {
    this.modeValue = mode;
    this.reasonValue = reason;
    this.options.onModeChange?.(mode, reason, detail);
  }
}
