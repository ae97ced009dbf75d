/// <reference lib="webworker" />
import { createForceLayer } from '../features/forces/forceLayer';
import { createStageLoop } from '../features/simulator/stage/stageLoop';
import type { StageReply, StageRequest } from '../features/simulator/stage/stageProtocol';
import { createStagePainter } from '../features/simulator/stage/stagePainter';

declare const self: DedicatedWorkerGlobalScope;

// The live stage's worker: its loop (stageLoop.ts) on this worker's clock and animation frames, drawing with the
// painter (stagePainter.ts) and the forces feature's pin forces.
const hasFrames = typeof self.requestAnimationFrame === 'function';
const handle = createStageLoop(
  {
    now: () => performance.now(),
    timeOrigin: performance.timeOrigin,
    requestFrame: hasFrames ? (callback) => self.requestAnimationFrame(callback) : null,
    cancelFrame: (h) => self.cancelAnimationFrame(h),
    reply: (message: StageReply) => self.postMessage(message),
  },
  createStagePainter(createForceLayer()),
);
self.onmessage = (e: MessageEvent<StageRequest>) => handle(e.data);
