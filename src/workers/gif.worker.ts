/// <reference lib="webworker" />
import { serveJobs } from '../shared/jobs/jobExpose';
import { createGifSession } from '../features/export/animation/gifSession';

declare const self: DedicatedWorkerGlobalScope;

// One worker per encode: serve a fresh GIF session's jobs (gifJobs.ts) to gifExport.ts.
serveJobs(createGifSession(), self);
