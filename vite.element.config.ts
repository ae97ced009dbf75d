import { resolve } from 'node:path';
import react from '@vitejs/plugin-react';
import { defineConfig } from 'vite';
import { asciiOnly } from './scripts/viteAsciiOnly';
import { cssIntoShadowRoot } from './scripts/viteShadowCss';
import { inlineSolverWorker } from './scripts/viteInlineWorker';

/**
 * The custom element (npm run build:element): dist-element/fourbar-lab.js, one classic script that defines
 * <fourbar-lab>, with React, the widget, its CSS (for the shadow root) and the solver worker (a classic blob
 * worker, which any page can start whatever origin the script came from) inside.
 */
export default defineConfig({
  plugins: [react(), inlineSolverWorker(), cssIntoShadowRoot(), asciiOnly()],
  define: { 'process.env.NODE_ENV': JSON.stringify('production') },
  worker: { format: 'iife', rollupOptions: { output: { inlineDynamicImports: true } } },
  publicDir: false,
  build: {
    outDir: 'dist-element',
    emptyOutDir: true,
    target: 'es2022',
    cssCodeSplit: false,
    assetsInlineLimit: Number.MAX_SAFE_INTEGER,
    lib: {
      entry: resolve(import.meta.dirname, 'src/app/element.tsx'),
      formats: ['iife'],
      name: 'FourbarLab',
      fileName: () => 'fourbar-lab.js',
    },
    rollupOptions: { output: { inlineDynamicImports: true } },
  },
});
