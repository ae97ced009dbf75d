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

/**
 * Holds ArrowRight on the Spatial page's 3D view for seconds as a keyboard does: a press, then repeats (repeat: true)
 * 30 times a second, then the release. Where the view has its own clock (its worker), the repeats only keep the hold
 * alive and the view turns on its own frames.
 */
export async function holdSpatialKey(page: Page, seconds: number): Promise<void> {
  await page.locator('.spatial-canvas-host').evaluate(async (host: HTMLElement, s) => {
    const send = (type: 'keydown' | 'keyup', repeat: boolean) =>
      host.dispatchEvent(new KeyboardEvent(type, { key: 'ArrowRight', code: 'ArrowRight', repeat, bubbles: true }));
    send('keydown', false);
    await new Promise<void>((done) => {
      const start = performance.now();
      const timer = setInterval(() => {
        send('keydown', true);
        if (performance.now() - start >= s * 1000) {
          clearInterval(timer);
          done();
        }
      }, 1000 / 30);
    });
    send('keyup', false);
  }, seconds);
}
