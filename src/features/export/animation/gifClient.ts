import type { GifWorkerRequest, GifWorkerResponse } from './gifProtocol';

/** Thrown into pending requests when the channel itself died: the worker could not load, or it crashed. */
export class GifChannelError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'GifChannelError';
  }
}

/** Where a GIF is encoded. */
export type GifEncoderPlace = 'worker' | 'main-thread';

/** The part of a Worker the client uses (a fake in tests). */
export interface GifWorkerLike {
  postMessage(message: GifWorkerRequest, transfer: Transferable[]): void;
  addEventListener(type: 'message' | 'error' | 'messageerror', listener: (e: Event) => void): void;
  terminate(): void;
}

type Pending = { resolve: (r: GifWorkerResponse) => void; reject: (e: Error) => void };

/**
 * Main-thread side of one GIF encode. Requests are answered exactly once and in order (the session's
 * promise), so answers are matched first in, first out. close() ends the encode (terminates the worker)
 * and rejects whatever is still pending.
 */
export class GifClient {
  private pending: Pending[] = [];
  private closed = false;
  private send: (req: GifWorkerRequest, transfer: Transferable[]) => void = () => undefined;
  private stop: () => void = () => undefined;

  private constructor(readonly place: GifEncoderPlace) {}

  /** A client over a module worker running gif.worker.ts. */
  static overWorker(worker: GifWorkerLike): GifClient {
    const c = new GifClient('worker');
    worker.addEventListener('message', (e) => c.answer((e as MessageEvent<GifWorkerResponse>).data));
    worker.addEventListener('error', (e) => {
      (e as ErrorEvent).preventDefault?.();
      c.fail(new GifChannelError(`GIF worker error: ${(e as ErrorEvent).message || 'could not load the worker'}`));
    });
    worker.addEventListener('messageerror', () => c.fail(new GifChannelError('GIF worker message could not be read')));
    c.send = (req, transfer) => worker.postMessage(req, transfer);
    c.stop = () => worker.terminate();
    return c;
  }

  /**
   * A client that encodes here, one request per macrotask, so the page still paints progress and takes a
   * Cancel click between frames. Loads the encoder (gifenc) on demand.
   */
  static async onMainThread(): Promise<GifClient> {
    const { createGifSession } = await import('./gifSession');
    const session = createGifSession();
    const c = new GifClient('main-thread');
    let queue = Promise.resolve();
    c.send = (req) => {
      queue = queue
        .then(() => new Promise<void>((resolve) => setTimeout(resolve, 0)))
        .then(() => {
          if (!c.closed) c.answer(session.handle(req).response);
        });
    };
    return c;
  }

  /** Sends a request; resolves with its answer, rejects with the session's error message or a GifChannelError. */
  request(req: GifWorkerRequest, transfer: Transferable[] = []): Promise<GifWorkerResponse> {
    if (this.closed) return Promise.reject(new GifChannelError('the GIF encoder was closed'));
    const p = new Promise<GifWorkerResponse>((resolve, reject) => this.pending.push({ resolve, reject }));
    this.send(req, transfer);
    return p;
  }

  /** Ends the encode and rejects what is pending. Idempotent. */
  close(): void {
    if (this.closed) return;
    this.fail(new GifChannelError('the GIF encoder was closed'));
    this.closed = true;
    this.stop();
  }

  private answer(r: GifWorkerResponse): void {
    const p = this.pending.shift();
    if (!p) return;
    if (r.type === 'error') p.reject(new Error(r.message));
    else p.resolve(r);
  }

  private fail(e: Error): void {
    const all = this.pending;
    this.pending = [];
    for (const p of all) p.reject(e);
  }
}
