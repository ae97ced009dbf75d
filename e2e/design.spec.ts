import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import { artifact, waitReady } from './helpers';

// The design metrics of issue 10 on the report's 6-2-5-5 linkage: panel values, go-to buttons, the μ band on
// the transmission plot and the canvas toggles, in English and Traditional Chinese. Reference values from the
// solver's 60-digit oracle tests: μ 47.156° at θ2 = 0 and 106.260° at 180°, extended dead centre θ2 = 44.415°
// (θ4 101.537°), folded 236.251° (θ4 150.074°), swing 48.537°, time ratio 1.1407635628308073.

/** Canvas pixels within tol of an sRGB colour per channel (anti-aliased edges excluded by the tolerance). */
async function pixelsNear(page: Page, rgb: [number, number, number], tol = 10): Promise<number> {
  return page.locator('canvas.linkage-canvas').evaluate(
    (c: HTMLCanvasElement, [r, g, b, t]) => {
      const d = c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < d.length; i += 4)
        if (Math.abs(d[i] - r) <= t && Math.abs(d[i + 1] - g) <= t && Math.abs(d[i + 2] - b) <= t) n++;
      return n;
    },
    [...rgb, tol] as const,
  );
}

const DEAD_CENTRE: [number, number, number] = [0x64, 0x74, 0x8b];
const INSTANT_CENTRE: [number, number, number] = [0x0e, 0x74, 0x90];
const WARNING: [number, number, number] = [0xb9, 0x1c, 0x1c];

const theta2Field = (page: Page) => page.getByRole('textbox', { name: /^θ2/ });

test.describe('design metrics', () => {
  for (const lang of ['en', 'zh-TW'] as const) {
    test(`the panel shows the report's values (${lang})`, async ({ page }) => {
      await page.goto(`./?lang=${lang}`);
      await waitReady(page);
      const panel = page.locator('section', {
        has: page.getByRole('heading', { name: lang === 'en' ? 'Design metrics' : '設計指標' }),
      });
      await expect(panel.getByTestId('design-mu-min')).toHaveText('47.156°');
      await expect(panel.getByTestId('design-mu-min-at')).toContainText('0.000°');
      await expect(panel.getByTestId('design-mu-max')).toHaveText('106.260°');
      await expect(panel.getByTestId('design-mu-max-at')).toContainText('180.000°');
      await expect(panel.getByTestId('design-dc-extended-at')).toContainText('44.415°');
      await expect(panel.getByTestId('design-dc-extended-theta4')).toHaveText('θ4 = 101.537°');
      await expect(panel.getByTestId('design-dc-folded-at')).toContainText('236.251°');
      await expect(panel.getByTestId('design-dc-folded-theta4')).toHaveText('θ4 = 150.074°');
      await expect(panel.getByTestId('design-swing')).toHaveText('48.537°');
      await expect(panel.getByTestId('design-time-ratio')).toHaveText(
        String(Number((1.1407635628308073).toPrecision(5))),
      );
      await expect(panel.getByText(lang === 'en' ? 'Time ratio (quick return)' : '急回比（時間比）')).toBeVisible();
      await page.screenshot({ path: artifact(`design-panel-${lang}.png`) });
    });
  }

  test('"go to" buttons move the linkage to each dead centre, on either branch', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    const a0 = await canvas.getAttribute('data-a');
    await page.getByRole('button', { name: /^Go to extended dead centre/ }).click();
    await expect(theta2Field(page)).toHaveValue('44.42');
    await expect(page.getByRole('img', { name: /^Linkage view\. θ2 44\.42°/ })).toBeVisible();
    await expect.poll(() => canvas.getAttribute('data-a')).not.toBe(a0);
    await page.getByRole('button', { name: /^Go to folded dead centre/ }).click();
    await expect(theta2Field(page)).toHaveValue('236.25');
    await expect(page.getByRole('img', { name: /θ4 150\.07°/ })).toBeVisible();

    // Crossed branch: the dead centres are the mirror images (θ2 negated).
    await page.goto('./?br=crossed');
    await waitReady(page);
    await page.getByRole('button', { name: /^Go to extended dead centre/ }).click();
    await expect
      .poll(async () => Math.abs(Number(await theta2Field(page).inputValue()) - (360 - 44.415)))
      .toBeLessThan(0.01);
    await expect(page.getByRole('img', { name: /θ4 −101\.54°/ })).toBeVisible();
  });

  test('"go to" while playing stops Play and keeps the dead centre, not the frame Play was showing', async ({
    page,
  }) => {
    await page.goto('./?t2=100');
    await waitReady(page);
    await page.getByRole('button', { name: 'Play' }).click();
    await expect(page.getByRole('button', { name: 'Pause' })).toBeVisible();
    // Play has moved the linkage on before the jump.
    await expect.poll(async () => Number(await theta2Field(page).inputValue())).not.toBe(100);
    await page.getByRole('button', { name: /^Go to extended dead centre/ }).click();
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
    await expect(theta2Field(page)).toHaveValue('44.42');
    await expect(page.getByRole('img', { name: /^Linkage view\. θ2 44\.42°/ })).toBeVisible();
    // Stopped for good: the address bar settles on the dead centre and the pose stays there.
    await expect.poll(() => new URL(page.url()).searchParams.get('t2')).toMatch(/^44\.41/);
    await expect(page.getByRole('img', { name: /^Linkage view\. θ2 44\.42°/ })).toBeVisible();
    await expect(theta2Field(page)).toHaveValue('44.42');
  });

  test("a rocking input's limits have go-to buttons that land on an assembled pose (zh-TW)", async ({ page }) => {
    // Non-Grashof 5-3-2.5-4: the input rocks through 0° between ±θ, where |A O4| = r3 + r4 (law of cosines).
    const limit = (Math.acos((25 + 9 - 6.5 * 6.5) / 30) * 180) / Math.PI;
    await page.goto('./?r1=5&r2=3&r3=2.5&r4=4&lang=zh-TW');
    await waitReady(page);
    await page.getByRole('button', { name: /^前往輸入極限 2/ }).click();
    await expect.poll(async () => Math.abs(Number(await theta2Field(page).inputValue()) - limit)).toBeLessThan(0.01);
    // The canvas describes an assembled pose (angles, not the can't-assemble message).
    await expect(page.locator('canvas.linkage-canvas')).toHaveAttribute('aria-label', /θ3 .*θ4 .*μ /);
  });

  test('the transmission plot shades the band and the stretches outside it, and follows mulo/muhi', async ({
    page,
  }) => {
    await page.goto('./');
    await waitReady(page);
    const chart = page.locator('svg.transmission-svg');
    await expect(chart.locator('rect.mu-band')).toHaveAttribute('data-lo', '40');
    await expect(chart.locator('rect.mu-band')).toHaveAttribute('data-hi', '140');
    // μ stays in 47.2°..106.3°: nothing outside the default band.
    await expect(chart.locator('rect.mu-outside')).toHaveCount(0);
    const h0 = Number(await chart.locator('rect.mu-band').getAttribute('height'));

    await page.goto('./?mulo=60&muhi=100');
    await waitReady(page);
    await expect(chart.locator('rect.mu-band')).toHaveAttribute('data-lo', '60');
    expect(Number(await chart.locator('rect.mu-band').getAttribute('height'))).toBeLessThan(h0);
    // Outside 60..100: around θ2 = 0 (both ends of the axis) and around 180°. Law of cosines, independently:
    // μ = 60° at cos θ2 = (40 − 25) / 24, μ = 100° at cos θ2 = (40 − 50 + 50 cos 100°) / 24.
    const a = (Math.acos(15 / 24) * 180) / Math.PI;
    const b = (Math.acos((40 - 50 + 50 * Math.cos((100 * Math.PI) / 180)) / 24) * 180) / Math.PI;
    const runs = await chart
      .locator('rect.mu-outside')
      .evaluateAll((rs) => rs.map((r) => [Number(r.getAttribute('data-x0')), Number(r.getAttribute('data-x1'))]));
    const expected = [
      [0, a],
      [b, 360 - b],
      [360 - a, 360],
    ];
    expect(runs).toHaveLength(3);
    runs.forEach((r, i) => {
      expect(Math.abs(r[0] - expected[i][0])).toBeLessThan(0.5);
      expect(Math.abs(r[1] - expected[i][1])).toBeLessThan(0.5);
    });
    await expect(chart.locator('path.mu-line-outside')).toHaveAttribute('clip-path', /url\(#/);

    // The band fields move it and write the URL.
    const lo = page.getByRole('textbox', { name: /^μ band, lower edge/ });
    await lo.fill('50');
    await expect(chart.locator('rect.mu-band')).toHaveAttribute('data-lo', '50');
    await expect.poll(() => new URL(page.url()).searchParams.get('mulo')).toBe('50');
    await page.locator('section.transmission-card').scrollIntoViewIfNeeded();
    await page.screenshot({ path: artifact('design-transmission.png'), fullPage: true });
  });

  test('the μ label turns to the warning colour when the pose is outside the band', async ({ page }) => {
    await page.goto('./?t2=0');
    await waitReady(page);
    expect(await pixelsNear(page, WARNING, 12)).toBe(0);
    await page.goto('./?t2=0&mulo=60&muhi=100');
    await waitReady(page);
    await expect.poll(() => pixelsNear(page, WARNING, 12)).toBeGreaterThan(10);
  });

  test('the dead-centre θ2 values are marked on every θ2 axis', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    // The angle charts and the transmission plot (the convergence chart has no θ2 axis).
    const charts = page.locator('section.plots svg.chart-svg, section.transmission-card svg.chart-svg');
    await expect(charts).toHaveCount(3);
    for (let i = 0; i < 3; i++) {
      await expect(charts.nth(i).locator('g.x-mark')).toHaveCount(2);
      await expect(charts.nth(i).locator('g.x-mark text')).toHaveText(['ext.', 'fold.']);
    }
    // A double crank has no dead centres: no marks.
    await page.goto('./?r1=2&r2=5&r3=5&r4=6');
    await waitReady(page);
    await expect(page.locator('g.x-mark')).toHaveCount(0);
  });

  for (const lang of ['en', 'zh-TW'] as const) {
    test(`the canvas toggles draw the dead centres and the instant centres (${lang})`, async ({ page }) => {
      const names = lang === 'en' ? { dc: 'Dead centres', ic: 'Instant centres' } : { dc: '死點', ic: '瞬心' };
      await page.goto(`./?lang=${lang}`);
      await waitReady(page);
      const dc0 = await pixelsNear(page, DEAD_CENTRE, 6);
      const ic0 = await pixelsNear(page, INSTANT_CENTRE, 6);
      expect(ic0).toBe(0);
      await page.getByRole('checkbox', { name: names.dc }).check();
      await expect.poll(() => pixelsNear(page, DEAD_CENTRE, 6)).toBeGreaterThan(dc0 + 100);
      await expect.poll(() => new URL(page.url()).searchParams.get('dc')).toBe('1');
      await page.getByRole('checkbox', { name: names.ic }).check();
      await expect.poll(() => pixelsNear(page, INSTANT_CENTRE, 6)).toBeGreaterThan(100);
      await page.locator('canvas.linkage-canvas').screenshot({ path: artifact(`design-canvas-${lang}.png`) });
      await page.getByRole('checkbox', { name: names.ic }).uncheck();
      await expect.poll(() => pixelsNear(page, INSTANT_CENTRE, 6)).toBe(0);
    });
  }
});
