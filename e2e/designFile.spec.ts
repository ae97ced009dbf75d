import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import { artifact, waitReady } from './helpers';

/** The value of a URL parameter in the address bar (which follows the state, debounced). */
function urlParam(page: Page, key: string): string | null {
  return new URL(page.url()).searchParams.get(key);
}

/** Chooses files in the Open design file chooser, the way a person does. */
async function openDesign(page: Page, file: string | { name: string; mimeType: string; buffer: Buffer }) {
  const chooser = page.waitForEvent('filechooser');
  await page.getByRole('button', { name: 'Open design' }).click();
  await (await chooser).setFiles(file);
}

/** A file payload for the chooser. */
function jsonFile(name: string, text: string) {
  return { name, mimeType: 'application/json', buffer: Buffer.from(text) };
}

test.describe('design files', () => {
  test('Save writes <name>.fourbar.json with the whole work, and Open gives it back', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const r1 = page.getByRole('textbox', { name: /^r1/ });
    await r1.fill('7');
    await page.getByRole('combobox', { name: 'ω2 unit' }).selectOption('rpm');
    await page.getByRole('textbox', { name: /^ω2/ }).fill('120');
    await page.getByRole('checkbox', { name: 'Grid' }).uncheck();
    await expect.poll(() => urlParam(page, 'w2u')).toBe('rpm');

    const download = page.waitForEvent('download');
    await page.getByRole('button', { name: 'Save design' }).click();
    const saved = await download;
    expect(saved.suggestedFilename()).toBe('fourbar_7-2-5-5_open.fourbar.json');
    const path = artifact('saved.fourbar.json');
    await saved.saveAs(path);
    const file = JSON.parse(readFileSync(path, 'utf8'));
    expect(file).toMatchObject({ format: 'fourbar-lab.design', version: 1, name: 'fourbar_7-2-5-5_open' });
    expect(file.state).toMatchObject({ r1: 7, w2u: 'rpm', grid: false, t2: 45 });
    expect(file.state.w2).toBeCloseTo((120 * 2 * Math.PI) / 60, 12);
    await expect(
      page.getByRole('status').filter({ hasText: 'Saved fourbar_7-2-5-5_open.fourbar.json.' }),
    ).toBeVisible();

    // Change everything that was saved, then open the file.
    await r1.fill('8');
    await page.getByRole('combobox', { name: 'ω2 unit' }).selectOption('rad/s');
    await page.getByRole('checkbox', { name: 'Grid' }).check();
    await expect.poll(() => urlParam(page, 'r1')).toBe('8');
    await openDesign(page, path);
    await expect(page.getByRole('status').filter({ hasText: 'Opened “fourbar_7-2-5-5_open”.' })).toBeVisible();
    await expect(r1).toHaveValue('7');
    await expect(page.getByRole('combobox', { name: 'ω2 unit' })).toHaveValue('rpm');
    await expect(page.getByRole('textbox', { name: /^ω2/ })).toHaveValue('120');
    await expect(page.getByRole('checkbox', { name: 'Grid' })).not.toBeChecked();
    await expect.poll(() => urlParam(page, 'r1')).toBe('7');

    // Opening is one undo step.
    await page.getByRole('button', { name: 'Undo', exact: true }).click();
    await expect(r1).toHaveValue('8');

    // The design is in the recent list, with its time.
    await page.getByRole('button', { name: 'Recent' }).click();
    const recent = page.getByRole('list', { name: 'Recent designs' });
    await expect(recent.getByRole('button')).toHaveCount(1);
    await recent.getByRole('button', { name: /^fourbar_7-2-5-5_open, / }).click();
    await expect(r1).toHaveValue('7');
  });

  test('a corrupt file gives a message naming it and keeps the work', async ({ page }) => {
    await page.goto('./?r1=6.5');
    await waitReady(page);
    const r1 = page.getByRole('textbox', { name: /^r1/ });
    await openDesign(page, jsonFile('broken.fourbar.json', '{"format": "fourbar-lab.design", "version": 1, "sta'));
    const alert = page.getByTestId('design-alert');
    await expect(alert).toHaveText(
      /“broken\.fourbar\.json” was not opened: it is not JSON\. Your current work is unchanged\./,
    );
    await expect(r1).toHaveValue('6.5');
    await expect(page.getByRole('button', { name: 'Undo', exact: true })).toBeDisabled();
    await page.screenshot({ path: artifact('design-file-corrupt-1280.png') });
    await alert.getByRole('button', { name: 'Close' }).click();
    await expect(alert).toBeEmpty();
  });

  test('a bad field and a newer version are named, and nothing is applied', async ({ page }) => {
    await page.goto('./?r1=6.5');
    await waitReady(page);
    const r1 = page.getByRole('textbox', { name: /^r1/ });
    const alert = page.getByTestId('design-alert');
    const bad = { format: 'fourbar-lab.design', version: 1, name: 'bad', state: { r1: 9, r2: -1, br: 'sideways' } };
    await openDesign(page, jsonFile('bad.fourbar.json', JSON.stringify(bad)));
    await expect(alert).toContainText('state.r2 is -1');
    await expect(alert).toContainText('state.br is "sideways": expected open or crossed');
    await expect(r1).toHaveValue('6.5');
    const newer = { ...bad, version: 2, state: { r1: 9 } };
    await openDesign(page, jsonFile('newer.fourbar.json', JSON.stringify(newer)));
    await expect(alert).toContainText('newer version of the app (file version 2; this app reads up to 1)');
    await expect(r1).toHaveValue('6.5');
  });

  test('the last session is offered on a plain start, restored, and not offered for a share link', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await expect(page.getByTestId('restore-offer')).toHaveCount(0);
    await page.getByRole('textbox', { name: /^r1/ }).fill('7.5');
    await page.getByRole('combobox', { name: 'ω2 unit' }).selectOption('deg/s');
    await expect
      .poll(() => page.evaluate(() => localStorage.getItem('fourbar-lab.autosave') ?? ''))
      .toMatch(/"w2u": "deg"/);

    // A share link shows no offer, and opening the app writes no autosave before a change: the clock is moved on
    // past the autosave's debounce (fake timers), and the last session is still the one kept.
    await page.clock.install();
    await page.goto('./?r1=3');
    await waitReady(page);
    await expect(page.getByTestId('restore-offer')).toHaveCount(0);
    await page.clock.fastForward(5000);
    await expect(page.getByRole('textbox', { name: /^r1/ })).toHaveValue('3');
    expect(await page.evaluate(() => localStorage.getItem('fourbar-lab.autosave') ?? '')).toMatch(/"w2u": "deg"/);

    await page.goto('./');
    await waitReady(page);
    const offer = page.getByRole('region', { name: 'Restore last session' });
    await expect(offer).toBeVisible();
    await expect(page.getByRole('textbox', { name: /^r1/ })).toHaveValue('6');
    await page.screenshot({ path: artifact('restore-offer-1280.png') });
    await offer.getByRole('button', { name: 'Restore last session' }).click();
    await expect(page.getByRole('textbox', { name: /^r1/ })).toHaveValue('7.5');
    await expect(page.getByRole('combobox', { name: 'ω2 unit' })).toHaveValue('deg/s');
    await expect(offer).toHaveCount(0);

    // Dismissed, it goes away and the work stays as it is.
    await page.evaluate(() =>
      localStorage.setItem(
        'fourbar-lab.autosave',
        JSON.stringify({ format: 'fourbar-lab.design', version: 1, name: 'old', state: { r1: 9 } }),
      ),
    );
    await page.goto('./');
    await waitReady(page);
    await expect(offer).toContainText('old');
    await offer.getByRole('button', { name: 'Dismiss' }).click();
    await expect(offer).toHaveCount(0);
    await expect(page.getByRole('textbox', { name: /^r1/ })).toHaveValue('6');
  });
});

test.describe('the design bar on a phone', () => {
  test.use({ viewport: { width: 390, height: 844 }, hasTouch: true });

  for (const lang of ['en', 'zh-TW'] as const) {
    test(`is in reach at 390×844 and saves and opens (${lang})`, async ({ page }) => {
      const names =
        lang === 'en'
          ? { save: 'Save design', open: 'Open design', undo: 'Undo', theta2: /^θ2/ }
          : { save: '儲存設計', open: '開啟設計', undo: '復原', theta2: /^θ2/ };
      await page.goto(`./?lang=${lang}`);
      await waitReady(page);
      for (const name of [names.save, names.open, names.undo]) {
        const box = await page.getByRole('button', { name, exact: true }).boundingBox();
        expect(box, name).not.toBeNull();
        // On screen without scrolling, and big enough for a finger (40 CSS px).
        expect(box!.y + box!.height).toBeLessThanOrEqual(844);
        expect(box!.x + box!.width).toBeLessThanOrEqual(390);
        expect(Math.min(box!.width, box!.height)).toBeGreaterThanOrEqual(40);
      }
      const theta2 = page.getByRole('textbox', { name: names.theta2 }).first();
      await theta2.fill('100');
      await expect.poll(() => urlParam(page, 't2')).toBe('100');
      const download = page.waitForEvent('download');
      await page.getByRole('button', { name: names.save, exact: true }).tap();
      const path = artifact(`phone-${lang}.fourbar.json`);
      await (await download).saveAs(path);
      await theta2.fill('200');
      await expect.poll(() => urlParam(page, 't2')).toBe('200');
      const chooser = page.waitForEvent('filechooser');
      await page.getByRole('button', { name: names.open, exact: true }).tap();
      await (await chooser).setFiles(path);
      await expect(theta2).toHaveValue('100');
      await page.screenshot({ path: artifact(`design-bar-390-${lang}.png`) });
    });
  }
});
