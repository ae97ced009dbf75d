/// <reference lib="webworker" />
import { handleRequest } from './compute';
import type { SolverRequest } from './protocol';

declare const self: DedicatedWorkerGlobalScope;

// A thin switch: every request is answered by handleRequest, which never throws.
self.onmessage = (event: MessageEvent<SolverRequest>) => {
  const { response, transfer } = handleRequest(event.data);
  self.postMessage(response, transfer);
};
