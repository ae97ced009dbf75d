/// <reference lib="webworker" />
import { createMechStageLoop } from '../features/mechanism/stage/mechStageLoop';
import type { MechStageReply, MechStageRequest } from '../features/mechanism/stage/mechStageProtocol';
import { createMechStagePainter } from '../features/mechanism/stage/mechStagePainter';
import { workerFrameHost } from './stageFrameHost';

declare const self: DedicatedWorkerGlobalScope;

// The Mechanisms page's live stage worker: its loop (mechStageLoop.ts) on this worker's clock and animation frames,
// drawing with the painter (mechStagePainter.ts).
const handle = createMechStageLoop(workerFrameHost<MechStageReply>(), createMechStagePainter());
self.onmessage = (e: MessageEvent<MechStageRequest>) => handle(e.data);
