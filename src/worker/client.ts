import type { ComputeResult } from './compute';
import type { LabResult } from '../lab/workPrecision';
import type {
  CycleRequest,
  CycleResponse,
  ErrorResponse,
  LabRequest,
  PointRequest,
  PointResponse,
  SolverRequest,
  SolverResponse,
} from './protocol';

/** What a cycle or point request carries besides its type and id. */
export type CycleParams = Omit<CycleRequest, 'type' | 'id'>;
export type PointParams = Omit<PointRequest, 'type' | 'id'>;
export type LabParams = Omit<LabRequest, 'type' | 'id'>;

/** A running lab study: its result (null when cancelled) and a way to cancel it. */
export interface LabRun {
  result: Promise<LabResult | null>;
  cancel: () => void;
}

interface LabPending {
  request: LabRequest;
  resolve: (r: LabResult | null) => void;
  reject: (e: Error) => void;
  onProgress: (fraction: number, stage: string) => void;
  cancelled: boolean;
}

/** The part of a Worker the client uses (a real Worker, or a fake in tests). */
export interface WorkerLike {
  postMessage(message: SolverRequest, transfer?: Transferable[]): void;
  addEventListener(type: 'message' | 'error' | 'messageerror', listener: (event: Event) => void): void;
  terminate(): void;
}

/** Where requests are solved: a Web Worker, or the main thread when no worker could start. */
export type SolverMode = 'starting' | 'worker' | 'main-thread';

/** Options of SolverClient: a worker factory (default: the module worker) and timing. */
export interface SolverClientOptions {
  /** Makes the worker; may throw (sandboxed iframes, no Worker). Default: createSolverWorker. */
  createWorker?: () => WorkerLike;
  /** Milliseconds to wait for the worker's first answer before solving on the main thread; default 4000. */
  startTimeoutMs?: number;
  /** Called once when the client falls back to the main thread, with the reason. */
  onModeChange?: (mode: SolverMode, reason?: string) => void;
}

type Channel = 'cycle' | 'point';
type ResponseOf<C extends Channel> = C extends 'cycle' ? CycleResponse : PointResponse;

interface Pending {
  request: SolverRequest;
  resolve: (r: SolverResponse | null) => void;
}

interface ChannelState {
  inFlight: Pending | null;
  queued: Pending | null;
}

/** Makes the module worker that owns every solve. */
export function createSolverWorker(): WorkerLike {
  return new Worker(new URL('./solver.worker.ts', import.meta.url), { type: 'module' }) as unknown as WorkerLike;
}

/** Thrown into a promise when the worker answered a request with an ErrorResponse. */
export class SolverError extends Error {
  constructor(readonly response: ErrorResponse) {
    super(response.message);
    this.name = 'SolverError';
  }
}

/**
 * Main-thread side of the solver worker. Each channel (cycle, point) keeps at most one request in
 * flight and one queued: a new request replaces the queued one, whose promise resolves to null, so
 * dragging a slider never builds a backlog and the last value is always solved. Answers to anything
 * but the newest request of a channel resolve to null. When the worker cannot start, requests are
 * solved on the main thread by the same code (loaded on demand).
 */
export class SolverClient {
  private worker: WorkerLike | null = null;
  private nextId = 1;
  private latest: Record<Channel, number> = { cycle: 0, point: 0 };
  private channels: Record<Channel, ChannelState> = {
    cycle: { inFlight: null, queued: null },
    point: { inFlight: null, queued: null },
  };
  private modeValue: SolverMode = 'starting';
  private startTimer: ReturnType<typeof setTimeout> | null = null;
  private compute: Promise<(req: SolverRequest) => ComputeResult> | null = null;
  private labs = new Map<number, LabPending>();
  private disposed = false;
  private readonly options: SolverClientOptions;

  constructor(options: SolverClientOptions = {}) {
    this.options = options;
    const create = options.createWorker ?? createSolverWorker;
    try {
      const w = create();
      w.addEventListener('message', (e) => this.onMessage((e as MessageEvent<SolverResponse>).data));
      w.addEventListener('error', (e) => {
        (e as ErrorEvent).preventDefault?.();
        this.fallBack(`worker error: ${(e as ErrorEvent).message || 'could not load the worker script'}`);
      });
      w.addEventListener('messageerror', () => this.fallBack('worker message could not be decoded'));
      this.worker = w;
    } catch (e) {
      this.fallBack(`worker could not start: ${e instanceof Error ? e.message : String(e)}`);
    }
  }

  /** Where requests are being solved now. */
  get mode(): SolverMode {
    return this.modeValue;
  }

  /** Solves the cycle; resolves to null when a newer cycle request superseded this one. Rejects with SolverError. */
  requestCycle(params: CycleParams): Promise<CycleResponse | null> {
    return this.request('cycle', params);
  }

  /** Solves one pose; resolves to null when a newer point request superseded this one. Rejects with SolverError. */
  requestPoint(params: PointParams): Promise<PointResponse | null> {
    return this.request('point', params);
  }

  /**
   * Starts the solver lab's study (in the worker, or here when there is none); onProgress gets the
   * fraction done and the stage. cancel() makes the result resolve to null. Rejects with SolverError.
   */
  runLab(params: LabParams, onProgress: (fraction: number, stage: string) => void): LabRun {
    const id = this.nextId++;
    const request: LabRequest = { ...params, type: 'lab', id };
    let pending: LabPending | null = null;
    const result = new Promise<LabResult | null>((resolve, reject) => {
      pending = { request, resolve, reject, onProgress, cancelled: false };
    });
    const p = pending as unknown as LabPending;
    this.labs.set(id, p);
    if (this.disposed) p.resolve(null);
    else if (this.modeValue === 'main-thread' || !this.worker) this.labHere(p);
    else this.worker.postMessage(request);
    const cancel = () => {
      if (p.cancelled) return;
      p.cancelled = true;
      if (this.worker && this.modeValue !== 'main-thread') this.worker.postMessage({ type: 'cancel', id });
    };
    return { result, cancel };
  }

  /** Stops the worker; pending requests resolve to null. */
  dispose(): void {
    this.disposed = true;
    if (this.startTimer) clearTimeout(this.startTimer);
    this.worker?.terminate();
    this.worker = null;
    for (const lab of this.labs.values()) lab.resolve(null);
    this.labs.clear();
    for (const ch of Object.values(this.channels)) {
      ch.inFlight?.resolve(null);
      ch.queued?.resolve(null);
      ch.inFlight = null;
      ch.queued = null;
    }
  }

  private request<C extends Channel>(
    channel: C,
    params: C extends 'cycle' ? CycleParams : PointParams,
  ): Promise<ResponseOf<C> | null> {
    const id = this.nextId++;
    this.latest[channel] = id;
    const request = { ...params, type: channel, id } as SolverRequest;
    return new Promise<ResponseOf<C> | null>((resolve, reject) => {
      if (this.disposed) {
        resolve(null);
        return;
      }
      const pending: Pending = {
        request,
        resolve: (r) => {
          if (r && r.type === 'error') reject(new SolverError(r));
          else resolve(r as ResponseOf<C> | null);
        },
      };
      const ch = this.channels[channel];
      if (ch.inFlight) {
        ch.queued?.resolve(null);
        ch.queued = pending;
      } else {
        this.dispatch(channel, pending);
      }
    });
  }

  private dispatch(channel: Channel, pending: Pending): void {
    const ch = this.channels[channel];
    ch.inFlight = pending;
    if (this.modeValue === 'main-thread' || !this.worker) {
      this.solveHere(pending.request);
      return;
    }
    if (this.modeValue === 'starting' && !this.startTimer) {
      this.startTimer = setTimeout(
        () => this.fallBack('worker did not answer in time'),
        this.options.startTimeoutMs ?? 4000,
      );
    }
    try {
      this.worker.postMessage(pending.request);
    } catch (e) {
      this.fallBack(`postMessage failed: ${e instanceof Error ? e.message : String(e)}`);
    }
  }

  private onMessage(response: SolverResponse): void {
    if (this.disposed) return;
    if (this.modeValue === 'starting' && this.worker) {
      if (this.startTimer) clearTimeout(this.startTimer);
      this.startTimer = null;
      this.setMode('worker');
    }
    if (
      response.type === 'lab' ||
      response.type === 'lab-progress' ||
      (response.type === 'error' && response.requestType === 'lab')
    ) {
      this.onLabMessage(response);
      return;
    }
    if (response.type === 'error' && response.requestType === 'cancel') return;
    const channel = (response.type === 'error' ? response.requestType : response.type) as Channel;
    const ch = this.channels[channel];
    if (!ch.inFlight || ch.inFlight.request.id !== response.id) return;
    const done = ch.inFlight;
    ch.inFlight = null;
    done.resolve(response.id === this.latest[channel] ? response : null);
    const next = ch.queued;
    ch.queued = null;
    if (next) this.dispatch(channel, next);
  }

  private onLabMessage(response: SolverResponse): void {
    const lab = this.labs.get(response.id);
    if (!lab) return;
    if (response.type === 'lab-progress') {
      if (!lab.cancelled) lab.onProgress(response.fraction, response.stage);
      return;
    }
    this.labs.delete(response.id);
    if (response.type === 'error') lab.reject(new SolverError(response));
    else if (response.type === 'lab') lab.resolve(lab.cancelled ? null : response.result);
  }

  private labHere(lab: LabPending): void {
    void import('./labRunner').then(
      (m) =>
        m.runLabRequest(
          lab.request,
          (r) => this.onLabMessage(r),
          () => lab.cancelled,
        ),
      (e: unknown) => lab.reject(new Error(`lab failed to load: ${e instanceof Error ? e.message : String(e)}`)),
    );
  }

  private fallBack(reason: string): void {
    if (this.disposed || this.modeValue === 'main-thread') return;
    if (this.startTimer) clearTimeout(this.startTimer);
    this.startTimer = null;
    try {
      this.worker?.terminate();
    } catch {
      // A worker that never started may refuse to terminate; it is dropped either way.
    }
    this.worker = null;
    this.setMode('main-thread', reason);
    for (const ch of Object.values(this.channels)) {
      if (ch.inFlight) this.solveHere(ch.inFlight.request);
    }
    for (const lab of this.labs.values()) this.labHere(lab);
  }

  private setMode(mode: SolverMode, reason?: string): void {
    this.modeValue = mode;
    this.options.onModeChange?.(mode, reason);
  }

  private solveHere(request: SolverRequest): void {
    this.compute ??= import('./compute').then((m) => m.handleRequest);
    void this.compute.then(
      (handle) => {
        // Answer asynchronously, as the worker would, so latest-wins behaves the same.
        setTimeout(() => {
          if (this.disposed) return;
          const channel = request.type as Channel;
          if (this.channels[channel].inFlight?.request.id !== request.id) return;
          this.onMessage(handle(request).response);
        }, 0);
      },
      (e: unknown) => {
        const message = `main-thread solver failed to load: ${e instanceof Error ? e.message : String(e)}`;
        this.onMessage({ type: 'error', id: request.id, requestType: request.type, message });
      },
    );
  }
}
