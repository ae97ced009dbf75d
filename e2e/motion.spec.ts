import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import { referenceMotion } from '../tests/oracle/rates';
import { CYCLE_CSV_MOTION_COLUMNS } from '../tests/shared/csvTable';
import { artifact, csvRowsOf, waitReady } from './helpers';

/** The report's linkage, the app's default: r1 = 6, r2 = 2, r3 = 5, r4 = 5, P at 2.5 and 30 degrees. */
const L = { r1: 6, r2: 2, r3: 5, r4: 5 };

/**
 * theta4 (radians) on the open branch by intersecting the circles about A (radius r3) and O4 (radius r4):
 * a construction of its own, no solver code.
 */
function theta4Open(theta2: number): number {
  const ax = L.r2 * Math.cos(theta2);
  const ay = L.r2 * Math.sin(theta2);
  const dx = L.r1 - ax;
  const dy = -ay;
  const d = Math.hypot(dx, dy);
  // Distance from O4 along O4 -> A to the chord of the two circles, and half the chord.
  const a = (L.r4 * L.r4 - L.r3 * L.r3 + d * d) / (2 * d);
  const h = Math.sqrt(L.r4 * L.r4 - a * a);
  const ux = -dx / d;
  const uy = -dy / d;
  const candidates = [1, -1].map((s) => ({ x: L.r1 + a * ux - s * h * uy, y: a * uy + s * h * ux }));
  // Open branch: sin(theta4 - theta3) > 0, i.e. the cross product (B - A) x (B - O4) is positive.
  for (const b of candidates) {
    const t3x = b.x - ax;
    const t3y = b.y - ay;
    const t4x = b.x - L.r1;
    const t4y = b.y;
    if (t3x * t4y - t3y * t4x > 0) return Math.atan2(t4y, t4x);
  }
  throw new Error('no open pose');
}

/** The number in a panel text such as "−1.23456 rad/s" (typographic minus). */
function leadingNumber(text: string): number {
  const m = /^[−-]?[\d.]+(?:e[−-]?\d+)?/.exec(text.trim());
  if (!m) throw new Error(`no number in ${JSON.stringify(text)}`);
  return Number(m[0].replace(/−/g, '-'));
}

/** Pixels of the canvas close to an RGB colour (the arrows' token colours). */
async function pixelsOfColour(page: Page, rgb: [number, number, number]): Promise<number> {
  return page.locator('canvas.linkage-canvas').evaluate((c: HTMLCanvasElement, [r, g, b]) => {
    const ctx = c.getContext('2d');
    if (!ctx) return 0;
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (Math.abs(d[i] - r) < 24 && Math.abs(d[i + 1] - g) < 24 && Math.abs(d[i + 2] - b) < 24) n++;
    }
    return n;
  }, rgb);
}

test.describe('velocity and acceleration', () => {
  test('ω2 set in rpm gives the panel ω4 of the linkage', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('combobox', { name: 'ω2 unit' }).selectOption('rpm');
    const field = page.getByRole('textbox', { name: /^ω2/ });
    await expect(field).toHaveValue('95.492966');
    await field.fill('120');
    // dtheta4/dtheta2 by a central difference of the construction (h = 1e-5: truncation ~1e-10 relative).
    const theta2 = Math.PI / 4;
    const h = 1e-5;
    const ratio = (theta4Open(theta2 + h) - theta4Open(theta2 - h)) / (2 * h);
    const omega4 = ratio * ((120 * 2 * Math.PI) / 60);
    const cell = page.getByTestId('motion-omega4');
    await expect(cell).toContainText('rad/s');
    await expect
      .poll(async () => Math.abs(leadingNumber(await cell.innerText()) - omega4) / Math.abs(omega4))
      .toBeLessThan(2e-6); // the panel shows 6 significant digits
    await expect(page).toHaveURL(/[?&]w2=12\.566370614359/);
    // The unit is kept with the link (issue 19): reloading shows rpm again.
    await expect(page).toHaveURL(/[?&]w2u=rpm(&|$)/);
    await page.reload();
    await expect(page.getByRole('combobox', { name: 'ω2 unit' })).toHaveValue('rpm');
    await expect(page.getByRole('textbox', { name: /^ω2/ })).toHaveValue('120');
  });

  test('the vector toggles draw arrows with a scale legend', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const velocity: [number, number, number] = [0x0e, 0x74, 0x90];
    const acceleration: [number, number, number] = [0xbe, 0x18, 0x5d];
    expect(await pixelsOfColour(page, velocity)).toBe(0);
    await page.getByRole('checkbox', { name: 'Velocity vectors' }).check();
    await expect.poll(() => pixelsOfColour(page, velocity)).toBeGreaterThan(60);
    expect(await pixelsOfColour(page, acceleration)).toBe(0);
    await page.getByRole('checkbox', { name: 'Acceleration vectors' }).check();
    await expect.poll(() => pixelsOfColour(page, acceleration)).toBeGreaterThan(60);
    await page.locator('canvas.linkage-canvas').screenshot({ path: artifact('motion-vectors.png') });
    await page.getByRole('checkbox', { name: 'Velocity vectors' }).uncheck();
    await expect.poll(() => pixelsOfColour(page, velocity)).toBe(0);
    await expect(page).toHaveURL(/[?&]acc=1/);
  });

  test('the velocity plot shows ω3 and ω4 against θ2 with the cursor', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('radio', { name: 'Velocities' }).check();
    for (const name of ['ω3 against θ2', 'ω4 against θ2']) {
      const svg = page.getByRole('img', { name });
      await expect(svg).toBeVisible();
      await expect(svg.locator('g.lines path').last()).toHaveAttribute('d', /^M.+L/);
      // The live chart draws its marker over the SVG; its box lists the dots it shows.
      await expect(svg.locator('xpath=..').locator('.chart-marker')).toHaveAttribute(
        'data-dots',
        /^\[\{"cx":[^}]*\}\]$/,
      );
      // The dead centres of this crank-rocker, as on the angle plots: the rocker stops there (ω4 = 0).
      await expect(svg.locator('g.x-mark text')).toHaveText(['ext.', 'fold.']);
    }
    await page.getByRole('radio', { name: 'Accelerations' }).check();
    await expect(page.getByRole('img', { name: 'α4 against θ2' })).toBeVisible();
    await expect(page).toHaveURL(/[?&]plot=acc/);
  });

  test("near a triple rocker's limits the rate plots clip their runaway curves and mark where they leave", async ({
    page,
  }) => {
    await page.goto('./?r1=4&r2=3&r3=3.5&r4=3&plot=vel');
    await waitReady(page);
    for (const name of ['ω3 against θ2', 'ω4 against θ2']) {
      const svg = page.getByRole('img', { name });
      // ω grows without bound at the input's limits: the curves are clipped to the plot, and a triangle marks
      // each place a solid curve leaves it (two limits, each left on one side).
      await expect(svg.locator('g.lines')).toHaveAttribute('clip-path', /^url\(#theta2-clip-\d+\)$/);
      await expect(svg).toHaveAttribute('data-clip-marks', /^[1-9]\d*$/);
      const marks = await svg.locator('g.clip-marks path').count();
      expect(marks).toBe(Number(await svg.getAttribute('data-clip-marks')));
    }
  });

  test('the CSV carries the motion columns, true to the oracle', async ({ page }) => {
    const input = { omega2: 12, alpha2: -3 };
    await page.goto(`./?w2=${input.omega2}&a2=${input.alpha2}`);
    await waitReady(page);
    const [d] = await Promise.all([
      page.waitForEvent('download'),
      page.getByRole('button', { name: 'Export cycle CSV' }).click(),
    ]);
    const rows = await csvRowsOf(d);
    const header = rows[0];
    expect(header).toEqual(CYCLE_CSV_MOTION_COLUMNS);
    const col = (name: string) => header.indexOf(name);
    const data = rows.slice(1);
    expect(data).toHaveLength(361);
    const pDist = 2.5;
    const pAngle = Math.PI / 6;
    for (let i = 0; i <= 360; i += 15) {
      const row = data[i];
      const ref = referenceMotion(L, (i * Math.PI) / 180, 1, input, pDist, pAngle);
      // Well conditioned (|sin mu| >= 0.6 on this linkage): 1e-9 of the scale covers rounding many times over.
      const close = (name: string, want: number, scale: number) =>
        expect(Math.abs(Number(row[col(name)]) - want), `${name} at ${i} deg`).toBeLessThan(1e-9 * scale);
      const w = Math.abs(input.omega2);
      const a = Math.hypot(input.omega2 ** 2, input.alpha2);
      close('omega3_rad_s', ref.omega3, w);
      close('omega4_rad_s', ref.omega4, w);
      close('alpha3_rad_s2', ref.alpha3, a);
      close('alpha4_rad_s2', ref.alpha4, a);
      close('mu_deg', (Math.acos(ref.cosMu) * 180) / Math.PI, 180);
      close('px', ref.point.x, 10);
      close('py', ref.point.y, 10);
      close('vpx', ref.point.vx, 10 * w);
      close('vpy', ref.point.vy, 10 * w);
      close('apx', ref.point.ax, 10 * a);
      close('apy', ref.point.ay, 10 * a);
    }
  });

  test('in zh-TW the controls, panel and plots speak Chinese', async ({ page }) => {
    await page.goto('./?lang=zh-TW');
    await waitReady(page);
    await expect(page.getByRole('textbox', { name: /^ω2/ })).toBeVisible();
    await expect(page.getByRole('textbox', { name: /^α2/ })).toBeVisible();
    await expect(page.getByRole('heading', { name: '速度與加速度' })).toBeVisible();
    await expect(page.getByText('角速度 ω3')).toBeVisible();
    await page.getByRole('checkbox', { name: '速度向量', exact: true }).check();
    await page.getByRole('checkbox', { name: '加速度向量', exact: true }).check();
    await page.getByRole('radio', { name: '角速度', exact: true }).check();
    await expect(page.getByRole('img', { name: 'ω3 對 θ2' })).toBeVisible();
    await expect(page.getByTestId('motion-vP')).toContainText('方向');
    await page.locator('.app').screenshot({ path: artifact('motion-zh-TW.png') });
  });
});
