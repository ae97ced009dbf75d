import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';

/** Clicks an export button and returns the download's name and bytes. */
async function download(page: Page, name: string): Promise<{ file: string; bytes: Buffer }> {
  const [d] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name }).click()]);
  return { file: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
}

const PNG_SIGNATURE = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);

// Every synthesis mode exports its canvas as SVG (the same drawing through the SVG context) and PNG (2x).
for (const [mode, testId, fileBase] of [
  ['motion', 'motion-mode', 'synthesis-motion'],
  ['fn', 'function-mode', 'synthesis-function'],
] as const) {
  test(`the ${mode} canvas exports as SVG and PNG`, async ({ page }) => {
    await page.goto(`./?page=syn&syn=${mode}`);
    await expect(page.getByTestId(testId)).toBeVisible();
    if (mode === 'fn') await expect(page.getByTestId(testId)).toHaveAttribute('data-ready', 'true');
    // On the canvas, not clipped under it.
    for (const name of ['Export picture SVG', 'Export picture PNG'])
      await expect(page.getByRole('button', { name })).toBeInViewport({ ratio: 1 });
    const svg = await download(page, 'Export picture SVG');
    expect(svg.file).toBe(`${fileBase}.svg`);
    const text = svg.bytes.toString('utf8');
    expect(text).toMatch(/^<svg[^>]+xmlns="http:\/\/www\.w3\.org\/2000\/svg"/);
    // A real picture: the grid's lines and the drawing's paths, no NaN coordinates.
    expect((text.match(/<path|<line|<polyline/g) ?? []).length).toBeGreaterThan(10);
    expect(text).not.toContain('NaN');
    const png = await download(page, 'Export picture PNG');
    expect(png.file).toBe(`${fileBase}.png`);
    expect(png.bytes.subarray(0, 8).equals(PNG_SIGNATURE)).toBe(true);
    // IHDR width: twice the canvas's CSS width.
    const canvasWidth = await page
      .getByTestId(mode === 'fn' ? 'function-canvas' : 'motion-canvas')
      .evaluate((c) => (c as HTMLCanvasElement).getBoundingClientRect().width);
    expect(png.bytes.readUInt32BE(16)).toBe(Math.round(Math.floor(canvasWidth) * 2));
  });
}
