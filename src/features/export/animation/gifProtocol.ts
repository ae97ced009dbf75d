/** Main thread to GIF worker: start with the size, loop and palette samples; add a frame; finish. */
export type GifWorkerRequest =
  | { type: 'begin'; width: number; height: number; loop: boolean; samples: ArrayBuffer[] }
  | { type: 'frame'; index: number; rgba: ArrayBuffer; delayCs: number }
  | { type: 'finish' };

/** GIF worker to main thread: exactly one answer per request, in order; errors are answers too. */
export type GifWorkerResponse =
  | { type: 'ready'; colors: number }
  | { type: 'frame-done'; index: number }
  | { type: 'done'; bytes: ArrayBuffer }
  | { type: 'error'; message: string };
