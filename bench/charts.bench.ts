/**
 * Chart update benchmark: JavaScript time per update of the two separate angle plots when r3 changes
 * (default linkage 6-2-5-5, open branch, plot samples at the chart's pixel width), in headless Chromium
 * served by the Vite dev server. Prints median, p95 and mean over STEPS updates after WARMUP; writes
 * bench/results/charts.json. A benchmark, not a test: it reports, it does not fail.
 * With the argument log, it times the log charts instead (bench/charts/log.html): a redraw of the NR convergence
 * chart, the lab's work-precision diagram and its cycle chart, and their CPU time from Chromium's TaskDuration
 * (less noisy than wall time on a shared machine); writes bench/results/charts-log.json.
 * Run: npx vite-node bench/charts.bench.ts [port] [log]
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright';
import { createServer } from 'vite';
import { findChromium } from '../scripts/ensure-chromium.mjs';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');
const PORT = Number(process.argv[2] ?? 4182);
const LOG = process.argv[3] === 'log';
const WARMUP = 40;
const STEPS = 300;
const SIZES: Array<[number, number]> = [
  [560, 320],
  [340, 240],
];

function quantile(sorted: number[], q: number): number {
  return sorted[Math.min(sorted.length - 1, Math.max(0, Math.round(q * (sorted.length - 1))))];
}

const server = await createServer({ root: ROOT, server: { port: PORT, strictPort: true }, logLevel: 'error' });
await server.listen();
const browser = await chromium.launch({ executablePath: (await findChromium()) || undefined, args: ['--no-sandbox'] });
const results: Record<string, { median: number; p95: number; mean: number; steps: number; cpuMs?: number }> = {};

/** Times the log charts' redraws at each size: wall time per redraw and Chromium's task (CPU) time per redraw. */
async function logBench(): Promise<void> {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Performance.enable');
  const taskSeconds = async () =>
    (await cdp.send('Performance.getMetrics')).metrics.find((m) => m.name === 'TaskDuration')?.value ?? NaN;
  await page.goto(`http://localhost:${PORT}/bench/charts/log.html`);
  await page.waitForFunction(() => 'runLogBench' in window);
  for (const [w, h] of SIZES) {
    for (const which of ['convergence', 'diagram', 'cycle'] as const) {
      const t0 = await taskSeconds();
      const ms = await page.evaluate(
        ([steps, width, height, name]) =>
          (
            window as unknown as {
              runLogBench: (s: number, w: number, h: number, n: string) => Promise<number[]>;
            }
          ).runLogBench(steps, width, height, name),
        [WARMUP + STEPS, w, h, which] as const,
      );
      const cpuMs = ((await taskSeconds()) - t0) * 1000;
      const kept = ms.slice(WARMUP);
      const sorted = [...kept].sort((a, b) => a - b);
      const mean = kept.reduce((a, b) => a + b, 0) / kept.length;
      results[`${which} ${w}x${h}`] = {
        median: quantile(sorted, 0.5),
        p95: quantile(sorted, 0.95),
        mean,
        steps: kept.length,
        // Whole run (warm-up, frames between steps included) over its redraws.
        cpuMs: cpuMs / ms.length,
      };
    }
  }
}

try {
  if (LOG) await logBench();
  else {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.goto(`http://localhost:${PORT}/bench/charts/index.html`);
    await page.waitForFunction(() => 'runBench' in window);
    for (const [w, h] of SIZES) {
      const r = await page.evaluate(
        ([steps, width, height]) =>
          (
            window as unknown as { runBench: (s: number, w: number, h: number) => Promise<{ msPerUpdate: number[] }> }
          ).runBench(steps, width, height),
        [WARMUP + STEPS, w, h] as const,
      );
      const ms = r.msPerUpdate.slice(WARMUP);
      const sorted = [...ms].sort((a, b) => a - b);
      const mean = ms.reduce((a, b) => a + b, 0) / ms.length;
      results[`${w}x${h}`] = { median: quantile(sorted, 0.5), p95: quantile(sorted, 0.95), mean, steps: ms.length };
    }
  }
} finally {
  await browser.close();
  await server.close();
}
console.log(LOG ? 'log charts, JS per redraw, ms' : 'angle plots (two charts), JS per r3 update, ms');
for (const [k, v] of Object.entries(results))
  console.log(
    `  ${k}: median ${v.median.toFixed(3)}  p95 ${v.p95.toFixed(3)}  mean ${v.mean.toFixed(3)}` +
      (v.cpuMs === undefined ? '' : `  task ${v.cpuMs.toFixed(3)}`) +
      `  (n=${v.steps})`,
  );
mkdirSync(join(ROOT, 'bench', 'results'), { recursive: true });
const file = LOG ? 'charts-log.json' : 'charts.json';
writeFileSync(join(ROOT, 'bench', 'results', file), JSON.stringify(results, null, 2) + '\n');
