/**
 * What CDP's CPU throttling (Emulation.setCPUThrottlingRate, bench:ui's "4x") costs the machine itself: the page
 * thread's CPU time (from /proc, bench/procCpu.ts) over 2 s of an idle page and over a fixed busy loop, at 1x and at
 * RATE x. Chromium slows the page thread by keeping it busy, not by letting it sleep, so at 4x an idle page thread
 * takes about two thirds of a core: on a 2-core machine that is a third of the CPU the GPU process (SwiftShader) and
 * the workers no longer have (docs/benchmarks.md, session 28). Linux only; reports, never fails.
 * Run: npx vite-node bench/throttleSpin.ts   (RATE=6 for another rate)
 */
import { readFileSync } from 'node:fs';
import { chromium } from 'playwright';
import { findChromium } from '../scripts/ensure-chromium.mjs';
import { chromiumProcesses, mainThreadCpuMs } from './procCpu';

const RATE = Number(process.env.RATE ?? 4);
const IDLE_MS = 2000;

/** The page threads' CPU ms now, summed over the renderers. */
const pageThreadsMs = () => (chromiumProcesses().get('renderer') ?? []).reduce((s, pid) => s + mainThreadCpuMs(pid), 0);

async function main(): Promise<void> {
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH || (await findChromium()) || undefined,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu'],
  });
  try {
    const page = await browser.newPage();
    await page.goto('data:text/html,<p>idle</p>');
    const cdp = await page.context().newCDPSession(page);
    // The page's own start (parsing, first paint) is over by then.
    await page.waitForTimeout(1000);
    console.log(`load ${readFileSync('/proc/loadavg', 'utf8').trim()}`);
    for (const rate of [1, RATE, 1, RATE]) {
      await cdp.send('Emulation.setCPUThrottlingRate', { rate });
      await page.waitForTimeout(200);
      let c0 = pageThreadsMs();
      await page.waitForTimeout(IDLE_MS);
      const idle = pageThreadsMs() - c0;
      c0 = pageThreadsMs();
      const t0 = performance.now();
      await page.evaluate(() => {
        let s = 0;
        for (let i = 0; i < 1e8; i++) s += i % 7;
        return s;
      });
      const wall = performance.now() - t0;
      const busy = pageThreadsMs() - c0;
      console.log(
        `${rate}x: idle page thread ${idle.toFixed(0)} ms CPU in ${IDLE_MS} ms (${((100 * idle) / IDLE_MS).toFixed(0)} % of a core); a fixed loop ${wall.toFixed(0)} ms wall, ${busy.toFixed(0)} ms CPU`,
      );
    }
  } finally {
    await browser.close();
  }
}

void main();
