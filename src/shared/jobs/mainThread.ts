import type { WorkerLike } from './jobClient';
import type { Endpoint } from './jobExpose';
import { serveJobs } from './jobExpose';
import type { AnyJobRequest, AnyJobResponse } from './jobProtocol';
import type { AnyJobHandlers } from './jobTable';

type Listener = (event: MessageEvent) => void;

/**
 * A stand-in worker that serves a handler table on the main thread, loading it on demand (load() is a dynamic
 * import, so the handlers stay out of the main bundle). Messages are delivered in later tasks, one per task, as
 * a worker's are: the page still paints between two calls, and latest-wins and cancel behave the same.
 * Nothing is cloned: transferred buffers are handed over as they are.
 */
export function createMainThreadWorker(load: () => Promise<AnyJobHandlers>): WorkerLike {
  const toClient: Listener[] = [];
  let toHandlers: Listener | null = null;
  let waiting: AnyJobRequest[] = [];
  let closed = false;
  let loadError: string | null = null;
  const refuse = (m: AnyJobRequest, message: string) => {
    if (m.type === 'run') endpoint.postMessage({ type: 'error', id: m.id, job: m.job, message }, []);
  };
  let stop = (): void => undefined;
  const later = (listener: Listener, data: unknown) =>
    setTimeout(() => {
      if (!closed) listener({ data } as MessageEvent);
    }, 0);
  const endpoint: Endpoint = {
    postMessage: (message: AnyJobResponse) => toClient.forEach((l) => later(l, message)),
    addEventListener: (_type, listener) => {
      toHandlers = listener;
    },
  };
  load().then(
    (handlers) => {
      stop = serveJobs(handlers, endpoint);
      for (const m of waiting) if (toHandlers) later(toHandlers, m);
      waiting = [];
    },
    (e: unknown) => {
      loadError = `the main-thread jobs failed to load: ${e instanceof Error ? e.message : String(e)}`;
      for (const m of waiting) refuse(m, loadError);
      waiting = [];
    },
  );
  return {
    postMessage: (message) => {
      if (toHandlers) later(toHandlers, message);
      else if (loadError) refuse(message, loadError);
      else waiting.push(message);
    },
    addEventListener: (type, listener) => {
      if (type === 'message') toClient.push(listener as Listener);
    },
    terminate: () => {
      closed = true;
      stop();
    },
  };
}
