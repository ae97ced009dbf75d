import { readFileSync, writeFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import { artifact, waitReady } from './helpers';
import { GifReader } from 'omggif';
import { gifFacts, videoDurationInBrowser, webmFacts } from './media';

/**
 * The Export panel's animation export, driven as a person does. The UI:
 * a group "Animation size" with radios "Screen" and "720p", a number input "Frames per cycle" (36..720),
 * a checkbox "Loop" (checked by default), buttons "Export animation GIF" and "Export animation WebM", and
 * while an export runs a progressbar "Animation export progress" with a "Cancel" button beside it; the
 * panel's status line says "cancelled" after Cancel.
 */

async function exportFile(page: Page, button: string): Promise<{ name: string; bytes: Uint8Array }> {
  const [d] = await Promise.all([
    page.waitForEvent('download', { timeout: 60_000 }),
    page.getByRole('button', { name: button }).click(),
  ]);
  return { name: d.suggestedFilename(), bytes: new Uint8Array(readFileSync(await d.path())) };
}

/** Decodes frame k of a GIF (omggif), paints it on a canvas in the page and saves a screenshot to look at. */
async function lookAtFrame(page: Page, bytes: Uint8Array, k: number, name: string): Promise<void> {
  const r = new GifReader(bytes);
  const rgba = new Uint8Array(r.width * r.height * 4);
  for (let i = 0; i <= k; i++) r.decodeAndBlitFrameRGBA(i, rgba);
  const canvas = await page.evaluateHandle(
    ({ b64, w, h }) => {
      const c = document.createElement('canvas');
      c.width = w;
      c.height = h;
      c.style.cssText = 'position:fixed;left:0;top:0;z-index:99999';
      const data = Uint8ClampedArray.from(atob(b64), (ch) => ch.charCodeAt(0));
      c.getContext('2d')?.putImageData(new ImageData(data, w, h), 0, 0);
      document.body.appendChild(c);
      return c;
    },
    { b64: Buffer.from(rgba).toString('base64'), w: r.width, h: r.height },
  );
  await canvas.asElement()?.screenshot({ path: artifact(name) });
  await canvas.evaluate((c) => (c as HTMLCanvasElement).remove());
}

async function setFrames(page: Page, n: number): Promise<void> {
  await page.getByRole('spinbutton', { name: 'Frames per cycle' }).fill(String(n));
  await page.getByRole('spinbutton', { name: 'Frames per cycle' }).press('Enter');
}

test.describe('animation export', () => {
  test('the GIF decodes to one cycle of frames at the screen size, looping', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const box = await page.locator('canvas.linkage-canvas').boundingBox();
    if (!box) throw new Error('no canvas');
    await setFrames(page, 36);
    const file = await exportFile(page, 'Export animation GIF');
    expect(file.name).toMatch(/\.gif$/);
    writeFileSync(artifact('animation-screen.gif'), file.bytes);
    await lookAtFrame(page, file.bytes, 9, 'animation-screen-frame9.png');
    const gif = gifFacts(file.bytes);
    expect(gif.frames).toBe(36);
    expect(gif.loopCount).toBe(0);
    // Screen size: the canvas's CSS size at devicePixelRatio 1, rounded to even pixels.
    expect(Math.abs(gif.width - box.width)).toBeLessThanOrEqual(2);
    expect(Math.abs(gif.height - box.height)).toBeLessThanOrEqual(2);
    expect(gif.bytes).toBeLessThan(4 * 1024 * 1024);
  });

  test('720p without loop gives a 1280x720 GIF that plays once', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('group', { name: 'Animation size' }).getByRole('radio', { name: '720p' }).check();
    await page.getByRole('checkbox', { name: 'Loop' }).uncheck();
    await setFrames(page, 36);
    const gif = gifFacts((await exportFile(page, 'Export animation GIF')).bytes);
    expect([gif.width, gif.height]).toEqual([1280, 720]);
    expect(gif.frames).toBe(36);
    expect(gif.loopCount).toBeNull();
  });

  test('a rocking input exports its back-and-forth as one cycle', async ({ page }) => {
    await page.goto('./?r1=4&r2=3&r3=3.5&r4=3');
    await waitReady(page);
    await setFrames(page, 48);
    const gif = gifFacts((await exportFile(page, 'Export animation GIF')).bytes);
    expect(gif.frames).toBe(48);
  });

  test('the WebM is a video with frames and a non-zero duration', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await setFrames(page, 36);
    const file = await exportFile(page, 'Export animation WebM');
    expect(file.name).toMatch(/\.webm$/);
    const webm = webmFacts(file.bytes);
    expect(webm.docType).toBe('webm');
    expect(webm.frames).toBeGreaterThan(0);
    expect(await videoDurationInBrowser(page, file.bytes, 'video/webm')).toBeGreaterThan(0);
  });

  test('Cancel stops a running export and says so', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await setFrames(page, 720);
    await page.getByRole('button', { name: 'Export animation GIF' }).click();
    const progress = page.getByRole('progressbar', { name: 'Animation export progress' });
    await expect(progress).toBeVisible();
    await page.getByRole('button', { name: 'Cancel' }).click();
    await expect(progress).toBeHidden();
    await expect(page.getByRole('status').filter({ hasText: /cancelled/i })).toBeVisible();
  });
});
