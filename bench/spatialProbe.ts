/**
 * Spatial page (issue 32) under a software WebGL: CPU time per drawn frame of Chromium's GPU process (where
 * SwiftShader rasterises) and of its renderer processes (the page's threads; of which its dedicated workers, the 3D
 * view's worker where it draws there), from /proc (bench/procCpu.ts), robust to a loaded machine in a way frames per
 * second are not. Builds given as SPATIAL_PROBE="name=distDir,name=distDir" are served side by side and measured
 * alternately, ROUNDS times (default 2), each during SECONDS of Play and of orbit (an ArrowRight on the view every
 * animation frame) at RATE x CPU (default 4; CDP throttling slows the page's main thread only, not workers).
 * SPATIAL_PROBE_QUERY adds to page=3d (say sk=rssr); SPATIAL_PROBE_PAGE=embed.html opens the widget. Linux only.
 * Prints a table; reports, never fails.
 * Run: SPATIAL_PROBE="before=/tmp/a,after=dist" npx vite-node bench/spatialProbe.ts
 */
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { chromium } from 'playwright';
import type { Browser } from 'playwright';
import { preview } from 'vite';
import { findChromium } from '../scripts/ensure-chromium.mjs';
import { chromiumCpu } from './procCpu';
import { orbitSpatialView } from './spatialOrbit';

const ROUNDS = Number(process.env.ROUNDS ?? 2);
const SECONDS = Number(process.env.SECONDS ?? 4);
const RATE = Number(process.env.RATE ?? 4);
const QUERY = process.env.SPATIAL_PROBE_QUERY ?? '';
/** The page to open: '' (the app) or 'embed.html' (the widget, whose panels= can hide the numbers and plots). */
const PAGE = process.env.SPATIAL_PROBE_PAGE ?? '';
const PORT0 = Number(process.env.BENCH_PORT ?? 4366);
interface Figures {
  fps: number;
  gpuMsPerFrame: number;
  rendererMsPerFrame: number;
  /** The renderers' dedicated worker threads (the 3D view's worker where it draws there). */
  workerMsPerFrame: number;
}

async function measure(browser: Browser, base: string): Promise<{ play: Figures; orbit: Figures }> {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
  try {
    const page = await context.newPage();
    const cdp = await context.newCDPSession(page);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: RATE });
    await page.goto(`${base}${PAGE}?page=3d${QUERY ? `&${QUERY}` : ''}`);
    await page.locator('.spatial-view[data-state="ready"]').waitFor({ timeout: 60_000 });
    await page.waitForTimeout(500);
    const canvas = page.getByTestId('spatial-canvas');
    const frames = () => canvas.evaluate((c: HTMLCanvasElement) => Number(c.dataset.frames ?? 0));
    const sample = async () => ({ f: await frames(), ...chromiumCpu(), t: performance.now() });
    const since = async (a: Awaited<ReturnType<typeof sample>>): Promise<Figures> => {
      const b = await sample();
      const n = Math.max(1, b.f - a.f);
      return {
        fps: ((b.f - a.f) * 1000) / (b.t - a.t),
        gpuMsPerFrame: (b.gpu - a.gpu) / n,
        rendererMsPerFrame: (b.renderer - a.renderer) / n,
        workerMsPerFrame: (b.workers - a.workers) / n,
      };
    };
    await page.getByRole('button', { name: 'Play' }).click();
    await page.waitForTimeout(300);
    let a = await sample();
    await page.waitForTimeout(SECONDS * 1000);
    const play = await since(a);
    await page.getByRole('button', { name: 'Pause' }).click();
    await page.waitForTimeout(500);
    a = await sample();
    await orbitSpatialView(page, SECONDS);
    const orbit = await since(a);
    return { play, orbit };
  } finally {
    await context.close();
  }
}

async function main(): Promise<void> {
  const variants = (process.env.SPATIAL_PROBE ?? 'dist=dist').split(',').map((s, i) => {
    const [name, dir] = s.split('=');
    return { name, dir: resolve(dir), port: PORT0 + i };
  });
  const servers = await Promise.all(
    variants.map((v) =>
      preview({ logLevel: 'error', build: { outDir: v.dir }, preview: { port: v.port, strictPort: true } }),
    ),
  );
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH || (await findChromium()) || undefined,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update'],
  });
  const f = (x: Figures) =>
    `${x.gpuMsPerFrame.toFixed(1).padStart(6)} ${x.rendererMsPerFrame.toFixed(1).padStart(6)} ${x.workerMsPerFrame.toFixed(1).padStart(6)} ${x.fps.toFixed(1).padStart(5)}`;
  console.log(`load ${readFileSync('/proc/loadavg', 'utf8').trim()}; ${RATE}x CPU; ${SECONDS} s each; query ${QUERY}`);
  console.log('variant       | Play: GPU ms/frame, renderer ms/frame (of which worker), fps | orbit: same');
  try {
    for (let round = 0; round < ROUNDS; round++) {
      for (const v of variants) {
        const r = await measure(browser, `http://localhost:${v.port}/`);
        console.log(`${v.name.padEnd(13)} | ${f(r.play)}                  | ${f(r.orbit)}`);
      }
    }
  } finally {
    console.log(`load ${readFileSync('/proc/loadavg', 'utf8').trim()}`);
    await browser.close();
    await Promise.all(servers.map((s) => s.close()));
  }
}

void main();
