import { expect, test } from '@playwright/test';
import { ORIGIN, artifact, waitReady } from './helpers';

// A course page that embeds the widget in a sandboxed iframe without allow-same-origin: the frame gets an
// opaque origin (no storage, no clipboard, no worker from its own server, module scripts fetched with CORS).
// The page is routed on the preview server's host because Chromium's local-network-access checks stop a
// public origin from framing localhost; the sandbox makes the frame cross-origin all the same.
const HOST = `${ORIGIN}/e2e-course/week3.html`;
const SRC = `${ORIGIN}/embed.html?r1=6&r2=2&r3=5&r4=5&t2=60&panels=controls,info,plots&lock=r1,r4`;

test.describe('the embed widget', () => {
  test('renders and works inside <iframe sandbox="allow-scripts">', async ({ page }) => {
    await page.route(HOST, (route) =>
      route.fulfill({
        contentType: 'text/html',
        body: `<!doctype html><html><head><title>Week 3</title></head><body style="font-family:sans-serif;margin:24px">
<h1>Week 3: four-bar linkages</h1><p>Drag the crank angle and watch the rocker.</p>
<iframe id="sim" title="Four-bar linkage simulator" sandbox="allow-scripts" src="${SRC}" width="900" height="640" style="border:1px solid #ccc"></iframe>
</body></html>`,
      }),
    );
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(HOST);
    const frame = page.frameLocator('#sim');
    await waitReady(frame);
    await expect(frame.getByRole('img', { name: /^Linkage view\. θ2 60\.00°/ })).toBeVisible();
    await expect(frame.getByRole('textbox', { name: /^r1/ })).toBeDisabled();
    await expect(frame.getByRole('textbox', { name: /^r2/ })).toBeEnabled();
    await expect(frame.getByTestId('linkage-type')).toHaveText('Crank-rocker');
    await expect(frame.getByText('Web Worker unavailable here: solving on the main thread.')).toBeVisible();
    // It still solves: move theta2 with the keyboard and the pose follows.
    await frame.getByRole('slider', { name: /^θ2/ }).focus();
    for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowRight');
    await expect(frame.getByRole('img', { name: /^Linkage view\. θ2 64\.00°/ })).toBeVisible();
    await frame.getByRole('button', { name: 'Play' }).click();
    await expect(frame.getByRole('button', { name: 'Pause' })).toBeVisible();
    await frame.getByRole('button', { name: 'Pause' }).click();
    expect(errors).toEqual([]);
    await page.screenshot({ path: artifact('embed.png'), fullPage: true });
  });

  test('shows only the panels the URL asks for', async ({ page }) => {
    await page.goto('./embed.html?panels=none');
    await waitReady(page);
    await expect(page.getByRole('slider')).toHaveCount(0);
    await expect(page.locator('canvas.linkage-canvas')).toBeVisible();
    await page.goto('./embed.html?panels=info,export');
    await waitReady(page);
    await expect(page.getByTestId('linkage-type')).toBeVisible();
    await expect(page.getByRole('button', { name: /^Export/ }).first()).toBeVisible();
  });

  test('its plot chooser works: a link asking for velocities shows them, Angles goes back', async ({ page }) => {
    await page.goto('./embed.html?panels=plots&plot=vel');
    await waitReady(page);
    const omega3 = page.getByRole('img', { name: 'ω3 against θ2' });
    await expect(omega3).toBeVisible();
    await expect(omega3.locator('g.lines path').last()).toHaveAttribute('d', /^M.+L/);
    await page.getByRole('radio', { name: 'Angles' }).check();
    await expect(page.getByRole('img', { name: 'θ3 against θ2' })).toBeVisible();
    await expect(omega3).toHaveCount(0);
  });

  test('on a phone the plots card holds both stacked charts', async ({ page }) => {
    await page.setViewportSize({ width: 390, height: 844 });
    for (const plot of ['ang', 'acc']) {
      await page.goto(`./embed.html?panels=plots&plot=${plot}`);
      await waitReady(page);
      const charts = page.locator('.embed-plots svg.chart-svg');
      await expect(charts).toHaveCount(2);
      // The card grows as the charts (a lazy chunk for the rate plots) mount: measure once both are laid out.
      const overflow = async () => {
        const card = await page.locator('.embed-plots').boundingBox();
        const boxes = [await charts.nth(0).boundingBox(), await charts.nth(1).boundingBox()];
        return Math.max(...boxes.map((b) => b!.y + b!.height - (card!.y + card!.height)));
      };
      await expect.poll(overflow, { message: plot }).toBeLessThanOrEqual(0);
    }
  });

  test('the app copies an embed code for a sandboxed iframe', async ({ page, context }) => {
    await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: ORIGIN });
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('button', { name: 'Copy embed code' }).click();
    await expect(page.getByText('Copied to the clipboard.')).toBeVisible();
    const code = await page.evaluate(() => navigator.clipboard.readText());
    expect(code.startsWith(`<iframe src="${ORIGIN}/embed.html?r1=6&amp;`)).toBe(true);
    expect(code).toContain('sandbox="allow-scripts');
  });
});
