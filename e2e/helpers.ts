import { csvParseRows } from 'd3-dsv';
import { mkdirSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Download, FrameLocator, Page } from '@playwright/test';
import { expect } from '@playwright/test';

/** Origin of the preview server the specs run against (E2E_PORT, as in playwright.config.ts). */
export const ORIGIN = `http://localhost:${process.env.E2E_PORT ?? 4173}`;

/** Where screenshots of the main views are saved (git-ignored). */
export const ARTIFACTS = join(dirname(fileURLToPath(import.meta.url)), 'artifacts');
mkdirSync(ARTIFACTS, { recursive: true });

/** Path of an artefact file. */
export function artifact(name: string): string {
  return join(ARTIFACTS, name);
}

/**
 * Waits until the app has its first cycle and pose (data-ready on the root layout); a test that throttles the CPU
 * from the first load gives a longer bound (a 6x page on a busy machine takes tens of seconds).
 */
export async function waitReady(page: Page | FrameLocator, timeout = 20_000): Promise<void> {
  await expect(page.locator('[data-ready="true"]')).toHaveCount(1, { timeout });
}

/**
 * Waits until the address bar shows the simulator page (no page key): the URL is rewritten 250 ms after the last
 * change, so a key the previous page also wrote (tg on the synthesis page) says nothing about the opened design.
 */
export async function waitSimulatorUrl(page: Page): Promise<URLSearchParams> {
  await expect.poll(() => new URL(page.url()).searchParams.get('page')).toBeNull();
  return new URL(page.url()).searchParams;
}

/** PNG facts from a file's bytes: the signature and the IHDR width and height. */
export interface PngFacts {
  signatureOk: boolean;
  width: number;
  height: number;
  bytes: number;
}

/** Reads a downloaded file and checks it is a PNG, returning its IHDR size. */
export async function pngFacts(download: Download): Promise<PngFacts> {
  const path = await download.path();
  const b = readFileSync(path);
  const sig = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];
  return {
    signatureOk: sig.every((v, i) => b[i] === v) && b.toString('latin1', 12, 16) === 'IHDR',
    width: b.readUInt32BE(16),
    height: b.readUInt32BE(20),
    bytes: b.length,
  };
}

/** Counts non-background pixels of the linkage canvas (a blank canvas gives 0). */
export async function inkedPixels(page: Page): Promise<number> {
  return page.locator('canvas.linkage-canvas').evaluate((c: HTMLCanvasElement) => {
    const ctx = c.getContext('2d');
    if (!ctx) return 0;
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 200 || d[i + 1] < 200 || d[i + 2] < 200) n++;
    return n;
  });
}

/** The 'd' attribute of the first solid series path of the n-th angle chart on the page. */
export async function chartPath(page: Page, n = 0): Promise<string> {
  return page
    .locator('svg.chart-svg')
    .nth(n)
    .evaluate((svg) => {
      const paths = [...svg.querySelectorAll('g.lines path')];
      const solid = paths.find((p) => !p.getAttribute('stroke-dasharray'));
      return solid?.getAttribute('d') ?? '';
    });
}

/**
 * The θ2 (degrees) of the linkage on screen, read in the page: the live stage's while its canvas shows (Play drawn in
 * a worker: its data-theta2), else the one the linkage canvas's label names (hundredths). Pass to page.evaluate, or
 * to a locator's evaluate to click its element right after reading (in the same task).
 */
export function shownTheta2InPage(thenClick?: unknown): number {
  const live = document.querySelector<HTMLCanvasElement>('canvas.linkage-live');
  const label = document.querySelector('canvas.linkage-canvas')?.getAttribute('aria-label') ?? '';
  const theta2 = live && !live.hidden ? Number(live.dataset.theta2) : Number(/θ2 (-?[\d.]+)°/.exec(label)?.[1]);
  if (thenClick instanceof HTMLElement) thenClick.click();
  return theta2;
}

/** A page whose browser has no OffscreenCanvas: the page draws Play itself (no live stage), as where workers cannot draw. */
export async function withoutLiveStage(page: Page): Promise<void> {
  await page.addInitScript(() => {
    delete (globalThis as { OffscreenCanvas?: unknown }).OffscreenCanvas;
  });
}

/** The θ2 slider's thumb position for an angle (page pixels): a mouse drag along it sets θ2. */
export async function theta2Slider(page: Page): Promise<{ x: (deg: number) => number; y: number }> {
  const box = await page.getByRole('slider', { name: /^θ2/ }).boundingBox();
  if (!box) throw new Error('θ2 slider has no box');
  // Chromium's thumb is 16 px wide: its centre runs from 8 px in to 8 px short of the track's ends.
  return { x: (deg) => box.x + 8 + ((box.width - 16) * deg) / 360, y: box.y + box.height / 2 };
}

// The coupler-point oracle of the synthesis specs: a placed four-bar read from the simulator's URL and its coupler
// curve, computed here independently of the app.

/** A point of the plane (length unit). */
export type Pt = { x: number; y: number };

/** A placed four-bar as the URL gives it: lengths, branch, coupler point (degrees), O2 and ground angle (degrees). */
export interface UrlDesign {
  r1: number;
  r2: number;
  r3: number;
  r4: number;
  open: boolean;
  pd: number;
  paDeg: number;
  ox: number;
  oy: number;
  ogDeg: number;
}

/** Degrees to radians. */
export const rad = (deg: number) => (deg * Math.PI) / 180;

/**
 * The coupler point at θ2 (radians), written here independently of the app: B is the intersection of the circles
 * about A (radius r3) and O4 (radius r4) left of the ray A→O4 (open) or right of it (crossed), P is read in the frame
 * of AB, and the whole is turned by the ground angle and moved to O2. Null where the circles do not meet.
 */
export function couplerPoint(d: UrlDesign, theta2: number): Pt | null {
  const A = { x: d.r2 * Math.cos(theta2), y: d.r2 * Math.sin(theta2) };
  const O4 = { x: d.r1, y: 0 };
  const dx = O4.x - A.x;
  const dy = O4.y - A.y;
  const s = Math.hypot(dx, dy);
  const a = (d.r3 * d.r3 - d.r4 * d.r4 + s * s) / (2 * s);
  const h2 = d.r3 * d.r3 - a * a;
  if (h2 < 0) return null;
  const h = Math.sqrt(h2) * (d.open ? 1 : -1);
  // Left of the ray A→O4 is the +90° turn of (dx, dy).
  const B = { x: A.x + (a * dx - h * dy) / s, y: A.y + (a * dy + h * dx) / s };
  const t3 = Math.atan2(B.y - A.y, B.x - A.x);
  const P = { x: A.x + d.pd * Math.cos(t3 + rad(d.paDeg)), y: A.y + d.pd * Math.sin(t3 + rad(d.paDeg)) };
  const g = rad(d.ogDeg);
  return { x: d.ox + Math.cos(g) * P.x - Math.sin(g) * P.y, y: d.oy + Math.sin(g) * P.x + Math.cos(g) * P.y };
}

/** Distance from t to the design's coupler curve: a fine sweep of θ2, then a golden-section refinement. */
export function distanceToCurve(d: UrlDesign, t: Pt): number {
  const dist = (th: number) => {
    const p = couplerPoint(d, th);
    return p ? Math.hypot(p.x - t.x, p.y - t.y) : Infinity;
  };
  const n = 20_000;
  let best = 0;
  for (let i = 1; i < n; i++) if (dist((2 * Math.PI * i) / n) < dist((2 * Math.PI * best) / n)) best = i;
  let lo = (2 * Math.PI * (best - 1)) / n;
  let hi = (2 * Math.PI * (best + 1)) / n;
  const k = (Math.sqrt(5) - 1) / 2;
  for (let i = 0; i < 80; i++) {
    const m1 = hi - k * (hi - lo);
    const m2 = lo + k * (hi - lo);
    if (dist(m1) < dist(m2)) hi = m2;
    else lo = m1;
  }
  return dist((lo + hi) / 2);
}

/** The design the simulator's URL holds. */
export function designOfUrl(url: string): UrlDesign {
  const q = new URL(url).searchParams;
  const n = (k: string, dflt = 0) => (q.has(k) ? Number(q.get(k)) : dflt);
  return {
    r1: n('r1'),
    r2: n('r2'),
    r3: n('r3'),
    r4: n('r4'),
    open: q.get('br') !== 'crossed',
    pd: n('pd'),
    paDeg: n('pa'),
    ox: n('ox'),
    oy: n('oy'),
    ogDeg: n('og'),
  };
}

/** A downloaded CSV's rows (d3-dsv's parser, not the app's writer), without the empty line after the last newline. */
export async function csvRowsOf(download: Download): Promise<string[][]> {
  return csvParseRows(readFileSync(await download.path(), 'utf8')).filter((r) => r.length > 1);
}
