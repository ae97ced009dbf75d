import { expect, test } from '@playwright/test';
import type { Locator, Page } from '@playwright/test';
import { artifact, theta2Slider, waitReady, withoutLiveStage } from './helpers';

/** A joint's position in page pixels, from the canvas's data-* attribute (CSS pixels inside the canvas). */
async function joint(canvas: Locator, name: 'o2' | 'a'): Promise<{ x: number; y: number }> {
  const box = await canvas.boundingBox();
  const v = await canvas.getAttribute(`data-${name}`);
  if (!box || !v) throw new Error(`no ${name} on the canvas`);
  const [x, y] = v.split(',').map(Number);
  return { x: box.x + x, y: box.y + y };
}

/** The value of a URL parameter in the address bar (which follows the state, debounced). */
function urlParam(page: Page, key: string): string | null {
  return new URL(page.url()).searchParams.get(key);
}

const undoButton = (page: Page) => page.getByRole('button', { name: 'Undo', exact: true });
const redoButton = (page: Page) => page.getByRole('button', { name: 'Redo', exact: true });

test.describe('undo and redo', () => {
  test('start disabled, with accessible names', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await expect(undoButton(page)).toBeDisabled();
    await expect(redoButton(page)).toBeDisabled();
    await expect(page.getByRole('group', { name: 'Design file and history' })).toBeVisible();
  });

  test('one Ctrl+Z undoes a whole canvas drag of A, to θ2 exactly; Ctrl+Shift+Z and Ctrl+Y redo it', async ({
    page,
  }) => {
    await page.goto('./?t2=45.123456789');
    await waitReady(page);
    const theta2 = page.getByRole('textbox', { name: /^θ2/ });
    await expect(theta2).toHaveValue('45.12');
    const canvas = page.locator('canvas.linkage-canvas');
    const o2 = await joint(canvas, 'o2');
    const a = await joint(canvas, 'a');
    const r = Math.hypot(a.x - o2.x, a.y - o2.y);
    await page.mouse.move(a.x, a.y);
    await page.mouse.down();
    // Forty moves along an arc to 150°: forty state changes in one gesture. Half way the hand holds A still for
    // longer than a burst (BURST_MS, 1 s): the pause is part of the gesture under test, not a wait for the app.
    for (let i = 1; i <= 40; i++) {
      const deg = 45 + (105 * i) / 40;
      const rad = (deg * Math.PI) / 180;
      await page.mouse.move(o2.x + r * Math.cos(rad), o2.y - r * Math.sin(rad));
      if (i === 20) await page.waitForTimeout(1300);
    }
    await page.mouse.up();
    // The last move is at 150° (to a pixel); the moves before it are at most 147.4°, so this waits for the end.
    await expect.poll(() => Number(urlParam(page, 't2'))).toBeGreaterThan(149);
    const dragged = urlParam(page, 't2');
    await expect(undoButton(page)).toBeEnabled();
    await page.keyboard.press('Control+z');
    await expect.poll(() => urlParam(page, 't2')).toBe('45.123456789');
    await expect(theta2).toHaveValue('45.12');
    // The drag was one step: nothing is left to undo.
    await expect(undoButton(page)).toBeDisabled();
    await expect(redoButton(page)).toBeEnabled();
    await page.keyboard.press('Control+Shift+Z');
    await expect.poll(() => urlParam(page, 't2')).toBe(dragged);
    await page.keyboard.press('Control+z');
    await expect.poll(() => urlParam(page, 't2')).toBe('45.123456789');
    await page.keyboard.press('Control+y');
    await expect.poll(() => urlParam(page, 't2')).toBe(dragged);
  });

  test('undoes a typed length in one step, and leaves Ctrl+Z inside a field to the browser', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const crossed = page.getByRole('radio', { name: 'Crossed' });
    await crossed.check();
    // Ctrl+Z in a text field is the browser's: the app's history does not move (React renders a key's
    // dispatch before the key event ends, so a wrong undo would show at once as an enabled Redo).
    const r3 = page.getByRole('textbox', { name: /^r3/ });
    await r3.focus();
    await page.keyboard.press('Control+z');
    await expect(redoButton(page)).toBeDisabled();
    await expect(crossed).toBeChecked();
    const r2 = page.getByRole('textbox', { name: /^r2/ });
    await r2.click();
    await r2.selectText();
    // Typed key by key: "2", "2.", "2.7", "2.75" reach the state one by one.
    await page.keyboard.type('2.75', { delay: 30 });
    await expect.poll(() => urlParam(page, 'r2')).toBe('2.75');
    await r2.blur();
    await page.keyboard.press('Control+z');
    await expect(r2).toHaveValue('2');
    await expect(crossed).toBeChecked();
    await expect.poll(() => urlParam(page, 'r2')).toBe('2');
    await page.keyboard.press('Control+z');
    await expect(page.getByRole('radio', { name: 'Open' })).toBeChecked();
    await expect(undoButton(page)).toBeDisabled();
    await redoButton(page).click();
    await redoButton(page).click();
    await expect(r2).toHaveValue('2.75');
    await expect(crossed).toBeChecked();
    await expect(redoButton(page)).toBeDisabled();
  });

  test('undoes a slider drag in one step and steps back through separate edits', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const box = await page.getByRole('slider', { name: /^r3/ }).boundingBox();
    if (!box) throw new Error('r3 slider has no box');
    const y = box.y + box.height / 2;
    await page.mouse.move(box.x + box.width * 0.25, y);
    await page.mouse.down();
    for (let i = 1; i <= 20; i++) await page.mouse.move(box.x + box.width * (0.25 + i * 0.01), y);
    await page.mouse.up();
    const r3 = page.getByRole('textbox', { name: /^r3/ });
    await expect(r3).not.toHaveValue('5');
    const dragged = await r3.inputValue();
    await page.getByRole('radio', { name: 'Crossed' }).check();
    await expect.poll(() => urlParam(page, 'br')).toBe('crossed');
    await undoButton(page).click();
    await expect.poll(() => urlParam(page, 'br')).toBe('open');
    await expect(r3).toHaveValue(dragged);
    await undoButton(page).click();
    await expect(r3).toHaveValue('5');
    await expect(undoButton(page)).toBeDisabled();
  });

  test('a θ2 slider drag shows each value at once, commits the last on release as one undo step, and hands the canvas back', async ({
    page,
  }) => {
    // The page draws the drag itself here (on a slow page the live stage would: app.spec's 6x drag).
    await withoutLiveStage(page);
    await page.goto('./?t2=45');
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    // The crank's angle as drawn: from O2 to A on the canvas (y grows downwards), degrees in [0, 360).
    const drawnTheta2 = async () => {
      const o2 = await joint(canvas, 'o2');
      const a = await joint(canvas, 'a');
      const deg = (Math.atan2(o2.y - a.y, a.x - o2.x) * 180) / Math.PI;
      return (deg + 360) % 360;
    };
    const field = page.getByRole('textbox', { name: /^θ2/ });
    const { x, y } = await theta2Slider(page);
    await page.mouse.move(x(45), y);
    await page.mouse.down();
    // The field and the canvas show each value as the input event that brought it is handled: read at once, not
    // polled (the app state, which commits a few times a second, would lag by moves of 5°).
    for (let deg = 50; deg <= 130; deg += 5) {
      await page.mouse.move(x(deg), y);
      const shown = Number(await field.inputValue());
      expect(Math.abs(shown - deg)).toBeLessThan(2);
      expect(Math.abs((await drawnTheta2()) - shown)).toBeLessThan(0.5);
    }
    await page.mouse.up();
    const dragged = Number(await field.inputValue());
    // The state (address bar, results) ends at the value on screen.
    await expect.poll(() => Number(urlParam(page, 't2'))).toBeCloseTo(dragged, 1);
    // One undo step back to where the drag started, drawn there.
    await undoButton(page).click();
    await expect(field).toHaveValue('45');
    await expect.poll(drawnTheta2).toBeCloseTo(45, 0);
    await expect(undoButton(page)).toBeDisabled();
    // The canvas follows the state again: a typed θ2 is drawn.
    await field.fill('200');
    await field.press('Enter');
    await expect.poll(drawnTheta2).toBeCloseTo(200, 0);
  });

  test('Play frames, the language and the view are not undo steps', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const theta2 = page.getByRole('textbox', { name: /^θ2/ });
    await page.getByRole('button', { name: 'Play' }).click();
    await expect.poll(async () => Number(await theta2.inputValue())).toBeGreaterThan(50);
    await page.getByRole('button', { name: 'Pause' }).click();
    await page.getByRole('button', { name: 'Zoom in' }).click();
    await expect.poll(() => urlParam(page, 'z')).not.toBeNull();
    await expect(undoButton(page)).toBeDisabled();
    await page.screenshot({ path: artifact('undo-bar-1280.png') });
    await page.getByRole('combobox', { name: 'Language' }).selectOption('zh-TW');
    await expect(page.getByRole('button', { name: '復原', exact: true })).toBeDisabled();
    await expect(page.getByRole('button', { name: '重做', exact: true })).toBeDisabled();
    await page.screenshot({ path: artifact('undo-bar-1280-zh-TW.png') });
  });
});
