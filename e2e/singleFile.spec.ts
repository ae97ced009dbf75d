import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import { ORIGIN, csvRowsOf, waitReady } from './helpers';

// The offline file from `npm run build:single` (npm run test:e2e builds it first).
const SINGLE = join(dirname(fileURLToPath(import.meta.url)), '..', 'dist-single', 'fourbar-lab.html');

async function changeR3AndExportCsv(page: Page): Promise<string[][]> {
  const r3 = page.getByRole('textbox', { name: /^r3/ });
  await r3.fill('4.5');
  await r3.press('Enter');
  await expect(page.getByRole('img', { name: /^Linkage view\./ })).toBeVisible();
  const [d] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'Export cycle CSV' }).click(),
  ]);
  expect(d.suggestedFilename()).toBe('fourbar_6-2-4.5-5_open_cycle_n360.csv');
  const rows = await csvRowsOf(d);
  return rows;
}

test.describe('the offline single file', () => {
  test.beforeAll(() => {
    if (!existsSync(SINGLE)) throw new Error(`${SINGLE} is missing: run npm run build:single`);
  });

  test('is one file: no script, stylesheet or worker loaded from anywhere else', () => {
    const html = readFileSync(SINGLE, 'utf8');
    expect(html).not.toMatch(/<script[^>]*\ssrc=/);
    expect(html).not.toMatch(/<link[^>]*rel="(stylesheet|modulepreload)"/);
    expect(html).not.toMatch(/solver\.worker[^"']*\.js/);
    expect(html).not.toMatch(/stage\.worker[^"']*\.js/);
  });

  test('runs from file://, solves in its inline worker, takes a new r3 and exports the CSV', async ({ page }) => {
    const errors: string[] = [];
    const requests: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('request', (r) => requests.push(r.url()));
    await page.goto(`file://${SINGLE}`);
    await waitReady(page);
    const rows = await changeR3AndExportCsv(page);
    const header = rows[0];
    expect(header.slice(0, 3)).toEqual(['theta2_deg', 'theta3_deg', 'theta4_deg']);
    expect(header).toContain('omega4_rad_s');
    expect(rows).toHaveLength(362);
    // r1=6, r2=2, r3=4.5, r4=5 is a Grashof crank-rocker: every row of the cycle assembles.
    const status = header.indexOf('status');
    expect(rows.slice(1).every((r) => r[status] === 'ok')).toBe(true);
    expect(Number(rows[91][0])).toBe(90);
    // The worker from the inline blob answered: no fall-back to the main thread.
    await expect(page.getByText(/main thread/)).toHaveCount(0);
    expect(requests.filter((u) => !/^(file|blob|data):/.test(u))).toEqual([]);
    expect(errors).toEqual([]);
  });

  test('plays from file:// with Play drawn in its inline live stage worker', async ({ page }) => {
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`file://${SINGLE}`);
    await waitReady(page);
    await page.getByRole('button', { name: 'Play' }).click();
    const live = page.locator('canvas.linkage-live');
    await expect(live).toBeVisible();
    const first = await live.getAttribute('data-theta2');
    await expect.poll(() => live.getAttribute('data-theta2')).not.toBe(first);
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(live).toBeHidden();
    expect(errors).toEqual([]);
  });

  test('runs as a Moodle file resource: the same file served by the course site inside an iframe', async ({ page }) => {
    const host = `${ORIGIN}/moodle/mod/resource/view.php`;
    const file = `${ORIGIN}/moodle/pluginfile.php/42/mod_resource/content/1/fourbar-lab.html`;
    await page.route(file, (route) => route.fulfill({ contentType: 'text/html', body: readFileSync(SINGLE, 'utf8') }));
    await page.route(host, (route) =>
      route.fulfill({
        contentType: 'text/html',
        body: `<!doctype html><html><head><title>Resource</title></head><body>
<iframe id="resourceobject" title="fourbar-lab.html" src="${file}" width="1200" height="760"></iframe></body></html>`,
      }),
    );
    await page.goto(host);
    const frame = page.frameLocator('#resourceobject');
    await waitReady(frame);
    const r3 = frame.getByRole('textbox', { name: /^r3/ });
    await r3.fill('4.5');
    await r3.press('Enter');
    await expect(frame.getByRole('img', { name: /^Linkage view\./ })).toBeVisible();
    await expect(frame.getByText(/main thread/)).toHaveCount(0);
  });
  test('from file:// says its links work only on this computer and offers no embed code', async ({ page }) => {
    await page.goto(`file://${SINGLE}?r3=4.5`);
    await waitReady(page);
    await expect(page.getByTestId('offline-share')).toContainText('This is the offline file');
    await expect(page.getByRole('button', { name: 'Copy embed code' })).toHaveCount(0);
    await expect(page.getByText('Embed generator: size, panels, locks, preview')).toHaveCount(0);
    await page.getByRole('button', { name: 'Copy link (this computer only)' }).click();
    // The clipboard may be refused in a headless file page: either way the link is shown to copy by hand.
    const link = await page.getByRole('textbox', { name: 'Share and embed' }).inputValue();
    expect(link).toMatch(/^file:\/\/.*fourbar-lab\.html\?r1=6&r2=2&r3=4\.5&/);
  });
});
