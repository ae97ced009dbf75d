import type { Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { KNOWN as KNOWN_MOTION, knownPose } from '../tests/features/synthesis/motion/knownLinkage';
import type { Pt, UrlDesign } from './helpers';
import { artifact, couplerPoint, designOfUrl, rad, waitReady, waitSimulatorUrl } from './helpers';

// The synthesis page's print view (issue 34, item 12): in print media each mode prints one sheet, the task and the
// chosen design, with the panels' numbers and no controls, on one A4 and one Letter page, in en and zh-TW.

/** Pages in a PDF: its /Type /Page objects (not the /Pages tree). */
function pdfPages(pdf: Buffer): number {
  return (pdf.toString('latin1').match(/\/Type\s*\/Page(?!s)/g) ?? []).length;
}

/** A value the print view prints, by its key. */
async function printed(page: Page, key: string): Promise<string> {
  return (await page.locator(`[data-testid="synthesis-print"] [data-print="${key}"]`).innerText()).trim();
}

/** The cells of the print view's table rows (row header first). */
async function printedRows(page: Page): Promise<string[][]> {
  return page
    .locator('[data-testid="synthesis-print"] tr[data-print-row]')
    .evaluateAll((trs) => trs.map((tr) => [...tr.children].map((c) => (c.textContent ?? '').trim())));
}

/**
 * Into print media: the sheet shows, no control of the app is visible, nothing is cut off, and its PDF is one A4
 * page and one Letter page. Back to screen after.
 */
async function expectOneSheet(page: Page, name: string): Promise<void> {
  await page.emulateMedia({ media: 'print' });
  const sheet = page.getByTestId('synthesis-print');
  await expect(sheet).toBeVisible();
  await expect(sheet.locator('svg').first()).toBeVisible();
  const shownControls = await page.evaluate(() =>
    [...document.querySelectorAll('button, input, select, textarea, a[href], canvas')]
      .filter((el) => (el as HTMLElement).getClientRects().length > 0)
      .map((el) => el.outerHTML.slice(0, 80)),
  );
  expect(shownControls).toEqual([]);
  expect(await sheet.evaluate((el) => el.scrollHeight - el.clientHeight), 'cut off').toBeLessThanOrEqual(1);
  await page.screenshot({ path: artifact(`synthesis-print-${name}.png`), fullPage: true });
  for (const format of ['A4', 'Letter'] as const) expect(pdfPages(await page.pdf({ format })), format).toBe(1);
}

/** The known placed crank-rocker of synthesisPath.spec.ts, its coupler point 40° apart at six inputs. */
const KNOWN: UrlDesign = { r1: 5, r2: 1.5, r3: 4.5, r4: 4, open: true, pd: 3, paDeg: 40, ox: 2, oy: 1, ogDeg: 20 };
const SIX: Pt[] = Array.from({ length: 6 }, (_, k) => couplerPoint(KNOWN, rad(40 * k))!).map((p) => ({
  x: Number(p.x.toFixed(12)),
  y: Number(p.y.toFixed(12)),
}));

const WORDS = {
  en: { synthesize: 'Synthesize', open: 'Open in simulator', step: 'equal steps of 40.00°' },
  'zh-TW': { synthesize: '合成', open: '在模擬器中開啟', step: '等步距 40.00°' },
} as const;

for (const lang of ['en', 'zh-TW'] as const) {
  test(`Path (${lang}): the task, the chosen candidate with the panel's numbers, each target's distance, one page`, async ({
    page,
  }) => {
    test.setTimeout(180_000);
    const w = WORDS[lang];
    const tg = SIX.map((p) => `${p.x},${p.y}`).join(';');
    await page.goto(`./?page=syn&lang=${lang}&tg=${encodeURIComponent(tg)}&tm=step&ts=40&sd=1`);
    await page.getByRole('button', { name: w.synthesize, exact: true }).click();
    await expect(page.getByTestId('candidates')).toBeVisible({ timeout: 150_000 });
    // The panel's numbers: the chosen candidate's Σd² and max d (the list), its lengths (the chosen card).
    const first = page.getByTestId('candidates').getByRole('button').first();
    const listText = await first.innerText();
    const sum = /Σd² (\S+)/.exec(listText)![1];
    const maxD = /(?:max d|最大 d) (\S+)/.exec(listText)![1];
    const lengths = (await page.locator('.syn-cognate-detail').first().innerText()).split(' · ')[0];
    await expectOneSheet(page, `path-${lang}`);
    expect(await printed(page, 'error-sum')).toBe(sum);
    expect(await printed(page, 'max-distance')).toBe(maxD);
    expect(await printed(page, 'links')).toBe(`${lengths} m`);
    expect(await printed(page, 'length-unit')).toBe('m');
    expect(await printed(page, 'timing')).toBe(w.step);
    expect(await printed(page, 'seed')).toBe('1');
    expect(await printed(page, 'defects')).not.toBe('');
    // The targets as given, and where the design passes each: an exact fit exists, so every distance reads 0 or
    // below max d; θ2 steps 40° from target to target (the task's timing), as the oracle's design does.
    const rows = await printedRows(page);
    expect(rows.map((r) => r[0])).toEqual(SIX.map((_, i) => `T${i + 1}`));
    for (const [i, r] of rows.entries()) {
      expect(Number(r[1])).toBeCloseTo(SIX[i].x, 5);
      expect(Number(r[2])).toBeCloseTo(SIX[i].y, 5);
    }
    const theta2 = rows.map((r) => Number(r[3]));
    for (let i = 1; i < theta2.length; i++) {
      const step = (((theta2[i] - theta2[i - 1]) % 360) + 360) % 360;
      expect(Math.min(Math.abs(step - 40), Math.abs(step - 320)), `θ2 step ${i}`).toBeLessThan(0.02);
    }
    for (const r of rows)
      expect(Number(r[4].replace('\u2212', '-'))).toBeLessThanOrEqual(Number(maxD.replace('\u2212', '-')));
    // The coupler point and the placement printed are the design the simulator opens (URL: full precision).
    const coupler = await printed(page, 'coupler');
    const placement = await printed(page, 'placement');
    await page.emulateMedia({ media: 'screen' });
    await expect(page.getByTestId('synthesis-print')).toHaveCount(0);
    await page.getByRole('button', { name: w.open }).click();
    await waitReady(page);
    await waitSimulatorUrl(page);
    const d = designOfUrl(page.url());
    const nums = (s: string) => s.match(/[-−]?\d+(\.\d+)?(e[-−]?\d+)?/g)!.map((x) => Number(x.replace(/−/g, '-')));
    const [pd, pa] = nums(coupler);
    expect(pd).toBeCloseTo(d.pd, 3 - Math.ceil(Math.log10(d.pd)));
    expect(Math.abs(pa - d.paDeg)).toBeLessThan(0.006);
    const [ox, oy, og] = nums(placement.replace(/^O2/, ''));
    expect(Math.abs(ox - d.ox)).toBeLessThan(5e-4 * Math.max(1, Math.abs(d.ox)));
    expect(Math.abs(oy - d.oy)).toBeLessThan(5e-4 * Math.max(1, Math.abs(d.oy)));
    expect(Math.abs(((og - d.ogDeg + 540) % 360) - 180)).toBeLessThan(0.006);
  });
}

const poseText = (poses: { x: number; y: number; angleDeg: number }[]) =>
  poses.map((p) => `${p.x},${p.y},${p.angleDeg}`).join(';');

test('Motion, three poses (zh-TW): the design the panel shows, zero error at each pose, one page', async ({ page }) => {
  const three = [30, 100, 170].map((t) => knownPose(rad(t)));
  const pv = [KNOWN_MOTION.a, KNOWN_MOTION.b].map((p) => `${p.x},${p.y}`).join(';');
  await page.goto(
    `./?page=syn&syn=motion&lang=zh-TW&ps=${encodeURIComponent(poseText(three))}&pv=${encodeURIComponent(pv)}`,
  );
  const links = (await page.getByTestId('motion-links').innerText()).trim();
  const pivots = (await page.getByTestId('motion-pivots').innerText()).trim();
  await expectOneSheet(page, 'motion-zh-TW');
  expect(await printed(page, 'links')).toBe(`${links} m`);
  expect(await printed(page, 'pivots')).toBe(pivots);
  expect(await printed(page, 'poses')).toBe('3');
  // The known linkage meets the three poses exactly: position and angle errors print 0.
  const rows = await printedRows(page);
  expect(rows).toHaveLength(3);
  for (const r of rows) {
    expect(r[4]).toBe('0');
    expect(r[5]).toMatch(/^0\.00$/);
  }
});

test('Motion, eight poses: the error at each pose is the panel table’s, one page', async ({ page }) => {
  const eight = [10, 50, 90, 130, 170, 210, 250, 290].map((t) => knownPose(rad(t)));
  await page.goto(`./?page=syn&syn=motion&ps=${encodeURIComponent(poseText(eight))}`);
  await expect(page.getByTestId('motion-errors').locator('tbody tr')).toHaveCount(8);
  const panel = await page
    .getByTestId('motion-errors')
    .locator('tbody tr')
    .evaluateAll((trs) => trs.map((tr) => [...tr.children].map((c) => (c.textContent ?? '').trim())));
  expect(panel).toHaveLength(8);
  await expectOneSheet(page, 'motion-eight-en');
  const rows = await printedRows(page);
  expect(rows.map((r) => [r[0], r[4], r[5]])).toEqual(panel);
});

test('Function (en and zh-TW): the function, its ranges, the generator and its largest error as the card says, one page', async ({
  page,
}) => {
  for (const lang of ['en', 'zh-TW'] as const) {
    await page.emulateMedia({ media: 'screen' });
    await page.goto(`./?page=syn&syn=fn&lang=${lang}&fx=log10(x)&xr=1,10&t2r=30,90&t4r=-60,-150&np=3`);
    await expect(page.getByTestId('function-mode')).toHaveAttribute('data-ready', 'true');
    const links = (await page.locator('[data-testid="function-facts"] .synmode-links').innerText()).trim();
    const maxError = (await page.getByTestId('function-max-error').innerText()).trim();
    await expectOneSheet(page, `function-${lang}`);
    expect(await printed(page, 'links')).toBe(`${links} m`);
    expect(await printed(page, 'max-error')).toBe(maxError);
    expect(await printed(page, 'function')).toBe('log10(x)');
    expect(await printed(page, 'x-range')).toBe('1 … 10');
    expect(await printed(page, 'theta2-range')).toBe('30.00° … 90.00°');
    // Three precision points are exact: the generator's structural error at each is 0.
    const rows = await printedRows(page);
    expect(rows).toHaveLength(3);
    // Chebyshev spacing over [1, 10]: x_k = 5.5 − 4.5 cos((2k − 1)π / 6).
    for (const [k, r] of rows.entries()) {
      expect(Number(r[1])).toBeCloseTo(5.5 - 4.5 * Math.cos(((2 * k + 1) * Math.PI) / 6), 4);
      expect(r[4]).toBe('0');
    }
  }
});

test('Nine points before a run: the nine points and the note, one page', async ({ page }) => {
  await page.goto('./?page=syn&syn=nine');
  await page.getByRole('button', { name: /^Example: Problem 3/ }).click();
  await expectOneSheet(page, 'nine-en');
  expect(await printedRows(page)).toHaveLength(9);
  expect(await printed(page, 'note')).toMatch(/No design yet/);
});
