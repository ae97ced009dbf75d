import { resolve } from 'node:path';
import react from '@vitejs/plugin-react';
import { defineConfig } from 'vite';
import { MECH_STAGE_WORKER, SOLVER_WORKER, STAGE_WORKER, inlineWorkers } from './scripts/viteInlineWorker';

/**
 * The offline single file (npm run build:single): the app as one script and one stylesheet in dist-single,
 * every dynamic import and asset inlined and the solver and live stage workers as inline blobs;
 * scripts/inline-single.mjs then puts both into the HTML as dist-single/fourbar-lab.html.
 */
export default defineConfig({
  base: './',
  plugins: [react(), inlineWorkers([SOLVER_WORKER, STAGE_WORKER, MECH_STAGE_WORKER])],
  // A classic (iife) worker: Chromium refuses a module worker from a blob: URL on a file:// page (opaque origin,
  // CORS-mode fetch) and the client falls back to the main thread; a classic one starts. The worker's own lazy
  // import (the lab's 60-digit reference) goes inside the blob too.
  worker: { format: 'iife', rollupOptions: { output: { inlineDynamicImports: true } } },
  publicDir: false,
  build: {
    outDir: 'dist-single',
    emptyOutDir: true,
    target: 'es2022',
    assetsInlineLimit: Number.MAX_SAFE_INTEGER,
    cssCodeSplit: false,
    modulePreload: false,
    rollupOptions: {
      input: resolve(import.meta.dirname, 'index.html'),
      output: { inlineDynamicImports: true },
    },
  },
});
