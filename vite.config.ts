import { resolve } from 'node:path';
import react from '@vitejs/plugin-react';
import { defineConfig } from 'vitest/config';

/**
 * Each page's own modules: its entry and layout and their CSS (the rest of a page's first load is shared by both
 * pages and goes into the one 'app' chunk).
 */
const PAGE_OWN =
  /[\\/]src[\\/]app[\\/](main\.tsx|embed\.tsx|AppLayout\.tsx|EmbedLayout\.tsx|layout\.css|embedPage\.css|AppLayout\.css|EmbedLayout\.css)$/;

/**
 * Whether a module goes into the 'app' chunk: every module of either page's first load but the page's own. One
 * chunk instead of twenty: on a phone over HTTP/1.1 (six connections, 150 ms RTT), twenty small files cost several
 * round trips (bench:ui, phone row).
 */
function sharedInitial(id: string): boolean {
  return !id.includes('.html') && !PAGE_OWN.test(id);
}

/** Vite config: two entries (the app and the embeddable widget) on the same components. */
export default defineConfig({
  base: './',
  plugins: [react()],
  worker: { format: 'es' },
  build: {
    target: 'es2022',
    // kB, minified. The largest chunk is 'app' (534 kB, 180 kB gzip, on 2026-12-04): every module of the first load
    // merged on purpose (sharedInitial above), so its size is one file's, not twenty's. Its budget is the ready time
    // on a phone profile (bench:ui), not bytes; the lazy pages and the workers are far below this. 600 still warns if
    // the first load grows by a sixth.
    chunkSizeWarningLimit: 600,
    rollupOptions: {
      input: {
        main: resolve(import.meta.dirname, 'index.html'),
        embed: resolve(import.meta.dirname, 'embed.html'),
      },
      output: {
        codeSplitting: {
          groups: [{ name: 'app', tags: ['$initial'], test: sharedInitial }],
        },
      },
    },
  },
  server: { port: 5173 },
  // CORS like static hosts send it: a sandboxed embed iframe has an opaque origin, so its module scripts are cross-origin.
  preview: { port: 4173, cors: true },
  test: {
    include: ['tests/**/*.test.ts'],
    environment: 'node',
    testTimeout: 60_000,
  },
});
