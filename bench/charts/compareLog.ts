/**
 * Compares the log charts' redraws (bench/charts/log.html) of several source trees in one browser and one run, the
 * trees taking turns round by round so that a change in the machine's load falls on all of them alike. Each tree
 * is a folder under ROOT holding src/, bench/ and node_modules (say, `git archive <commit> src bench` unpacked, with
 * a node_modules link); one Vite dev server serves ROOT. Prints, per chart and size, the median wall time of a
 * redraw and Chromium's task (CPU) time per redraw (TaskDuration over a round's redraws, median over the rounds).
 * Run: [ROUNDS=7] npx vite-node bench/charts/compareLog.ts <ROOT> <port> <tree> [<tree> ...]
 */
import { chromium } from 'playwright';
import { createServer } from 'vite';
import { findChromium } from '../../scripts/ensure-chromium.mjs';

const [ROOT, portArg, ...TREES] = process.argv.slice(2);
const PORT = Number(portArg);
const ROUNDS = Number(process.env.ROUNDS ?? 7);
const WARMUP = 20;
const STEPS = 60;
const SIZES: Array<[number, number]> = [
  [560, 320],
  [340, 240],
];
const CHARTS = ['convergence', 'diagram', 'cycle'] as const;

const median = (v: number[]) => {
  const s = [...v].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

const server = await createServer({
  root: ROOT,
  configFile: false,
  server: { port: PORT, strictPort: true },
  logLevel: 'error',
});
await server.listen();
const browser = await chromium.launch({ executablePath: (await findChromium()) || undefined, args: ['--no-sandbox'] });
try {
  const pages = [];
  for (const tree of TREES) {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    const cdp = await page.context().newCDPSession(page);
    await cdp.send('Performance.enable');
    await page.goto(`http://localhost:${PORT}/${tree}/bench/charts/log.html`);
    await page.waitForFunction(() => 'runLogBench' in window, null, { timeout: 120_000 });
    pages.push({ tree, page, cdp });
  }
  // wall[tree][key]: every kept redraw's ms; cpu[tree][key]: CPU ms per redraw of each round.
  const wall: Record<string, Record<string, number[]>> = {};
  const cpu: Record<string, Record<string, number[]>> = {};
  for (let round = 0; round < ROUNDS; round++) {
    for (const [w, h] of SIZES) {
      for (const which of CHARTS) {
        const key = `${which} ${w}x${h}`;
        for (const { tree, page, cdp } of round % 2 ? [...pages].reverse() : pages) {
          const task = async () =>
            (await cdp.send('Performance.getMetrics')).metrics.find((m) => m.name === 'TaskDuration')?.value ?? NaN;
          await page.evaluate(
            ([n, width, height, name]) =>
              (window as unknown as { runLogBench: (...a: unknown[]) => Promise<number[]> }).runLogBench(
                n,
                width,
                height,
                name,
              ),
            [WARMUP, w, h, which] as const,
          );
          const t0 = await task();
          const ms = await page.evaluate(
            ([n, width, height, name]) =>
              (window as unknown as { runLogBench: (...a: unknown[]) => Promise<number[]> }).runLogBench(
                n,
                width,
                height,
                name,
              ),
            [STEPS, w, h, which] as const,
          );
          const cpuMs = ((await task()) - t0) * 1000;
          ((wall[tree] ??= {})[key] ??= []).push(...ms);
          ((cpu[tree] ??= {})[key] ??= []).push(cpuMs / STEPS);
        }
      }
    }
  }
  const rows: string[] = [`| chart | ${TREES.map((t) => `${t} wall / CPU ms`).join(' | ')} |`];
  for (const [w, h] of SIZES) {
    for (const which of CHARTS) {
      const key = `${which} ${w}x${h}`;
      const cells = TREES.map((t) => `${median(wall[t][key]).toFixed(2)} / ${median(cpu[t][key]).toFixed(2)}`);
      rows.push(`| ${key} | ${cells.join(' | ')} |`);
    }
  }
  console.log(rows.join('\n'));
  console.log(JSON.stringify({ wall: undefined, cpu }, null, 1));
} finally {
  await browser.close();
  await server.close();
}
