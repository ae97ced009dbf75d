import type { WorkerLike } from '../../../src/shared/jobs/jobClient';
import { serveJobs } from '../../../src/shared/jobs/jobExpose';
import type { AnyJobRequest, AnyJobResponse } from '../../../src/shared/jobs/jobProtocol';
import type { AnyJobHandlers } from '../../../src/shared/jobs/jobTable';

/**
 * A fake Worker serving a handler table through the real serveJobs(): requests wait in `received` until the
 * test delivers them (or at once when auto), and both directions cross a structured clone with their transfer
 * lists, as they would between threads (a transferred buffer is detached on the sending side). A dead worker
 * (close() in it) takes requests and never answers.
 */
export class FakeWorker implements WorkerLike {
  received: AnyJobRequest[] = [];
  /** The transfer list each request came with. */
  transfers: Transferable[][] = [];
  /** The transfer list each answer went out with. */
  answerTransfers: Transferable[][] = [];
  delivered = 0;
  terminated = false;
  dead = false;
  private toClient: Record<string, ((e: Event) => void)[]> = { message: [], error: [], messageerror: [] };
  private toHandlers: ((e: MessageEvent) => void) | null = null;
  constructor(
    handlers: AnyJobHandlers,
    private auto = false,
  ) {
    serveJobs(handlers, {
      postMessage: (message: AnyJobResponse, transfer: Transferable[]) => {
        if (this.terminated) return;
        this.answerTransfers.push(transfer);
        const data = structuredClone(message, { transfer });
        for (const l of this.toClient.message) l({ data } as MessageEvent);
      },
      addEventListener: (_type, l) => {
        this.toHandlers = l;
      },
    });
  }
  postMessage(message: AnyJobRequest, transfer: Transferable[] = []): void {
    if (this.terminated || this.dead) return;
    this.received.push(structuredClone(message, { transfer }));
    this.transfers.push(transfer);
    if (this.auto) this.deliverAll();
  }
  addEventListener(type: string, listener: (e: Event) => void): void {
    this.toClient[type].push(listener);
  }
  terminate(): void {
    this.terminated = true;
  }
  /** Hands the next waiting request to the handlers and lets them answer. */
  async deliver(): Promise<void> {
    this.toHandlers?.({ data: this.received[this.delivered++] } as MessageEvent);
    await flush();
  }
  /** Hands every waiting request to the handlers. */
  deliverAll(): void {
    while (this.delivered < this.received.length)
      this.toHandlers?.({ data: this.received[this.delivered++] } as MessageEvent);
  }
  /** An error event, as a worker whose script failed or threw gives. */
  error(message: string): void {
    for (const l of this.toClient.error) l({ message, preventDefault: () => undefined } as unknown as Event);
  }
  /** The run requests received (cancels left out). */
  runs(): Extract<AnyJobRequest, { type: 'run' }>[] {
    return this.received.filter((r): r is Extract<AnyJobRequest, { type: 'run' }> => r.type === 'run');
  }
}

/** Lets promise callbacks (and serveJobs' awaited answers) run. */
export async function flush(): Promise<void> {
  for (let i = 0; i < 5; i++) await Promise.resolve();
}
