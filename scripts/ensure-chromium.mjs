#!/usr/bin/env node
// Finds a Chromium for Playwright, or installs one, and says what it did.
// Order: $CHROMIUM_PATH, a system Chromium on PATH, Playwright's own download,
// then Debian's package (apt-get, needs root). Prints the path; exits 1 if none.
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { pathToFileURL } from 'node:url';

const SYSTEM_NAMES = ['chromium', 'chromium-browser', 'google-chrome-stable', 'google-chrome'];

function onPath(name) {
  const r = spawnSync('sh', ['-c', `command -v ${name}`], { encoding: 'utf8' });
  const p = r.stdout.trim();
  return r.status === 0 && p && existsSync(p) ? p : null;
}

function systemChromium() {
  const env = process.env.CHROMIUM_PATH;
  if (env && existsSync(env)) return env;
  for (const name of SYSTEM_NAMES) {
    const p = onPath(name);
    if (p) return p;
  }
  return null;
}

async function playwrightChromium() {
  try {
    const { chromium } = await import('playwright');
    const p = chromium.executablePath();
    return p && existsSync(p) ? p : null;
  } catch {
    return null;
  }
}

function tryRun(cmd, args) {
  console.log(`[ensure-chromium] running: ${cmd} ${args.join(' ')}`);
  const r = spawnSync(cmd, args, { stdio: 'inherit', timeout: 15 * 60_000 });
  return r.status === 0;
}

/** Returns a Chromium executable path, installing one if needed; null if impossible. */
export async function findChromium({ install = false } = {}) {
  const found = systemChromium() ?? (await playwrightChromium());
  if (found || !install) return found;
  if (tryRun('npx', ['playwright', 'install', 'chromium'])) {
    const p = await playwrightChromium();
    if (p) return p;
  }
  console.log('[ensure-chromium] Playwright could not download a browser; trying the system package manager');
  const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
  const sudo = isRoot ? [] : onPath('sudo') ? ['sudo', '-n'] : null;
  if (sudo && onPath('apt-get')) {
    const run = (args) =>
      sudo.length ? tryRun(sudo[0], [...sudo.slice(1), 'apt-get', ...args]) : tryRun('apt-get', args);
    if (run(['install', '-y', 'chromium']) || (run(['update']) && run(['install', '-y', 'chromium']))) {
      return systemChromium();
    }
  }
  return null;
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) {
  const before = systemChromium() ?? (await playwrightChromium());
  const path = await findChromium({ install: true });
  if (!path) {
    console.error('[ensure-chromium] no Chromium found and none could be installed; set CHROMIUM_PATH');
    process.exit(1);
  }
  let version = '';
  try {
    version = execFileSync(path, ['--version'], { encoding: 'utf8' }).trim();
  } catch {
    version = 'version unknown';
  }
  console.log(`[ensure-chromium] ${before ? 'found' : 'installed'} ${path} (${version})`);
}
