/**
 * Animation export benchmark in Chromium: builds bench/animation-harness (a page that is not part of the app)
 * with Vite into a temporary folder, serves it, and exports cycles drawn by the app's drawLinkage through
 * exportAnimation: the real module worker, the lazily loaded gifenc chunk and MediaRecorder. Reports size,
 * time, where the GIF was encoded, main-thread long tasks, the decoded frame count (omggif), the WebM's
 * frames and duration, and the sizes of the export's chunks. Writes bench/results/animation-browser.json.
 * A benchmark, not a test: it reports, it does not fail. Run: npx vite-node bench/animation.browser.ts
 * (E2E_PORT picks the port, default 4186).
 */
import { mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { chromium } from 'playwright';
import { build, preview } from 'vite';
import { gifFacts, videoDurationInBrowser, webmFacts } from '../e2e/media';
import { findChromium } from '../scripts/ensure-chromium.mjs';
import type { HarnessRequest, HarnessResult } from './animation-harness/harness';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');
const OUT = join(tmpdir(), 'fourbar-animation-harness');
const PORT = Number(process.env.E2E_PORT ?? 4186);
const PAGE = `http://localhost:${PORT}/bench/animation-harness/index.html`;

const CRANK_ROCKER = { r1: 6, r2: 2, r3: 5, r4: 5 };
const TRIPLE_ROCKER = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
const BASE: HarnessRequest = {
  format: 'gif',
  linkage: CRANK_ROCKER,
  theta2Deg: 45,
  framesPerCycle: 360,
  size: 'screen',
  viewWidth: 640,
  viewHeight: 360,
  fps: 30,
  loop: true,
};

const RUNS: { name: string; req: HarnessRequest }[] = [
  { name: 'GIF crank-rocker 360 frames 640x360', req: BASE },
  { name: 'GIF triple rocker 360 frames 640x360', req: { ...BASE, linkage: TRIPLE_ROCKER, theta2Deg: 0 } },
  {
    name: 'GIF crank-rocker 120 frames 720p (800x500 view)',
    req: { ...BASE, framesPerCycle: 120, size: '720p', viewWidth: 800, viewHeight: 500 },
  },
  { name: 'GIF cancelled after 20 frames', req: { ...BASE, cancelAfter: 20 } },
  { name: 'WebM crank-rocker 60 frames 640x360 at 30 FPS', req: { ...BASE, format: 'webm', framesPerCycle: 60 } },
];

async function main() {
  await build({
    root: ROOT,
    configFile: false,
    base: './',
    logLevel: 'warn',
    worker: { format: 'es' },
    build: {
      outDir: OUT,
      emptyOutDir: true,
      target: 'es2022',
      rollupOptions: { input: join(ROOT, 'bench/animation-harness/index.html') },
    },
  });
  const chunks = readdirSync(join(OUT, 'assets'))
    .filter((f) => f.endsWith('.js'))
    .map((f) => {
      const b = readFileSync(join(OUT, 'assets', f));
      return { file: f, bytes: b.length, gzip: gzipSync(b).length };
    });
  const server = await preview({
    root: ROOT,
    configFile: false,
    logLevel: 'warn',
    build: { outDir: OUT },
    preview: { port: PORT, strictPort: true },
  });
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH || (await findChromium()) || undefined,
    args: ['--no-sandbox', '--disable-gpu', '--autoplay-policy=no-user-gesture-required'],
  });
  const results: Record<string, unknown>[] = [];
  try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    page.on('pageerror', (e) => console.error('page error:', e.message));
    await page.goto(PAGE);
    await page.locator('#status', { hasText: 'ready' }).waitFor();
    for (const { name, req } of RUNS) {
      const r: HarnessResult = await page.evaluate(
        (q) =>
          (
            window as unknown as { __animationHarness: { run: (q: unknown) => Promise<HarnessResult> } }
          ).__animationHarness.run(q),
        req,
      );
      const row: Record<string, unknown> = {
        run: name,
        status: r.status,
        size: `${r.width}x${r.height}`,
        frames: r.frames,
        ms: r.ms,
        encoder: r.encoder ?? '',
        longTasks: r.longTasksMs.length,
        longestTaskMs: r.longTasksMs.length ? Math.max(...r.longTasksMs) : 0,
      };
      if (r.reason) row.reason = r.reason;
      if (r.base64) {
        const bytes = new Uint8Array(Buffer.from(r.base64, 'base64'));
        // Kept outside the repository to look at: the last file of each format.
        writeFileSync(join(tmpdir(), `fourbar-animation-sample.${req.format}`), bytes);
        row.bytes = bytes.length;
        row.mb = +(bytes.length / (1024 * 1024)).toFixed(2);
        if (req.format === 'gif') {
          const g = gifFacts(bytes);
          row.decodedFrames = g.frames;
          row.loopCount = g.loopCount;
          row.playSeconds = g.delaysCs.reduce((s, d) => s + d, 0) / 100;
        } else {
          const w = webmFacts(bytes);
          row.mimeType = r.mimeType;
          row.decodedFrames = w.frames;
          row.spanSeconds = +w.spanSeconds.toFixed(3);
          row.infoDuration = w.durationSeconds;
          row.videoDuration = +(await videoDurationInBrowser(page, bytes, r.mimeType ?? 'video/webm')).toFixed(3);
        }
      }
      results.push(row);
      console.log(JSON.stringify(row));
    }
  } finally {
    await browser.close();
    await new Promise<void>((resolve) => server.httpServer.close(() => resolve()));
  }
  console.table(results);
  console.table(chunks);
  mkdirSync(join(ROOT, 'bench', 'results'), { recursive: true });
  writeFileSync(join(ROOT, 'bench', 'results', 'animation-browser.json'), JSON.stringify({ results, chunks }, null, 2));
}

await main();
