/// <reference lib="webworker" />
import type { StageFrameHost } from '../shared/linkage/liveStage';

declare const self: DedicatedWorkerGlobalScope;

/** This worker's clock, animation frames (null where workers have none) and postMessage, for a stage's loop. */
export function workerFrameHost<R>(): StageFrameHost<R> {
  const hasFrames = typeof self.requestAnimationFrame === 'function';
  return {
    now: () => performance.now(),
    timeOrigin: performance.timeOrigin,
    requestFrame: hasFrames ? (callback) => self.requestAnimationFrame(callback) : null,
    cancelFrame: (h) => self.cancelAnimationFrame(h),
    reply: (message: R) => self.postMessage(message),
  };
}
