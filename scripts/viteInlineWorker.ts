import type { Plugin } from 'vite';

/** The expression in src/workers/solverClient.ts that starts the solver worker from its own file. */
export const WORKER_FROM_FILE = "new Worker(new URL('./solver.worker.ts', import.meta.url), { type: 'module' })";

/**
 * For the offline file and the custom element: starts the solver worker from a blob inlined in the bundle
 * (Vite's `?worker&inline`) instead of its own file. A file:// page cannot start a worker from a file, and a
 * page that loads the element script from another origin cannot start a worker from that origin; a blob URL
 * made by the page itself works in both. Fails the build if solverClient.ts no longer has the expression, so
 * the swap can never silently stop happening.
 */
export function inlineSolverWorker(): Plugin {
  return {
    name: 'fourbar-inline-solver-worker',
    enforce: 'pre',
    transform(code, id) {
      if (!/[\\/]src[\\/]workers[\\/]solverClient\.ts$/.test(id)) return null;
      if (!code.includes(WORKER_FROM_FILE))
        this.error(`src/workers/solverClient.ts no longer contains ${WORKER_FROM_FILE}`);
      return (
        "import InlineSolverWorker from './solver.worker.ts?worker&inline';\n" +
        code.replace(WORKER_FROM_FILE, 'new InlineSolverWorker()')
      );
    },
  };
}
