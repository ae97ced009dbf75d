import type { AnyJobResponse } from './jobProtocol';
import type { AnyJobHandlers, JobContext } from './jobTable';

/** The side of a channel the handlers answer on: a worker's global scope, or the main-thread stand-in. */
export interface Endpoint {
  postMessage(message: AnyJobResponse, transfer: Transferable[]): void;
  addEventListener(type: 'message', listener: (event: MessageEvent) => void): void;
}

/** Every distinct ArrayBuffer in value (bare, or under a typed array; plain objects and arrays only): its transfer list. */
export function transferablesOf(value: unknown, out = new Set<ArrayBuffer>()): ArrayBuffer[] {
  if (value instanceof ArrayBuffer) out.add(value);
  else if (ArrayBuffer.isView(value)) {
    if (value.buffer instanceof ArrayBuffer) out.add(value.buffer);
  } else if (Array.isArray(value)) {
    for (const v of value) transferablesOf(v, out);
  } else if (value !== null && typeof value === 'object' && Object.getPrototypeOf(value) === Object.prototype) {
    for (const v of Object.values(value)) transferablesOf(v, out);
  }
  return [...out];
}

/** The fields of a request as received, each checked before use: a worker trusts nothing it is sent. */
function readRequest(data: unknown): { type: string; id: number; job: unknown; params: unknown } {
  const req = (typeof data === 'object' && data !== null ? data : {}) as Record<string, unknown>;
  return {
    type: typeof req.type === 'string' ? req.type : 'unknown',
    id: typeof req.id === 'number' ? req.id : -1,
    job: req.job,
    params: req.params,
  };
}

/**
 * Serves a handler table on endpoint: each request { type: 'run', id, job, params } calls handlers[job](params,
 * context) and answers { type: 'result', id, job, value } with the value's buffers transferred, progress as
 * { type: 'progress' }, and any failure (unknown job, missing params, a throw or rejection) as
 * { type: 'error', job } naming the request's own job. { type: 'cancel', id } aborts that call's signal. Never
 * throws. Returns a function that aborts every running call (the main-thread stand-in's terminate).
 */
export function serveJobs(handlers: AnyJobHandlers, endpoint: Endpoint): () => void {
  const running = new Map<number, AbortController>();
  const answer = async (data: unknown): Promise<void> => {
    const req = readRequest(data);
    if (req.type === 'cancel') {
      running.get(req.id)?.abort();
      return;
    }
    const { id } = req;
    const jobName = typeof req.job === 'string' ? req.job : 'unknown';
    const controller = new AbortController();
    running.set(id, controller);
    try {
      if (req.type !== 'run') throw new Error(`unknown request type ${JSON.stringify(req.type)}`);
      const handler = Object.hasOwn(handlers, jobName) ? handlers[jobName] : undefined;
      if (!handler) throw new Error(`unknown job ${JSON.stringify(req.job)}`);
      if (typeof req.params !== 'object' || req.params === null) throw new Error(`${jobName} request has no params`);
      const context: JobContext = {
        signal: controller.signal,
        progress: (fraction, stage) => endpoint.postMessage({ type: 'progress', id, fraction, stage }, []),
      };
      const value = await handler(req.params as never, context);
      endpoint.postMessage({ type: 'result', id, job: jobName, value }, transferablesOf(value));
    } catch (e) {
      const message = e instanceof Error ? e.message : String(e);
      endpoint.postMessage({ type: 'error', id, job: jobName, message }, []);
    } finally {
      if (running.get(id) === controller) running.delete(id);
    }
  };
  endpoint.addEventListener('message', (event) => void answer(event.data));
  return () => {
    for (const controller of running.values()) controller.abort();
  };
}
