/** Where the 3D view draws: in a worker on an OffscreenCanvas, on the page's thread, or nowhere (no WebGL). */
export type ViewRoute = 'worker' | 'main' | 'none';

/** What the browser offers the 3D view (read on the page by browserViewFacts in webglProbe.ts). */
export interface ViewFacts {
  /** A WebGL context could be made on the page. */
  webgl: boolean;
  /** Worker, OffscreenCanvas and HTMLCanvasElement.transferControlToOffscreen all exist. */
  canTransfer: boolean;
  /** The worker already failed on this page (could not start, or no WebGL there). */
  workerFailed: boolean;
}

/**
 * The route for the 3D view: none without WebGL (the page's message, the numbers and plots still work); the worker
 * where a canvas can be handed to one and it has not failed; else the page's own thread, as before the worker.
 */
export function chooseViewRoute(f: ViewFacts): ViewRoute {
  if (!f.webgl) return 'none';
  return f.canTransfer && !f.workerFailed ? 'worker' : 'main';
}
