import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import { csvParseRows } from 'd3-dsv';
import { solveClosedForm } from '../src/solver';
import { csvRowsOf, pngFacts, waitReady } from './helpers';

async function download(page: Page, name: string) {
  const [d] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name }).click()]);
  return d;
}

test.describe('exports', () => {
  test('each PNG export downloads a real PNG at the chosen size', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const box = await page.locator('canvas.linkage-canvas').boundingBox();
    if (!box) throw new Error('no canvas');
    const w = Math.floor(box.width);
    const h = Math.floor(box.height);
    const sizes: [string, number][] = [
      ['Screen', 1],
      ['2×', 2],
      ['300 DPI print', 300 / 96],
    ];
    for (const [size, k] of sizes) {
      await page.getByRole('group', { name: 'PNG size' }).getByRole('radio', { name: size }).check();
      const d = await download(page, 'Export linkage view PNG');
      const suffix = k === 1 ? 'screen' : k === 2 ? '2x' : '300dpi';
      expect(d.suggestedFilename()).toBe(`fourbar_6-2-5-5_open_theta2-45_linkage_${suffix}.png`);
      const png = await pngFacts(d);
      expect(png.signatureOk).toBe(true);
      expect(png.width).toBe(Math.round(w * k));
      expect(png.height).toBe(Math.round(h * k));
    }
    await page.getByRole('radio', { name: '2×' }).check();
    const charts: [string, string, number, number][] = [
      ['Export θ3 plot PNG', 'theta3-vs-theta2', 1280, 720],
      ['Export θ4 plot PNG', 'theta4-vs-theta2', 1280, 720],
      ['Export θ3 and θ4 plot PNG', 'theta3-theta4-vs-theta2', 1280, 720],
      // The rate plots export whichever plot shows: here the angle plots do.
      ['Export ω3 and ω4 plot PNG', 'omega3-omega4-vs-theta2', 1280, 720],
      ['Export α3 and α4 plot PNG', 'alpha3-alpha4-vs-theta2', 1280, 720],
      ['Export NR convergence plot PNG', 'nr-convergence', 1120, 680],
    ];
    for (const [name, subject, pw, ph] of charts) {
      const d = await download(page, name);
      expect(d.suggestedFilename()).toContain(subject);
      expect(d.suggestedFilename().endsWith('_2x.png')).toBe(true);
      const png = await pngFacts(d);
      expect(png.signatureOk).toBe(true);
      expect([png.width, png.height]).toEqual([pw, ph]);
      expect(png.bytes).toBeGreaterThan(10_000);
    }
    await page.getByRole('radio', { name: '300 DPI print' }).check();
    const print = await pngFacts(await download(page, 'Export θ3 plot PNG'));
    expect([print.width, print.height]).toEqual([2000, 1125]);
  });

  test('the CSV has a header and 361 rows that agree with the solver', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const d = await download(page, 'Export cycle CSV');
    expect(d.suggestedFilename()).toBe('fourbar_6-2-5-5_open_cycle_n360.csv');
    const text = readFileSync(await d.path(), 'utf8');
    expect(text).not.toMatch(/NaN|Infinity/);
    const rows = csvParseRows(text);
    if (rows[rows.length - 1].length === 1 && rows[rows.length - 1][0] === '') rows.pop();
    // The position columns; the motion columns between theta4_deg and status, and the input's after residual,
    // are motion.spec.ts's.
    const header = rows[0];
    expect(header.slice(0, 3)).toEqual(['theta2_deg', 'theta3_deg', 'theta4_deg']);
    expect(header.slice(-5)).toEqual(['status', 'iterations', 'residual', 'omega2_rad_s', 'alpha2_rad_s2']);
    const [cStatus, cIter, cRes] = ['status', 'iterations', 'residual'].map((c) => header.indexOf(c));
    const data = rows.slice(1);
    expect(data).toHaveLength(361);
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    for (const [i, row] of data.entries()) {
      expect(Number(row[0])).toBe(i);
      expect(row[cStatus]).toBe('ok');
      expect(Number(row[cIter])).toBeGreaterThanOrEqual(0);
      expect(Number(row[cRes])).toBeLessThan(1e-12);
      const ref = solveClosedForm(l, (i * Math.PI) / 180, 'open');
      if (!ref) throw new Error(`solver says ${i} deg cannot assemble`);
      // Both full precision: they agree to far better than 1e-9 deg.
      const wrap = (x: number) => x - 360 * Math.floor((x + 180) / 360);
      expect(Math.abs(wrap(Number(row[1]) - (ref.theta3 * 180) / Math.PI))).toBeLessThan(1e-9);
      expect(Math.abs(wrap(Number(row[2]) - (ref.theta4 * 180) / Math.PI))).toBeLessThan(1e-9);
      expect(Number(row[1])).toBeGreaterThan(-180);
      expect(Number(row[1])).toBeLessThanOrEqual(180);
    }
    expect(Number(data[90][1])).toBeCloseTo(32.3335306935, 8);
  });

  test('the CSV of a triple rocker leaves the unreachable angles empty', async ({ page }) => {
    await page.goto('./?r1=4&r2=3&r3=3.5&r4=3&t2=0');
    await waitReady(page);
    const d = await download(page, 'Export cycle CSV');
    const all = await csvRowsOf(d);
    const status = all[0].indexOf('status');
    const rows = all.slice(1);
    expect(rows).toHaveLength(361);
    // Every column from theta3_deg up to status is empty where the linkage cannot assemble.
    expect(rows[180].slice(1, status + 1)).toEqual([...Array<string>(status - 1).fill(''), 'unreachable']);
    expect(rows[0][status]).toBe('ok');
    // The input it is driven with is known on every row, assembled or not (10 rad/s counter-clockwise).
    expect(rows[180].slice(-2)).toEqual(['10', '0']);
  });
});
