import type { Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { artifact, pngFacts, waitReady } from './helpers';

/** Waits until the lab shows a finished study (data-ready on the lab root). */
async function waitLab(page: Page): Promise<void> {
  await expect(page.getByTestId('solver-lab')).toHaveAttribute('data-ready', 'true', { timeout: 90_000 });
}

/** Distinct method colours among the diagram's markers: one per method drawn. */
async function methodsDrawn(page: Page): Promise<number> {
  return page.getByTestId('work-precision').evaluate((svg) => {
    const fills = new Set<string>();
    for (const el of svg.querySelectorAll('g.markers [data-method]')) fills.add(el.getAttribute('data-method') ?? '');
    return fills.size;
  });
}

test.describe('the solver lab', () => {
  test('draws a work-precision diagram of at least four methods on the default linkage', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('tab', { name: 'Solver lab' }).click();
    await waitLab(page);
    expect(await methodsDrawn(page)).toBeGreaterThanOrEqual(4);
    const rows = page.locator('table.lab-table tbody tr');
    expect(await rows.count()).toBeGreaterThanOrEqual(4);
    // The report's linkage: no failures, no branch jumps, no false convergence for any default.
    for (const cell of await page.locator('table.lab-table td.bad').all()) expect(await cell.textContent()).toBe('0');
    await expect(page.getByTestId('lab-limit')).toHaveText('The crank turns fully: no input limit.');
    await page.screenshot({ path: artifact('lab.png') });
  });

  test('paints both panels of the cycle chart over its background', async ({ page }) => {
    await page.goto('./?page=lab');
    await waitLab(page);
    const chart = page.locator('.lab-cycle svg.chart-svg');
    await chart.scrollIntoViewIfNeeded();
    // What a person sees at the middle of each plot belongs to that panel, not to a background laid over it.
    const hits = await chart.evaluate((svg) =>
      ['panel-top', 'panel-bottom'].map((cls) => {
        const r = svg.querySelector(`svg.${cls} g.plot`)?.getBoundingClientRect();
        const el = r ? document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2) : null;
        return el?.closest(`svg.${cls}`) ? cls : `covered by ${el?.getAttribute('class')}`;
      }),
    );
    expect(hits).toEqual(['panel-top', 'panel-bottom']);
  });

  test('re-runs on a near-toggle hard case and still shows every method', async ({ page }) => {
    await page.goto('./?page=lab');
    await waitLab(page);
    await page.getByRole('button', { name: /^2\. Near toggle/ }).click();
    await expect(page.getByRole('textbox', { name: /^r4/ })).toHaveValue('2.000000001');
    await expect(page.getByTestId('solver-lab')).toHaveAttribute('data-ready', 'false');
    await waitLab(page);
    expect(await methodsDrawn(page)).toBeGreaterThanOrEqual(4);
    await page.screenshot({ path: artifact('lab-near-toggle.png') });
  });

  test('the method chosen in the lab changes the main view’s iteration counts', async ({ page }) => {
    await page.goto('./?page=lab');
    await waitLab(page);
    const summary = page.getByText(/NR iterations in all/);
    const before = await summary.textContent();
    await page.getByRole('combobox', { name: 'Method' }).selectOption('seed');
    await expect(summary).not.toHaveText(before ?? '');
    const count = (s: string | null) => Number(/(\d+) NR iterations/.exec(s ?? '')?.[1]);
    // The report's NR needs about 2.5 iterations a point, the polished continuation about 1.1.
    expect(count(await summary.textContent())).toBeGreaterThan(count(before));
    await page.getByRole('combobox', { name: 'Method' }).selectOption('closed-form');
    await expect(summary).toHaveText(/ 0 NR iterations/);
    // The choice is part of the shared state.
    await expect.poll(() => new URL(page.url()).searchParams.get('m')).toBe('closed-form');
  });

  test('exports the diagram as a PNG and its data as CSV', async ({ page }) => {
    await page.goto('./?page=lab');
    await waitLab(page);
    const [png] = await Promise.all([
      page.waitForEvent('download'),
      page.getByRole('button', { name: 'Export diagram PNG' }).click(),
    ]);
    expect(png.suggestedFilename()).toBe('fourbar_6-2-5-5_open_work-precision_step1_2x.png');
    const facts = await pngFacts(png);
    expect(facts.signatureOk).toBe(true);
    expect([facts.width, facts.height]).toEqual([1520, 920]);
    const [csv] = await Promise.all([
      page.waitForEvent('download'),
      page.getByRole('button', { name: 'Export diagram CSV' }).click(),
    ]);
    expect(csv.suggestedFilename()).toBe('fourbar_6-2-5-5_open_work-precision_step1.csv');
    const lines = readFileSync(await csv.path(), 'utf8')
      .trim()
      .split('\n');
    expect(lines[0]).toBe(
      'method,tolerance,ns_per_point,iterations_per_point,max_error_rad,p99_error_rad,failed,wrong_branch,false_convergence,points,step_deg',
    );
    // Five methods, three of them traced over five tolerances: 5 defaults + 15 tolerance rows.
    expect(lines).toHaveLength(1 + 20);
    expect(lines.join('\n')).not.toMatch(/NaN|Infinity/);
  });

  test('reads in Traditional Chinese', async ({ page }) => {
    await page.goto('./?page=lab&lang=zh-TW');
    await waitLab(page);
    await expect(page.getByRole('tab', { name: '求解器實驗室' })).toHaveAttribute('aria-selected', 'true');
    await page.screenshot({ path: artifact('lab-zh-TW.png') });
  });

  test('cancels a running study and keeps the page usable', async ({ page }) => {
    await page.goto('./?page=lab&lstep=0.1');
    await expect(page.getByRole('button', { name: 'Cancel' })).toBeVisible({ timeout: 20_000 });
    await page.getByRole('button', { name: 'Cancel' }).click();
    await expect(page.getByText('Cancelled. The last finished result stays on screen.')).toBeVisible();
    await expect(page.getByRole('button', { name: /^Run/ })).toBeEnabled();
  });
});
