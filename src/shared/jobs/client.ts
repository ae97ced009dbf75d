import type { LabResult } from '../../study/workPrecision';
import { createMainThreadWorker } from './mainThread';
import type { WatchdogOptions } from './watchdog';
import { DEFAULT_WATCHDOG, armTimer, budgetMs } from './watchdog';
import type {
  CycleParams,
  CycleResponse,
  ErrorResponse,
  LabParams,
  ParamsOf,
  PointParams,
  PointResponse,
  ResultOf,
  SolverMethod,
  SolverRequest,
  SolverResponse,
  TableParams,
  TableResponse,
} from './protocol';

/** The part of a Worker the client uses (a real Worker, the main-thread stand-in, or a fake in tests). */
export interface WorkerLike {
  postMessage(message: SolverRequest, transfer?: Transferable[]): void;
  addEventListener(type: 'message' | 'error' | 'messageerror', listener: (event: Event) => void): void;
  terminate(): void;
}

/** Where requests are solved: the first worker, a restarted one, or the main thread. */
export type SolverMode = 'starting' | 'worker' | 'restarted' | 'main-thread';

/** Why the client left a worker: none ever answered or could start ('unavailable'), or one stopped ('stopped'). */
export type SolverModeReason = 'unavailable' | 'stopped';

/** Options of SolverClient: worker factories (default: the module worker, then the main thread) and the watchdog. */
export interface SolverClientOptions {
  createWorker?: () => WorkerLike;
  createFallback?: () => WorkerLike;
  watchdog?: Partial<WatchdogOptions>;
  /** Called when the mode changes after the first answer (worker) or a failure, with why and a detail for the console. */
  onModeChange?: (mode: SolverMode, reason: SolverModeReason | null, detail: string) => void;
}

/** A running lab study: its result (null when cancelled or superseded) and a way to cancel it. */
export interface LabRun {
  result: Promise<LabResult | null>;
  cancel: () => void;
}

/** Thrown into a call's promise when the API answered with an error. */
export class SolverError extends Error {
  constructor(readonly response: ErrorResponse) {
    super(response.message);
    this.name = 'SolverError';
  }
}

/** Makes the module worker that serves the API object. */
export function createSolverWorker(): WorkerLike {
  const worker = new Worker(new URL('../../workers/solver.worker.ts', import.meta.url), { type: 'module' });
  return worker as unknown as WorkerLike;
}

interface Call {
  id: number;
  type: SolverMethod;
  params: unknown;
  channel: string;
  budgetMs: number;
  promise: Promise<unknown>;
  resolve: (value: unknown) => void;
  reject: (error: Error) => void;
  onProgress?: (fraction: number, stage: string) => void;
  stale: boolean;
}

/**
 * Main-thread side of the solver API. Each channel (cycle, point, table, lab) has at most one call in
 * flight and one queued; a newer call supersedes the queued one (it resolves to null at once), so a
 * dragged slider builds no backlog and the last value is always solved. The call in flight of a cycle or
 * point channel still resolves with its answer: it is newer than what the views show, and dropping it
 * would leave a drag with no plot update until the worker keeps up. A table or lab call in flight is
 * superseded too (an export must not download twice; a superseded lab is cancelled). A watchdog
 * gives the worker the summed budgets of what it holds, restarted at every message: when it misses
 * that, errors or cannot be decoded, the client restarts it once, then serves the same API on the
 * main thread, resending what was in flight.
 */
export class SolverClient {
  private worker: WorkerLike | null = null;
  private readonly inFlight = new Map<string, Call>();
  private readonly queued = new Map<string, Call>();
  private readonly watchdog: WatchdogOptions;
  private nextId = 1;
  private restarts = 0;
  private heard = false;
  private everHeard = false;
  private disarm = (): void => undefined;
  private disposed = false;
  private modeValue: SolverMode = 'starting';
  private reasonValue: SolverModeReason | null = null;

  constructor(private readonly options: SolverClientOptions = {}) {
    this.watchdog = { ...DEFAULT_WATCHDOG, ...options.watchdog };
    this.start(options.createWorker ?? createSolverWorker, 'starting', null, '');
  }

  /** Where calls are solved now. */
  get mode(): SolverMode {
    return this.modeValue;
  }

  /** Why the client is not on its first worker (null while it is). */
  get reason(): SolverModeReason | null {
    return this.reasonValue;
  }

  /** The cycle at view resolution; null when superseded. Rejects with SolverError. */
  cycle(params: CycleParams): Promise<CycleResponse | null> {
    return this.call('cycle', params, 'cycle').promise as Promise<CycleResponse | null>;
  }

  /** One pose and its NR runs; null when superseded. Rejects with SolverError. */
  point(params: PointParams): Promise<PointResponse | null> {
    return this.call('point', params, 'point').promise as Promise<PointResponse | null>;
  }

  /** The whole samples + 1 table of one branch; latest wins per channel (use one per consumer). */
  table(params: TableParams, channel = 'table'): Promise<TableResponse | null> {
    return this.call('table', params, channel).promise as Promise<TableResponse | null>;
  }

  /** Starts the lab study; onProgress gets the fraction done and the stage; a newer study or cancel() supersedes it. */
  lab(params: LabParams, onProgress: (fraction: number, stage: string) => void): LabRun {
    const call = this.call('lab', params, 'lab', onProgress);
    return { result: call.promise as Promise<ResultOf<'lab'>>, cancel: () => this.supersede(call) };
  }

  /** Stops the worker; every pending call resolves to null. */
  dispose(): void {
    this.disposed = true;
    this.disarm();
    this.worker?.terminate();
    this.worker = null;
    for (const c of [...this.inFlight.values(), ...this.queued.values()]) c.resolve(null);
    this.inFlight.clear();
    this.queued.clear();
  }

  /** Methods whose call in flight still delivers when a newer one is queued (see the class comment). */
  private static readonly PROGRESSIVE: ReadonlySet<SolverMethod> = new Set<SolverMethod>(['cycle', 'point']);

  private call<M extends SolverMethod>(type: M, params: ParamsOf<M>, channel: string, onProgress?: Call['onProgress']) {
    const call = { id: this.nextId++, type, params, channel, onProgress, stale: false } as Call;
    call.budgetMs = budgetMs(type, params, this.watchdog);
    call.promise = new Promise((resolve, reject) => Object.assign(call, { resolve, reject }));
    const busy = this.inFlight.get(channel);
    if (this.disposed) call.resolve(null);
    else if (!busy) this.send(call);
    else {
      const old = this.queued.get(channel);
      if (old) this.supersede(old);
      if (!SolverClient.PROGRESSIVE.has(busy.type)) this.supersede(busy);
      this.queued.set(channel, call);
    }
    return call;
  }

  private supersede(call: Call): void {
    if (call.stale) return;
    call.stale = true;
    call.resolve(null);
    if (this.queued.get(call.channel) === call) this.queued.delete(call.channel);
    else if (call.type === 'lab' && this.inFlight.get(call.channel) === call)
      this.worker?.postMessage({ type: 'cancel', id: call.id });
  }

  private send(call: Call): void {
    this.inFlight.set(call.channel, call);
    this.worker?.postMessage({ type: call.type, id: call.id, params: call.params } as SolverRequest);
    this.arm();
  }

  private onMessage(from: WorkerLike, m: SolverResponse): void {
    if (from !== this.worker || this.disposed) return;
    this.heard = this.everHeard = true;
    if (this.modeValue === 'starting') this.setMode('worker', null, '');
    const call = [...this.inFlight.values()].find((c) => c.id === m.id);
    if (!call) {
      // An answer to a call this worker no longer holds (resent after a restart): nothing to do.
    } else if (m.type === 'progress') {
      if (!call.stale) call.onProgress?.(m.fraction, m.stage);
    } else {
      this.inFlight.delete(call.channel);
      if (m.type === 'error') call.reject(new SolverError(m));
      else call.resolve(m.value);
      const next = this.queued.get(call.channel);
      this.queued.delete(call.channel);
      if (next) this.send(next);
    }
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
    if (this.disposed || this.modeValue === 'main-thread') return;
    const reason = this.everHeard ? 'stopped' : 'unavailable';
    if (this.restarts++ === 0) this.start(this.options.createWorker ?? createSolverWorker, 'restarted', reason, detail);
    else this.start(this.options.createFallback ?? createMainThreadWorker, 'main-thread', reason, detail);
    // Resend what the lost worker held: the newest call of each channel (an older one in flight gives way).
    for (const call of [...this.inFlight.values()]) {
      this.inFlight.delete(call.channel);
      const newer = this.queued.get(call.channel);
      this.queued.delete(call.channel);
      if (newer) this.supersede(call);
      const next = newer ?? (call.stale ? null : call);
      if (next) this.send(next);
    }
  }

  private start(create: () => WorkerLike, mode: SolverMode, reason: SolverModeReason | null, detail: string): void {
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
      this.restarts = 1; // It would not start again either: straight to the main thread.
      return this.fail(`worker could not start: ${e instanceof Error ? e.message : String(e)}`);
    }
    this.worker = w;
    w.addEventListener('message', (e) => this.onMessage(w, (e as MessageEvent<SolverResponse>).data));
    w.addEventListener('error', (e) => {
      (e as ErrorEvent).preventDefault?.();
      if (w === this.worker) this.fail(`worker error: ${(e as ErrorEvent).message || 'the script did not load'}`);
    });
    w.addEventListener('messageerror', () => w === this.worker && this.fail('a worker message could not be decoded'));
  }

  private setMode(mode: SolverMode, reason: SolverModeReason | null, detail: string): void {
    this.modeValue = mode;
    this.reasonValue = reason;
    this.options.onModeChange?.(mode, reason, detail);
  }
}
