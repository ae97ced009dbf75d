import type { Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { artifact, waitReady } from './helpers';

// The printable report (issue 19): in print media the page is one report, with no controls, made of the same
// numbers the panels show, and the browser's PDF of it is exactly one A4 or Letter page, in both languages.

const WORDS = {
  en: { print: 'Print report', pdf: /Save as PDF/, title: 'Four-bar linkage report' },
  'zh-TW': { print: '列印報告', pdf: /另存為 PDF/, title: '四連桿機構報告' },
} as const;

/** Pages in a PDF: its /Type /Page objects (not the /Pages tree). */
function pdfPages(pdf: Buffer): number {
  return (pdf.toString('latin1').match(/\/Type\s*\/Page(?!s)/g) ?? []).length;
}

/** The text of a panel value by its test id, as the screen shows it. */
async function panel(page: Page, testId: string): Promise<string> {
  return (await page.getByTestId(testId).innerText()).trim();
}

/** The report's value of a key. */
async function report(page: Page, key: string): Promise<string> {
  return (await page.locator(`[data-testid="print-report"] [data-report="${key}"]`).innerText()).trim();
}

for (const lang of ['en', 'zh-TW'] as const) {
  const w = WORDS[lang];

  test(`the printed report (${lang}): no controls, the panels' numbers, one A4 and one Letter page`, async ({
    page,
  }) => {
    await page.goto(`./?lang=${lang}&t2=45`);
    await waitReady(page);
    // On screen: the button, its PDF note, and no report.
    await expect(page.getByRole('button', { name: w.print })).toBeVisible();
    await expect(page.getByText(w.pdf)).toBeVisible();
    await expect(page.getByTestId('print-report')).toHaveCount(0);
    // The panels' numbers, read before printing.
    const numbers = {
      'grashof-sums': await panel(page, 'grashof-sums'),
      'linkage-type': await panel(page, 'linkage-type'),
      omega3: await panel(page, 'motion-omega3'),
      omega4: await panel(page, 'motion-omega4'),
      alpha3: await panel(page, 'motion-alpha3'),
      alpha4: await panel(page, 'motion-alpha4'),
    };
    const muMin = await panel(page, 'design-mu-min');
    const extendedAt = await panel(page, 'design-dc-extended-at');
    const foldedTheta4 = await panel(page, 'design-dc-folded-theta4');
    const timeRatio = await panel(page, 'design-time-ratio');
    const analysis = page.getByRole('region', { name: lang === 'en' ? 'Analysis' : '分析' });
    const theta3 = (await analysis.locator('.fact', { hasText: /^θ3/ }).locator('dd').innerText()).trim();
    const mu = (await analysis.locator('.fact').nth(6).locator('dd').innerText()).trim();

    await page.emulateMedia({ media: 'print' });
    const sheet = page.getByTestId('print-report');
    await expect(sheet).toBeVisible();
    await expect(sheet.getByRole('heading', { level: 1 })).toHaveText(w.title);
    // The figure (the canvas's drawing with r1..r4) and the chosen plots (θ3 and θ4) are SVG drawings.
    const figure = sheet.locator('.report-figure svg');
    await expect(figure).toBeVisible();
    // Each label is drawn twice, its white halo and its text.
    for (const r of ['r1', 'r2', 'r3', 'r4'])
      expect(await figure.locator('text', { hasText: new RegExp(`^${r}$`) }).count(), r).toBeGreaterThan(0);
    await expect(sheet.locator('[data-report="lengths"]')).toContainText('r1 = 6, r2 = 2, r3 = 5, r4 = 5');
    await expect(sheet.locator('.report-plot svg')).toHaveCount(2);
    // The same numbers as the panels.
    for (const [key, value] of Object.entries(numbers)) expect(await report(page, key), key).toBe(value);
    expect(await report(page, 'theta3')).toBe(theta3);
    expect(await report(page, 'mu')).toBe(mu);
    expect(await report(page, 'mu-min')).toContain(muMin);
    expect(await report(page, 'dc-extended')).toContain(extendedAt);
    expect(await report(page, 'dc-folded')).toContain(foldedTheta4);
    expect(await report(page, 'time-ratio')).toBe(timeRatio);
    // No control of the app is shown: no button, field, slider or menu.
    const shownControls = await page.evaluate(() =>
      [...document.querySelectorAll('button, input, select, textarea, a[href]')]
        .filter((el) => (el as HTMLElement).getClientRects().length > 0)
        .map((el) => el.outerHTML.slice(0, 80)),
    );
    expect(shownControls).toEqual([]);
    // Nothing of the report is cut off by its one-page box (PrintReport.css clips what would not fit).
    expect(await sheet.evaluate((el) => el.scrollHeight - el.clientHeight)).toBeLessThanOrEqual(1);
    await page.screenshot({ path: artifact(`print-${lang}.png`), fullPage: true });
    for (const format of ['A4', 'Letter'] as const) {
      const pdf = await page.pdf({ format });
      expect(pdfPages(pdf), format).toBe(1);
    }
    // Back on screen, the report goes.
    await page.emulateMedia({ media: 'screen' });
    await expect(page.getByTestId('print-report')).toHaveCount(0);
  });
}

test('the report prints the chosen plots: the velocity plot when velocities are shown', async ({ page }) => {
  await page.goto('./?plot=vel&plots=together');
  await waitReady(page);
  await page.emulateMedia({ media: 'print' });
  const sheet = page.getByTestId('print-report');
  await expect(sheet).toBeVisible();
  await expect(sheet.locator('.report-plot svg')).toHaveCount(1);
  await expect(sheet.locator('.report-plot svg text', { hasText: /^ω3/ }).first()).toBeAttached();
  expect(await sheet.evaluate((el) => el.scrollHeight - el.clientHeight)).toBeLessThanOrEqual(1);
  const pdf = await page.pdf({ format: 'A4' });
  expect(pdfPages(pdf)).toBe(1);
});
