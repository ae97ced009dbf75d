/// <reference lib="webworker" />
import { handleRequest } from './compute';
import { runLabRequest } from './labRunner';
import type { SolverRequest, SolverResponse } from './protocol';

declare const self: DedicatedWorkerGlobalScope;

const cancelled = new Set<number>();
const post = (r: SolverResponse) => self.postMessage(r);

// A thin switch: lab requests run asynchronously (cancellable), everything else through handleRequest, which never throws.
self.onmessage = (event: MessageEvent<SolverRequest>) => {
  const req = event.data;
  if (req.type === 'cancel') {
    cancelled.add(req.id);
    return;
  }
  if (req.type === 'lab') {
    void runLabRequest(req, post, () => cancelled.has(req.id)).finally(() => cancelled.delete(req.id));
    return;
  }
  const { response, transfer } = handleRequest(req);
  self.postMessage(response, transfer);
};
