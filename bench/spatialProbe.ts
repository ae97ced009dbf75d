/**
 * Spatial page (issue 32) under a software WebGL: CPU time per drawn frame of Chromium's GPU process (where
 * SwiftShader rasterises) and of its renderer processes (the page's threads), from /proc/<pid>/stat, robust to a
 * loaded machine in a way frames per second are not. Builds given as SPATIAL_PROBE="name=distDir,name=distDir" are
 * served side by side and measured alternately, ROUNDS times (default 2), each during SECONDS of Play and of orbit
 * (an ArrowRight on the view every animation frame) at RATE x CPU (default 4; CDP throttling slows the page's main
 * thread only). SPATIAL_PROBE_QUERY adds to page=3d (say sk=rssr); SPATIAL_PROBE_PAGE=embed.html opens the widget. Linux only. Prints a table; reports, never fails.
 * Run: SPATIAL_PROBE="before=/tmp/a,after=dist" npx vite-node bench/spatialProbe.ts
 */
import { readFileSync, readdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { chromium } from 'playwright';
import type { Browser } from 'playwright';
import { preview } from 'vite';
import { findChromium } from '../scripts/ensure-chromium.mjs';
import { orbitSpatialView } from './spatialOrbit';

const ROUNDS = Number(process.env.ROUNDS ?? 2);
const SECONDS = Number(process.env.SECONDS ?? 4);
const RATE = Number(process.env.RATE ?? 4);
const QUERY = process.env.SPATIAL_PROBE_QUERY ?? '';
/** The page to open: '' (the app) or 'embed.html' (the widget, whose panels= can hide the numbers and plots). */
const PAGE = process.env.SPATIAL_PROBE_PAGE ?? '';
const PORT0 = Number(process.env.BENCH_PORT ?? 4366);
const CLK_TCK = 100;

/** utime + stime (ms) of a process, 0 when it is gone. */
function cpuMs(pid: number): number {
  try {
    const stat = readFileSync(`/proc/${pid}/stat`, 'utf8');
    const f = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    return ((Number(f[11]) + Number(f[12])) * 1000) / CLK_TCK;
  } catch {
    return 0;
  }
}

/** This process's descendants by their Chromium --type (gpu-process, renderer, ...). */
function chromiumProcesses(): Map<string, number[]> {
  const parent = new Map<number, number>();
  for (const name of readdirSync('/proc')) {
    if (!/^\d+$/.test(name)) continue;
    try {
      const stat = readFileSync(`/proc/${name}/stat`, 'utf8');
      parent.set(Number(name), Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1]));
    } catch {
      /* gone */
    }
  }
  const mine = (pid: number): boolean => {
    for (let p = pid, n = 0; p > 1 && n < 50; p = parent.get(p) ?? 0, n++) if (p === process.pid) return true;
    return false;
  };
  const out = new Map<string, number[]>();
  for (const pid of parent.keys()) {
    if (pid === process.pid || !mine(pid)) continue;
    let cmd = '';
    try {
      cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8');
    } catch {
      continue;
    }
    const type = /--type=([\w-]+)/.exec(cmd)?.[1] ?? 'browser';
    out.set(type, [...(out.get(type) ?? []), pid]);
  }
  return out;
}

interface Figures {
  fps: number;
  gpuMsPerFrame: number;
  rendererMsPerFrame: number;
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
    const sample = async () => {
      const procs = chromiumProcesses();
      const sum = (type: string) => (procs.get(type) ?? []).reduce((s, pid) => s + cpuMs(pid), 0);
      return { f: await frames(), gpu: sum('gpu-process'), renderer: sum('renderer'), t: performance.now() };
    };
    const since = async (a: Awaited<ReturnType<typeof sample>>): Promise<Figures> => {
      const b = await sample();
      const n = Math.max(1, b.f - a.f);
      return {
        fps: ((b.f - a.f) * 1000) / (b.t - a.t),
        gpuMsPerFrame: (b.gpu - a.gpu) / n,
        rendererMsPerFrame: (b.renderer - a.renderer) / n,
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
    `${x.gpuMsPerFrame.toFixed(1).padStart(6)} ${x.rendererMsPerFrame.toFixed(1).padStart(6)} ${x.fps.toFixed(1).padStart(5)}`;
  console.log(`load ${readFileSync('/proc/loadavg', 'utf8').trim()}; ${RATE}x CPU; ${SECONDS} s each; query ${QUERY}`);
  console.log('variant       | Play: GPU ms/frame, renderer ms/frame, fps | orbit: same');
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
