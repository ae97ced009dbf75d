import { createServer } from 'node:http';
import type { Server } from 'node:http';
import { readFileSync, statSync } from 'node:fs';
import { extname, join, normalize } from 'node:path';
import { gzipSync } from 'node:zlib';
import type { Browser } from 'playwright';

/**
 * The first load on a student's phone: a cold load (fresh context, empty cache) of the built app at 390x844,
 * RTT 150 ms, 1.6 Mbit/s down, 750 kbit/s up, 4x CPU slowdown, every text file served gzip -9 by a small static
 * server of our own (vite preview does not compress). The time is from navigation start to the moment the app says
 * it is ready (`data-ready="true"`: the cycle and the pose have answered and the linkage is drawn).
 */
export const PHONE_PROFILE = {
  viewport: { width: 390, height: 844 },
  latencyMs: 150,
  downloadBitsPerS: 1.6e6,
  uploadBitsPerS: 750e3,
  cpuSlowdown: 4,
} as const;

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.svg': 'image/svg+xml',
  '.json': 'application/json',
  '.png': 'image/png',
  '.ico': 'image/x-icon',
  '.webmanifest': 'application/manifest+json',
};
const COMPRESSIBLE = new Set(['.html', '.js', '.css', '.svg', '.json', '.webmanifest']);

/** Serves dir on port with gzip -9 for text files (cached per file); resolves once listening. */
export function gzipStaticServer(dir: string, port: number): Promise<Server> {
  const cache = new Map<string, Buffer>();
  const server = createServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname);
    const rel = normalize(path.endsWith('/') ? `${path}index.html` : path).replace(/^([/\\])+/, '');
    const file = join(dir, rel);
    if (!file.startsWith(dir) || !statSync(file, { throwIfNoEntry: false })?.isFile()) {
      res.writeHead(404).end();
      return;
    }
    const ext = extname(file);
    const headers: Record<string, string> = { 'content-type': TYPES[ext] ?? 'application/octet-stream' };
    let body: Buffer = readFileSync(file);
    if (COMPRESSIBLE.has(ext) && /\bgzip\b/.test(String(req.headers['accept-encoding'] ?? ''))) {
      let gz = cache.get(file);
      if (!gz) cache.set(file, (gz = gzipSync(body, { level: 9 })));
      body = gz;
      headers['content-encoding'] = 'gzip';
    }
    res.writeHead(200, headers).end(body);
  });
  return new Promise((resolve) => server.listen(port, () => resolve(server)));
}

/** One cold load of url on the phone profile: ms from navigation start to data-ready, and the bytes transferred. */
export async function phoneColdLoad(browser: Browser, url: string): Promise<{ readyMs: number; transferKB: number }> {
  const context = await browser.newContext({
    viewport: PHONE_PROFILE.viewport,
    deviceScaleFactor: 3,
    isMobile: true,
    hasTouch: true,
    locale: 'en-US',
  });
  // The page notes when the app first says it is ready, in its own clock (ms since navigation start).
  await context.addInitScript(() => {
    const w = window as unknown as { __readyMs?: number };
    new MutationObserver((_records, observer) => {
      if (document.querySelector('.app[data-ready="true"]')) {
        w.__readyMs = performance.now();
        observer.disconnect();
      }
    }).observe(document, { subtree: true, childList: true, attributes: true, attributeFilter: ['data-ready'] });
  });
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send('Network.enable');
  await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
  await cdp.send('Network.emulateNetworkConditions', {
    offline: false,
    latency: PHONE_PROFILE.latencyMs,
    downloadThroughput: PHONE_PROFILE.downloadBitsPerS / 8,
    uploadThroughput: PHONE_PROFILE.uploadBitsPerS / 8,
  });
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: PHONE_PROFILE.cpuSlowdown });
  let transfer = 0;
  cdp.on('Network.loadingFinished', (e: { encodedDataLength: number }) => (transfer += e.encodedDataLength));
  await page.goto(url);
  await page.locator('.app[data-ready="true"]').waitFor({ timeout: 120_000 });
  await page.waitForFunction(() => (window as unknown as { __readyMs?: number }).__readyMs !== undefined);
  const readyMs = await page.evaluate(() => (window as unknown as { __readyMs: number }).__readyMs);
  await context.close();
  return { readyMs, transferKB: transfer / 1024 };
}
