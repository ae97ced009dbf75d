/// <reference lib="webworker" />
import { solverApi } from './api';
import { expose } from './expose';

declare const self: DedicatedWorkerGlobalScope;

// The whole worker: serve the one API object (src/worker/api.ts) to the client (src/worker/client.ts).
expose(solverApi, self);
