import type { Plugin } from 'vite';

/** Where the early worker waits for the app (src/workers/solverClient.ts takes it: keep the two in step). */
export const EARLY_WORKER_GLOBAL = '__fourbarSolverWorker';

/**
 * Starts the solver worker from each page's HTML head, before the app's script has downloaded. On a phone (RTT
 * 150 ms, 1.6 Mbit/s, 4x CPU) the worker's script then loads and compiles while the app's script downloads,
 * instead of after the first render has freed the main thread (a worker starts through its page's main thread);
 * its first answers come right after that render (bench:ui, phone row). The script leaves
 * `{ worker, failed }` on window; a worker that cannot start (a sandboxed embed's opaque origin) leaves nothing or
 * failed = true, and the app starts its own. Fails the build if the bundle has no solver worker file.
 */
export function earlySolverWorker(): Plugin {
  return {
    name: 'fourbar-early-solver-worker',
    apply: 'build',
    transformIndexHtml: {
      order: 'post',
      handler(_html, ctx) {
        const file = Object.keys(ctx.bundle ?? {}).find((f) => /(^|\/)solver\.worker-[\w-]+\.js$/.test(f));
        if (!file) throw new Error('earlySolverWorker: no solver.worker-*.js in the bundle');
        const start =
          `try{var w=new Worker(${JSON.stringify(`./${file}`)},{type:"module"}),e={worker:w,failed:false};` +
          `w.addEventListener("error",function(){e.failed=true});window.${EARLY_WORKER_GLOBAL}=e}catch(x){}`;
        return [{ tag: 'script', children: start, injectTo: 'head' }];
      },
    },
  };
}
