import type { Page } from 'playwright';

/** Orbits the Spatial page's 3D view for seconds: one ArrowRight on its host per animation frame, as a held key does. */
export async function orbitSpatialView(page: Page, seconds: number): Promise<void> {
  await page.locator('.spatial-canvas-host').evaluate(async (host: HTMLElement, s) => {
    const start = performance.now();
    await new Promise<void>((done) => {
      const tick = (t: number) => {
        host.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowRight', bubbles: true }));
        if (t - start < s * 1000) requestAnimationFrame(tick);
        else done();
      };
      requestAnimationFrame(tick);
    });
  }, seconds);
}
