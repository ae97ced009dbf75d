import { expect, test } from '@playwright/test';
import { waitReady } from './helpers';

test.describe('the address bar', () => {
  test('follows the state in the app, but not while playing', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('slider', { name: /^θ2/ }).focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(() => new URL(page.url()).searchParams.get('t2')).toBe('46');
    await page.getByRole('button', { name: 'Play' }).click();
    const theta2 = page.getByRole('textbox', { name: /^θ2/ });
    await expect.poll(async () => Number(await theta2.inputValue())).toBeGreaterThan(50);
    // Still the paused value: no history write per frame.
    expect(new URL(page.url()).searchParams.get('t2')).toBe('46');
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect.poll(async () => Number(new URL(page.url()).searchParams.get('t2'))).toBeGreaterThan(50);
  });

  test('keeps the embed’s panels and locks while the widget’s state changes', async ({ page }) => {
    await page.goto('./embed.html?t2=60&panels=controls,info&lock=r1,r4');
    await waitReady(page);
    await page.getByRole('slider', { name: /^θ2/ }).focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(() => new URL(page.url()).searchParams.get('t2')).toBe('61');
    const params = new URL(page.url()).searchParams;
    expect(params.get('panels')).toBe('controls,info');
    expect(params.get('lock')).toBe('r1,r4');
  });
});
