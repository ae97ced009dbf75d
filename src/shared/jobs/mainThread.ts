import type { WorkerLike } from './client';
import type { Endpoint } from './expose';
import type { SolverRequest, SolverResponse } from './protocol';

type Listener = (event: MessageEvent) => void;

/**
 * A stand-in worker that serves the same API object (api.ts, through expose.ts) on the main thread,
 * loaded on demand so the solver stays out of the main bundle. Messages are delivered in later tasks,
 * as a worker's are, so the client's latest-wins and a lab's cancel behave the same. Nothing is cloned.
 */
export function createMainThreadWorker(): WorkerLike {
  const toClient: Listener[] = [];
  let toApi: Listener | null = null;
  let waiting: SolverRequest[] = [];
  let closed = false;
  let loadError: string | null = null;
  const refuse = (m: SolverRequest, message: string) =>
    endpoint.postMessage({ type: 'error', id: m.id, requestType: m.type, message }, []);
  let stop = (): void => undefined;
  const later = (listener: Listener, data: unknown) =>
    setTimeout(() => {
      if (!closed) listener({ data } as MessageEvent);
    }, 0);
  const endpoint: Endpoint = {
    postMessage: (message: SolverResponse) => toClient.forEach((l) => later(l, message)),
    addEventListener: (_type, listener) => {
      toApi = listener;
    },
  };
  Promise.all([import('../../workers/api'), import('./expose')]).then(
    ([{ solverApi }, { expose }]) => {
      stop = expose(solverApi, endpoint);
      for (const m of waiting) if (toApi) later(toApi, m);
      waiting = [];
    },
    (e: unknown) => {
      loadError = `main-thread solver failed to load: ${e instanceof Error ? e.message : String(e)}`;
      for (const m of waiting) refuse(m, loadError);
      waiting = [];
    },
  );
  return {
    postMessage: (message) => {
      if (toApi) later(toApi, message);
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
