import type { SolverApi, SolverMethod, SolverResponse, TaskContext } from './protocol';

/** The side of a channel the API answers on: a worker's global scope, or the main-thread stand-in. */
export interface Endpoint {
  postMessage(message: SolverResponse, transfer: Transferable[]): void;
  addEventListener(type: 'message', listener: (event: MessageEvent) => void): void;
}

const METHODS: readonly SolverMethod[] = ['cycle', 'point', 'table', 'lab'];

/** Every distinct ArrayBuffer under a typed array in value (plain objects and arrays only): the answer's transfer list. */
export function transferablesOf(value: unknown, out = new Set<ArrayBuffer>()): ArrayBuffer[] {
  if (ArrayBuffer.isView(value)) {
    if (value.buffer instanceof ArrayBuffer) out.add(value.buffer);
  } else if (Array.isArray(value)) {
    for (const v of value) transferablesOf(v, out);
  } else if (value !== null && typeof value === 'object' && Object.getPrototypeOf(value) === Object.prototype) {
    for (const v of Object.values(value)) transferablesOf(v, out);
  }
  return [...out];
}

/**
 * Serves api on endpoint: each request { type, id, params } calls api[type](params, task) and answers
 * { type, id, value } with the value's buffers transferred, progress as { type: 'progress' }, and any
 * failure as { type: 'error', requestType } naming the request's own type. Never throws. Returns a
 * function that cancels every running call (the main-thread stand-in's terminate).
 */
export function expose(api: SolverApi, endpoint: Endpoint): () => void {
  const running = new Set<number>();
  const cancelled = new Set<number>();
  const answer = async (data: unknown): Promise<void> => {
    const req = (typeof data === 'object' && data !== null ? data : {}) as {
      type?: unknown;
      id?: unknown;
      params?: unknown;
    };
    const id = typeof req.id === 'number' ? req.id : -1;
    const type = typeof req.type === 'string' ? req.type : 'unknown';
    if (type === 'cancel') {
      if (running.has(id)) cancelled.add(id);
      return;
    }
    running.add(id);
    try {
      const method = METHODS.find((m) => m === type);
      if (!method) throw new Error(`unknown request type ${JSON.stringify(req.type)}`);
      if (typeof req.params !== 'object' || req.params === null) throw new Error(`${method} request has no params`);
      const task: TaskContext = {
        progress: (fraction, stage) => endpoint.postMessage({ type: 'progress', id, fraction, stage }, []),
        cancelled: () => cancelled.has(id),
      };
      const call = api[method] as (params: unknown, task: TaskContext) => unknown;
      const value = await call(req.params, task);
      endpoint.postMessage({ type: method, id, value } as SolverResponse, transferablesOf(value));
    } catch (e) {
      const message = e instanceof Error ? e.message : String(e);
      endpoint.postMessage({ type: 'error', id, requestType: type, message }, []);
    } finally {
      running.delete(id);
      cancelled.delete(id);
    }
  };
  endpoint.addEventListener('message', (event) => void answer(event.data));
  return () => {
    for (const id of running) cancelled.add(id);
  };
}
