import { expect, test } from '@playwright/test';
import type { Locator, Page } from '@playwright/test';
import { artifact, waitReady } from './helpers';

/** A joint's position in page pixels, from the canvas's data-* attribute (CSS pixels inside the canvas). */
async function joint(canvas: Locator, name: 'o2' | 'a' | 'p'): Promise<{ x: number; y: number }> {
  const box = await canvas.boundingBox();
  const v = await canvas.getAttribute(`data-${name}`);
  if (!box || !v) throw new Error(`no ${name} on the canvas`);
  const [x, y] = v.split(',').map(Number);
  return { x: box.x + x, y: box.y + y };
}

async function drag(page: Page, from: { x: number; y: number }, to: { x: number; y: number }): Promise<void> {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(to.x, to.y, { steps: 12 });
  await page.mouse.up();
}

test.describe('the linkage canvas', () => {
  test('dragging the crank pin A with the mouse sets θ2 to where it points', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    const o2 = await joint(canvas, 'o2');
    const a = await joint(canvas, 'a');
    const r = Math.hypot(a.x - o2.x, a.y - o2.y);
    // 120° counter-clockwise from the ground line (screen y points down).
    const to = { x: o2.x + r * Math.cos((120 * Math.PI) / 180), y: o2.y - r * Math.sin((120 * Math.PI) / 180) };
    await drag(page, a, to);
    // A pixel of rounding at this radius is well under a degree.
    const theta2 = Number(await page.getByRole('textbox', { name: /^θ2/ }).inputValue());
    expect(Math.abs(theta2 - 120)).toBeLessThan(1);
    await expect(page.getByRole('img', { name: /^Linkage view\. θ2 1[12]\d\.\d\d°/ })).toBeVisible();
    const aAfter = await joint(canvas, 'a');
    expect(Math.hypot(aAfter.x - to.x, aAfter.y - to.y)).toBeLessThan(2);
  });

  test('dragging P moves the coupler point to the pointer', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    const p = await joint(canvas, 'p');
    const a = await joint(canvas, 'a');
    // Pull P straight away from A by half again its distance.
    const to = { x: a.x + 1.5 * (p.x - a.x), y: a.y + 1.5 * (p.y - a.y) };
    await drag(page, p, to);
    const field = page.getByRole('textbox', { name: /^P distance/ });
    await expect(field).not.toHaveValue('2.5');
    const distance = Number(await field.inputValue());
    // Same direction, 1.5 times as far: 3.75 (to a pixel), angle still 30°.
    expect(Math.abs(distance - 3.75)).toBeLessThan(0.05);
    const angle = Number(await page.getByRole('textbox', { name: /^P angle/ }).inputValue());
    expect(Math.abs(angle - 30)).toBeLessThan(1);
  });

  test('a locked θ2 in the embed cannot be dragged or turned on the canvas', async ({ page }) => {
    await page.goto('./embed.html?t2=60&panels=controls&lock=theta2');
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    const o2 = await joint(canvas, 'o2');
    const a = await joint(canvas, 'a');
    await drag(page, a, { x: o2.x - (a.x - o2.x), y: a.y });
    await canvas.focus();
    await page.keyboard.press('ArrowRight');
    await expect(canvas).toHaveAccessibleName(/θ2 60\.00°/);
    await expect(canvas).not.toHaveAccessibleDescription(/turn the crank/);
  });

  test('dragging an empty spot pans the view', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    const box = await canvas.boundingBox();
    if (!box) throw new Error('no canvas box');
    const from = { x: box.x + 20, y: box.y + box.height - 20 };
    await drag(page, from, { x: from.x + box.width / 10, y: from.y });
    await expect.poll(() => Number(new URL(page.url()).searchParams.get('px'))).toBeCloseTo(0.1, 2);
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('45');
  });

  test('a two-finger pinch zooms the view on a phone', async ({ browser }) => {
    const context = await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
    const page = await context.newPage();
    await page.goto(`${test.info().project.use.baseURL}`);
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    await canvas.scrollIntoViewIfNeeded();
    const box = await canvas.boundingBox();
    if (!box) throw new Error('no canvas box');
    const cdp = await context.newCDPSession(page);
    const cx = box.x + box.width / 2;
    const cy = box.y + box.height * 0.8;
    const touch = (type: 'touchStart' | 'touchMove' | 'touchEnd', d: number) =>
      cdp.send('Input.dispatchTouchEvent', {
        type,
        touchPoints:
          type === 'touchEnd'
            ? []
            : [
                { x: cx - d, y: cy, id: 1 },
                { x: cx + d, y: cy, id: 2 },
              ],
      });
    await touch('touchStart', 20);
    for (let d = 25; d <= 60; d += 5) await touch('touchMove', d);
    await touch('touchEnd', 60);
    // Fingers three times as far apart: three times the zoom, kept in the address bar.
    await expect.poll(() => Number(new URL(page.url()).searchParams.get('z'))).toBeCloseTo(3, 1);
    await page.screenshot({ path: artifact('canvas-pinch-390.png') });
    await context.close();
  });
});
