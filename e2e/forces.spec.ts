import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import type { Locator, Page } from '@playwright/test';
import { oracleForces } from '../tests/solver/forcesOracle';
import type { OracleInertia, OracleLoads } from '../tests/solver/forcesOracle';
import { CYCLE_CSV_FORCE_COLUMNS } from '../tests/shared/csvTable';
import { artifact, csvRowsOf, waitReady } from './helpers';

/**
 * Forces (issue 20) driven as a person does: a link with the forces on, the panel's input torque against the
 * 40-digit Newton–Euler oracle (tests/solver/forcesOracle.ts, nothing of the app), the torque plot, the CSV's force
 * columns, the length unit, the force arrows and zh-TW. Every number the test expects is computed here.
 */

/** A crank-rocker in millimetres with every load: 2.5 kg/m bars, gravity, 40 N, −25 N at P, −3 N·m on the rocker. */
const DESIGN_MM = 'r1=600&r2=200&r3=500&r4=500&pd=250&pa=30';
const DESIGN_M = 'r1=0.6&r2=0.2&r3=0.5&r4=0.5&pd=0.25&pa=30';
const LOADS_URL = 'rho=2.5&pfx=40&pfy=-25&tl=-3&w2=7.5&a2=20';
const URL_MM = `./?${DESIGN_MM}&lu=mm&frc=1&${LOADS_URL}&t2=60`;
const URL_M = `./?${DESIGN_M}&lu=m&frc=1&${LOADS_URL}&t2=60`;

/** The same problem in SI, written out here: lengths in metres, uniform bars m = ρL, I = mL²/12, CG mid-link. */
const L = { r1: 0.6, r2: 0.2, r3: 0.5, r4: 0.5 };
const bar = (len: number): OracleInertia => {
  const mass = 2.5 * len;
  return { mass, inertia: (mass * len * len) / 12, cg: { dist: len / 2, angle: 0 } };
};
const INERTIA = { crank: bar(L.r2), coupler: bar(L.r3), rocker: bar(L.r4) };
const LOADS: OracleLoads = {
  gravity: { g: 9.81 },
  couplerForce: { pDist: 0.25, pAngle: Math.PI / 6, fx: 40, fy: -25 },
  outputTorque: -3,
};
const MOTION = { omega2: 7.5, alpha2: 20 };

/** The oracle's forces at theta2 in degrees (open branch). */
function oracleAt(theta2Deg: number) {
  const ref = oracleForces(L, (theta2Deg * Math.PI) / 180, 'open', MOTION, INERTIA, LOADS);
  if (!ref) throw new Error(`the oracle has no answer at ${theta2Deg}°`);
  return ref;
}

/** The value cell of the panel's row whose label is exactly `label`. */
function row(page: Page, label: string): Locator {
  return page.locator('.forces-panel .fact').filter({ has: page.locator('dt', { hasText: new RegExp(`^${label}$`) }) });
}

/** A panel value "−12.3456 N·m" as a number (its typographic minus read as '-'). */
function valueOf(text: string): number {
  return Number(text.replace('\u2212', '-').split(' ')[0]);
}

async function download(page: Page, name: string) {
  const [d] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name }).click()]);
  return d;
}

test.describe('forces', () => {
  test('a link with frc=1 shows the input torque T12 the oracle gives, with its unit', async ({ page }) => {
    await page.goto(URL_MM);
    await waitReady(page);
    const torque = row(page, 'Input torque T12');
    await expect(torque.locator('dd')).toHaveText(/^−?\d[\d.]* N·m$/);
    const shown = valueOf(await torque.locator('dd').innerText());
    const ref = oracleAt(60);
    // The panel writes 6 significant digits: half a unit in the sixth digit.
    expect(Math.abs(shown - ref.torque)).toBeLessThanOrEqual(5e-6 * Math.abs(ref.torque));
    // Each pin force as magnitude and direction, and the shaking force and moment.
    const f12 = await row(page, 'F12 ground on crank \\(O2\\)').locator('dd').innerText();
    expect(valueOf(f12)).toBeCloseTo(Math.hypot(ref.F12.x, ref.F12.y), 3);
    expect(f12).toMatch(/ N, at \d+(\.\d)?°$/);
    await expect(row(page, 'Shaking force').locator('dd')).toHaveText(/ N, at /);
    await expect(row(page, 'Shaking moment').locator('dd')).toHaveText(/ N·m$/);
    await expect(row(page, 'Flywheel inertia for k = 0.05').locator('dd')).toHaveText(/ kg·m²$/);
    await page.screenshot({ path: artifact('forces-panel-1280.png') });
  });

  test('the Torque plot draws T12 against θ2 with its mean, and exports as SVG and PNG', async ({ page }) => {
    await page.goto(URL_MM.replace('&a2=20', ''));
    await waitReady(page);
    await page.getByRole('radio', { name: 'Torque' }).check();
    const chart = page.getByRole('img', { name: 'Input torque T12 against θ2' });
    await expect(chart).toBeVisible();
    await expect(chart.locator('g.lines path')).toHaveCount(2);
    await expect(page).toHaveURL(/plot=trq/);
    // Gravity, a constant force at P and a torque on a rocker that swings back do no net work over a turn at a
    // steady speed: the mean input torque is 0 (docs/forces.md), and the legend says so.
    await expect(chart).toContainText('mean 0 N·m');
    const svg = await download(page, 'Download Input torque T12 against θ2 as SVG');
    expect(svg.suggestedFilename()).toBe('fourbar_600-200-500-500_open_torque-vs-theta2.svg');
    expect(readFileSync(await svg.path(), 'utf8')).toContain('Input torque T12 against θ2');
    const png = await download(page, 'Download Input torque T12 against θ2 as PNG');
    expect(
      readFileSync(await png.path())
        .subarray(1, 4)
        .toString('latin1'),
    ).toBe('PNG');
    await page.getByRole('radio', { name: 'Pin forces' }).check();
    await expect(
      page.getByRole('img', { name: 'Pin-force magnitudes against θ2' }).locator('g.lines path'),
    ).toHaveCount(4);
    await page.getByRole('radio', { name: 'Bearing load' }).check();
    await expect(page.getByRole('img', { name: 'Crank bearing load F12 over a turn' })).toBeVisible();
  });

  test('the cycle CSV ends with torque_Nm and f12x_N … f14y_N, as the oracle gives them', async ({ page }) => {
    await page.goto(URL_MM);
    await waitReady(page);
    const d = await download(page, 'Export cycle CSV');
    const rows = await csvRowsOf(d);
    const header = rows[0];
    // After every existing column (the position, motion and status columns all come first).
    expect(header.indexOf('torque_Nm')).toBeGreaterThan(header.indexOf('residual'));
    expect(header.indexOf('torque_Nm')).toBeGreaterThan(header.indexOf('apy'));
    expect(header.slice(-9)).toEqual(CYCLE_CSV_FORCE_COLUMNS);
    const data = rows.slice(1);
    expect(data).toHaveLength(361);
    const col = (r: string[], name: string) => Number(r[header.indexOf(name)]);
    for (const r of data.filter((_, i) => i % 15 === 0)) {
      const ref = oracleAt(col(r, 'theta2_deg'));
      const scale = Math.max(...[ref.F12, ref.F32, ref.F43, ref.F14].map((f) => Math.hypot(f.x, f.y)));
      // Full precision both sides; |sin mu| >= 0.7 here, so 1e-10 of the largest pin force is ample.
      expect(Math.abs(col(r, 'torque_Nm') - ref.torque)).toBeLessThan(1e-10 * scale * L.r2);
      expect(Math.abs(col(r, 'f12x_N') - ref.F12.x)).toBeLessThan(1e-10 * scale);
      expect(Math.abs(col(r, 'f32y_N') - ref.F32.y)).toBeLessThan(1e-10 * scale);
      expect(Math.abs(col(r, 'f43x_N') - ref.F43.x)).toBeLessThan(1e-10 * scale);
      expect(Math.abs(col(r, 'f14y_N') - ref.F14.y)).toBeLessThan(1e-10 * scale);
    }
  });

  test('the same linkage in mm and in m gives the same torque; the unit sits with the lengths and converts them', async ({
    page,
  }) => {
    await page.goto(URL_MM);
    await waitReady(page);
    const inMm = await row(page, 'Input torque T12').locator('dd').innerText();
    await expect(page.locator('.numctl').filter({ hasText: 'r1 ground' }).locator('.numctl-unit')).toHaveText('mm');
    await page.goto(URL_M);
    await waitReady(page);
    await expect(row(page, 'Input torque T12').locator('dd')).toHaveText(inMm);
    await expect(page.locator('.numctl').filter({ hasText: 'r1 ground' }).locator('.numctl-unit')).toHaveText('m');
    // Choosing a unit converts the lengths (issue 34 item 11): the same machine, so the angles and T12 stay.
    const theta3Cell = page
      .locator('.fact')
      .filter({ has: page.locator('dt', { hasText: /^θ3$/ }) })
      .first()
      .locator('dd');
    const theta3 = await theta3Cell.innerText();
    await page.getByRole('group', { name: 'Length unit' }).getByRole('radio', { name: 'mm' }).check();
    await expect(page).toHaveURL(/lu=mm/);
    await expect(page.getByRole('textbox', { name: 'r1 ground' })).toHaveValue('600');
    await expect(page.locator('.numctl').filter({ hasText: 'r1 ground' }).locator('.numctl-unit')).toHaveText('mm');
    await expect(theta3Cell).toHaveText(theta3);
    await expect(row(page, 'Input torque T12').locator('dd')).toHaveText(inMm);
  });

  test('a bad mass per length is refused with a message naming the field; Enter or leaving commits a good one', async ({
    page,
  }) => {
    await page.goto(URL_MM);
    await waitReady(page);
    const rho = page.getByRole('textbox', { name: 'Mass per length (kg/m)', exact: true });
    const torque = row(page, 'Input torque T12').locator('dd');
    await expect(rho).toHaveValue('2.5');
    const before = await torque.innerText();
    // Nothing is read while typing: the text is judged on Enter.
    await rho.fill('2..5');
    await expect(page.getByRole('alert')).toHaveCount(0);
    await rho.press('Enter');
    await expect(page.getByRole('alert')).toHaveText('Mass per length: “2..5” is not a number.');
    await expect(rho).toHaveAttribute('aria-invalid', 'true');
    await rho.fill('2e6');
    await rho.press('Enter');
    await expect(page.getByRole('alert')).toHaveText('Mass per length must be from 0 to 1e6.');
    await expect(torque).toHaveText(before);
    // Escape restores the value kept; a good text commits when the field loses focus.
    await rho.press('Escape');
    await expect(rho).toHaveValue('2.5');
    await expect(page.getByRole('alert')).toHaveCount(0);
    await rho.fill('5');
    await rho.press('Tab');
    await expect(rho).not.toHaveAttribute('aria-invalid');
    await expect(torque).not.toHaveText(before);
    await expect(page).toHaveURL(/rho=5(&|$)/);
  });

  test('the Force vectors toggle draws the pin forces with a scale legend, and fv=1 in the URL', async ({ page }) => {
    await page.goto(URL_MM);
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    // Pixels of the force arrows' red (#dc2626) on the canvas.
    const red = () =>
      canvas.evaluate((c: HTMLCanvasElement) => {
        const d = c.getContext('2d')?.getImageData(0, 0, c.width, c.height).data;
        let n = 0;
        if (d) for (let i = 0; i < d.length; i += 4) if (d[i] > 200 && d[i + 1] < 70 && d[i + 2] < 70) n++;
        return n;
      });
    expect(await red()).toBe(0);
    const toggle = page.getByRole('checkbox', { name: 'Force vectors' });
    await toggle.check();
    await expect(page).toHaveURL(/fv=1/);
    await expect.poll(red).toBeGreaterThan(200);
    await page.screenshot({ path: artifact('forces-vectors-1280.png') });
    await toggle.uncheck();
    await expect.poll(red).toBe(0);
  });

  test('zh-TW names the torque, the pin forces, the shaking force and the flywheel', async ({ page }) => {
    await page.goto(`${URL_MM}&lang=zh-TW`);
    await waitReady(page);
    await expect(row(page, '輸入扭矩 T12').locator('dd')).toHaveText(/ N·m$/);
    await expect(page.getByRole('heading', { name: '銷力' })).toBeVisible();
    await expect(row(page, '搖撼力').locator('dd')).toHaveText(/ N, 方向 /);
    await expect(page.getByRole('heading', { name: '飛輪' })).toBeVisible();
    await expect(page.getByRole('radio', { name: '扭矩' })).toBeVisible();
    await expect(page.getByRole('checkbox', { name: '力向量' })).toBeVisible();
  });

  test('on a phone (390×844) the six plot choices wrap instead of widening the page', async ({ page }) => {
    await page.setViewportSize({ width: 390, height: 844 });
    await page.goto(`${URL_MM}&fv=1&plot=trq`);
    await waitReady(page);
    await expect(page.getByRole('img', { name: 'Input torque T12 against θ2' })).toBeVisible();
    expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(390);
    await page.screenshot({ path: artifact('forces-phone-390.png') });
  });

  test('an embed can show the forces panel', async ({ page }) => {
    await page.goto(`./embed.html?${DESIGN_MM}&lu=mm&frc=1&${LOADS_URL}&t2=60&panels=forces`);
    await waitReady(page);
    await expect(row(page, 'Input torque T12').locator('dd')).toHaveText(/ N·m$/);
    const shown = valueOf(await row(page, 'Input torque T12').locator('dd').innerText());
    expect(Math.abs(shown - oracleAt(60).torque)).toBeLessThanOrEqual(5e-6 * Math.abs(oracleAt(60).torque));
  });
});
