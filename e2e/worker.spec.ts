import { expect, test } from '@playwright/test';
import type { Page, Worker } from '@playwright/test';
import { chartPath, waitReady } from './helpers';

/**
 * Kills the solver worker the hardest way to notice: close() inside it, so it stops without an error
 * event and every later request just vanishes. Uses Playwright's handle on the worker, so the app
 * ships no test hook. Resolves once the worker is gone.
 */
async function killWorker(worker: Worker): Promise<void> {
  const gone = new Promise<void>((resolve) => worker.once('close', () => resolve()));
  // The evaluation may or may not report back before the worker goes: either way it is closing.
  await worker.evaluate(() => (globalThis as unknown as { close(): void }).close()).catch(() => undefined);
  await gone;
}

/**
 * Holds the solver worker's script until release() is called: until then no worker exists, so whatever the page
 * shows was solved on the main thread.
 */
async function holdWorkerScript(page: Page): Promise<() => void> {
  let release = () => {};
  const held = new Promise<void>((resolve) => (release = resolve));
  await page.route(/solver\.worker[^/]*\.js$/, async (route) => {
    await held;
    await route.continue().catch(() => undefined);
  });
  return release;
}

/** Whether a worker is the solver's (a slow page may also have started the live stage's worker). */
const isSolver = (w: Worker) => /solver\.worker/.test(w.url());

/** The solver workers the page runs now. */
const solverWorkers = (page: Page) => page.workers().filter(isSolver);

/** The one solver worker the page runs now. */
function onlyWorker(page: Page): Worker {
  const workers = solverWorkers(page);
  expect(workers).toHaveLength(1);
  return workers[0];
}

// The watchdog needs a call's budget (a few seconds) to notice a silent worker: allow for it.
const RECOVERY = { timeout: 20_000 };

test.describe('a dying solver worker', () => {
  test('is restarted once, then replaced by the main thread, and the views keep updating', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const grashof = page.getByTestId('grashof-sums');
    await expect(grashof).toContainText('S + L = 8 < P + Q = 10');
    const plotBefore = await chartPath(page, 0);

    await killWorker(onlyWorker(page));
    const restarted = page.waitForEvent('worker', { predicate: isSolver });
    await page.getByRole('textbox', { name: /^r3/ }).fill('5.5');
    await expect(page.getByRole('status').filter({ hasText: 'The solver worker stopped; restarted it.' })).toHaveCount(
      1,
      RECOVERY,
    );
    await expect(grashof).toContainText('P + Q = 10.5', RECOVERY);
    await expect.poll(() => chartPath(page, 0)).not.toBe(plotBefore);
    await page.getByRole('textbox', { name: /^θ2/ }).fill('120');
    await expect(page.getByRole('heading', { name: 'At θ2 = 120.00°' })).toBeVisible();

    const second = await restarted;
    const plotRestarted = await chartPath(page, 0);
    await killWorker(second);
    await page.getByRole('textbox', { name: /^θ2/ }).fill('200');
    await page.getByRole('textbox', { name: /^r3/ }).fill('4.5');
    await expect(
      page.getByRole('status').filter({ hasText: 'Solving on the main thread: the worker stopped twice.' }),
    ).toHaveCount(1, RECOVERY);
    await expect(page.getByRole('heading', { name: 'At θ2 = 200.00°' })).toBeVisible(RECOVERY);
    await expect(grashof).toContainText('S + L = 8 < P + Q = 9.5', RECOVERY);
    await expect.poll(() => chartPath(page, 0)).not.toBe(plotRestarted);
    expect(solverWorkers(page)).toHaveLength(0);
  });

  test('says so in Traditional Chinese too', async ({ page }) => {
    await page.goto('./?lang=zh-TW');
    await waitReady(page);
    await killWorker(onlyWorker(page));
    await page.getByRole('textbox', { name: /^r3/ }).fill('5.5');
    await expect(
      page.getByRole('status').filter({ hasText: '求解用的背景執行緒（Worker）停止了，已重新啟動。' }),
    ).toHaveCount(1, RECOVERY);
    await expect(page.getByTestId('grashof-sums')).toContainText('P + Q = 10.5', RECOVERY);
  });
});

test.describe('the first load', () => {
  test('is ready with the first cycle and pose solved on the main thread, before the worker has loaded', async ({
    page,
  }) => {
    // The first answers (the pose's NR runs, the cycle's classification and numbers) and data-ready must come
    // without the worker; later requests go to it once it is there.
    const release = await holdWorkerScript(page);
    try {
      await page.goto('./?t2=45');
      await waitReady(page);
      await expect(page.getByTestId('nr-iterations')).toHaveText(/^\d+$/);
      await expect(page.getByTestId('linkage-type')).toHaveText('Crank-rocker');
      await expect(page.getByRole('img', { name: /Linkage view\. θ2 45\.00°, θ3 44\.18°/ })).toBeVisible();
      expect(solverWorkers(page)).toHaveLength(0);
      // Not the client's fallback (it starts only after the worker fails to answer, and says so).
      await expect(page.getByText('Web Worker unavailable here: solving on the main thread.')).toHaveCount(0);
    } finally {
      release();
    }
    // The page goes on once the worker has loaded.
    await page.getByRole('textbox', { name: /^r3/ }).fill('5.5');
    await expect(page.getByTestId('grashof-sums')).toContainText('P + Q = 10.5');
  });
});

test.describe('the plots', () => {
  test('are solved on the main thread: they draw and follow r3 while the worker has not even loaded', async ({
    page,
  }) => {
    // The worker is never asked for plot samples.
    const release = await holdWorkerScript(page);
    try {
      await page.goto('./');
      await expect.poll(() => chartPath(page, 0)).toMatch(/^M[\d.]+,[\d.]+L/);
      const before = await chartPath(page, 0);
      await page.getByRole('textbox', { name: /^r3/ }).fill('5.5');
      await expect.poll(() => chartPath(page, 0)).not.toBe(before);
    } finally {
      release();
    }
    await waitReady(page);
    await expect(page.getByTestId('grashof-sums')).toContainText('P + Q = 10.5');
  });
});
