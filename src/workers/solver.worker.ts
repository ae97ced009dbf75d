/// <reference lib="webworker" />
import { serveJobs } from '../shared/jobs/jobExpose';
import { solverHandlers } from './solverHandlers';

declare const self: DedicatedWorkerGlobalScope;

// The whole worker: serve every feature's solver jobs (solverHandlers.ts) to the client (solverClient.ts).
serveJobs(solverHandlers, self);
