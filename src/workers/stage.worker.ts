/// <reference lib="webworker" />
import { createForceLayer } from '../features/forces/forceLayer';
import { createStageLoop } from '../features/simulator/stage/stageLoop';
import type { StageReply, StageRequest } from '../features/simulator/stage/stageProtocol';
import { createStagePainter } from '../features/simulator/stage/stagePainter';
import { workerFrameHost } from './stageFrameHost';

declare const self: DedicatedWorkerGlobalScope;

// The live stage's worker: its loop (stageLoop.ts) on this worker's clock and animation frames, drawing with the
// painter (stagePainter.ts) and the forces feature's pin forces.
const handle = createStageLoop(workerFrameHost<StageReply>(), createStagePainter(createForceLayer()));
self.onmessage = (e: MessageEvent<StageRequest>) => handle(e.data);
