/// <reference lib="webworker" />
import { solverApi } from './api';
import { expose } from '../shared/jobs/expose';

declare const self: DedicatedWorkerGlobalScope;

// The whole worker: serve the one API object (src/workers/api.ts) to the client (src/shared/jobs/client.ts).
expose(solverApi, self);
