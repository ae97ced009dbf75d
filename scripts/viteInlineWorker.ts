import type { Plugin } from 'vite';

/** A worker the app starts from its own file: the client module that starts it and the worker's entry. */
export interface WorkerEntry {
  client: string;
  worker: string;
}

/** The solver worker (every feature's jobs), started by src/workers/solverClient.ts. */
export const SOLVER_WORKER: WorkerEntry = { client: 'solverClient.ts', worker: 'solver.worker.ts' };
/** The live stage's worker (Play drawn on an OffscreenCanvas), started by src/workers/stageClient.ts. */
export const STAGE_WORKER: WorkerEntry = { client: 'stageClient.ts', worker: 'stage.worker.ts' };
/** The Mechanisms page's live stage worker (Play and a joint's drag drawn), started by src/workers/mechStageClient.ts. */
export const MECH_STAGE_WORKER: WorkerEntry = { client: 'mechStageClient.ts', worker: 'mechStage.worker.ts' };

/** The expression a client starts its worker from its own file with. */
function workerFromFile(entry: WorkerEntry): string {
  return `new Worker(new URL('./${entry.worker}', import.meta.url), { type: 'module' })`;
}

/**
 * For the offline file and the custom element: starts each worker given from a blob inlined in the bundle (Vite's
 * `?worker&inline`) instead of its own file. A file:// page cannot start a worker from a file, and a page that loads
 * the element script from another origin cannot start a worker from that origin; a blob URL made by the page itself
 * works in both. Fails the build if a client no longer has the expression, so the swap can never silently stop
 * happening.
 */
export function inlineWorkers(entries: readonly WorkerEntry[]): Plugin {
  return {
    name: 'fourbar-inline-workers',
    enforce: 'pre',
    transform(code, id) {
      const entry = entries.find((e) => id.replace(/\\/g, '/').endsWith(`/src/workers/${e.client}`));
      if (!entry) return null;
      const expression = workerFromFile(entry);
      if (!code.includes(expression)) this.error(`src/workers/${entry.client} no longer contains ${expression}`);
      return (
        `import InlineWorker from './${entry.worker}?worker&inline';\n` + code.replace(expression, 'new InlineWorker()')
      );
    },
  };
}

/** The solver worker inlined (the custom element: the live stage's worker stays out of its bundle, for its bytes). */
export function inlineSolverWorker(): Plugin {
  return inlineWorkers([SOLVER_WORKER]);
}
