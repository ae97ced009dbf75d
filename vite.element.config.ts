import { resolve } from 'node:path';
import react from '@vitejs/plugin-react';
import { defineConfig } from 'vite';
import { asciiOnly } from './scripts/viteAsciiOnly';
import { ELEMENT_DIR, ELEMENT_MODULE, elementLoader } from './scripts/viteElementLoader';
import { cssIntoShadowRoot } from './scripts/viteShadowCss';
import { inlineSolverWorker } from './scripts/viteInlineWorker';

/**
 * The custom element (npm run build:element): dist-element/fourbar-lab.js, a small classic script that defines
 * <fourbar-lab> by importing the ES module dist-element/fourbar-lab/element.js beside it (React, the widget, its CSS for
 * the shadow root and the solver worker, a classic blob worker any page can start whatever origin the script came
 * from). The pages an element may show besides the simulator (Spatial with three.js, Mechanisms) are chunks in
 * fourbar-lab/ that the module imports from its own URL only when an element shows them.
 */
export default defineConfig({
  plugins: [react(), inlineSolverWorker(), cssIntoShadowRoot(), asciiOnly(), elementLoader()],
  define: { 'process.env.NODE_ENV': JSON.stringify('production') },
  worker: { format: 'iife', rollupOptions: { output: { inlineDynamicImports: true } } },
  publicDir: false,
  build: {
    outDir: 'dist-element',
    emptyOutDir: true,
    target: 'es2022',
    cssCodeSplit: false,
    assetsDir: ELEMENT_DIR,
    assetsInlineLimit: Number.MAX_SAFE_INTEGER,
    lib: {
      entry: resolve(import.meta.dirname, 'src/app/element.tsx'),
      formats: ['es'],
      fileName: () => ELEMENT_MODULE,
    },
    rollupOptions: {
      output: {
        chunkFileNames: `${ELEMENT_DIR}/[name]-[hash].js`,
        // Lib mode keeps an ES build's whitespace and comments for other bundlers; this one goes to browsers as is.
        minify: true,
        comments: false,
        // Everything the simulator's first draw needs in one chunk beside the entry, not forty small files.
        codeSplitting: { groups: [{ name: 'widget', tags: ['$initial'] }] },
      },
    },
  },
});
