/// <reference lib="webworker" />
import type { GifWorkerRequest } from '../features/export/animation/gifProtocol';
import { createGifSession } from '../features/export/animation/gifSession';

declare const self: DedicatedWorkerGlobalScope;

const session = createGifSession();

// A thin switch: the session answers every request exactly once, in order.
self.onmessage = (event: MessageEvent<GifWorkerRequest>) => {
  const { response, transfer } = session.handle(event.data);
  self.postMessage(response, transfer);
};
