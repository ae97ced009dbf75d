import type { Locator, Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { oracleForces } from '../tests/solver/forcesOracle';
import { artifact, waitReady } from './helpers';

// The printable report (issue 19): in print media the page is one report, with no controls, made of the same
// numbers the panels show, and the browser's PDF of it is exactly one A4 or Letter page, in both languages.

const WORDS = {
  en: { print: 'Print report', pdf: /Save as PDF/, title: 'Four-bar linkage report' },
  'zh-TW': { print: '列印報告', pdf: /另存為 PDF/, title: '四連桿機構報告' },
} as const;

interface Pt {
  x: number;
  y: number;
}

/**
 * The oracle's input torque T12 (N·m) at θ2 (degrees) for forces.spec.ts's crank-rocker in SI (lengths in metres,
 * 2.5 kg/m bars, gravity, 40 N and −25 N at P, −3 N·m on the rocker, ω2 = 7.5 rad/s, α2 = 20 rad/s²; open branch).
 */
function oracleTorque(theta2Deg: number): number {
  const L = { r1: 0.6, r2: 0.2, r3: 0.5, r4: 0.5 };
  const bar = (len: number) => ({ mass: 2.5 * len, inertia: (2.5 * len ** 3) / 12, cg: { dist: len / 2, angle: 0 } });
  const ref = oracleForces(
    L,
    (theta2Deg * Math.PI) / 180,
    'open',
    { omega2: 7.5, alpha2: 20 },
    { crank: bar(L.r2), coupler: bar(L.r3), rocker: bar(L.r4) },
    { gravity: { g: 9.81 }, couplerForce: { pDist: 0.25, pAngle: Math.PI / 6, fx: 40, fy: -25 }, outputTorque: -3 },
  );
  if (!ref) throw new Error(`the oracle has no answer at ${theta2Deg}°`);
  return ref.torque;
}

/** Pages in a PDF: its /Type /Page objects (not the /Pages tree). */
function pdfPages(pdf: Buffer): number {
  return (pdf.toString('latin1').match(/\/Type\s*\/Page(?!s)/g) ?? []).length;
}

/** The text of a panel value by its test id, as the screen shows it. */
async function panel(page: Page, testId: string): Promise<string> {
  return (await page.getByTestId(testId).innerText()).trim();
}

/** The report's value of a key. */
async function report(page: Page, key: string): Promise<string> {
  return (await page.locator(`[data-testid="print-report"] [data-report="${key}"]`).innerText()).trim();
}

for (const lang of ['en', 'zh-TW'] as const) {
  const w = WORDS[lang];

  test(`the printed report (${lang}): no controls, the panels' numbers, one A4 and one Letter page`, async ({
    page,
  }) => {
    await page.goto(`./?lang=${lang}&t2=45`);
    await waitReady(page);
    // On screen: the button, its PDF note, and no report.
    await expect(page.getByRole('button', { name: w.print })).toBeVisible();
    await expect(page.getByText(w.pdf)).toBeVisible();
    await expect(page.getByTestId('print-report')).toHaveCount(0);
    // Every value the report prints, as its panel shows it, read before printing (the report's key: the panel's text).
    const at = (testId: string) => panel(page, testId);
    const lengths = await Promise.all(
      ['r1', 'r2', 'r3', 'r4'].map(async (r) => {
        const field = page.getByRole('textbox', { name: new RegExp(`^${r}\\b`) });
        return `${r} = ${await field.inputValue()}`;
      }),
    );
    const panels: Record<string, string> = {
      lengths: lengths.join(', '),
      'grashof-sums': await at('grashof-sums'),
      grashof: await at('grashof-verdict'),
      'linkage-type': await at('linkage-type'),
      barker: await at('barker'),
      'input-range': await at('input-range'),
      'mu-min': `${await at('design-mu-min')} (${await at('design-mu-min-at')})`,
      'mu-max': `${await at('design-mu-max')} (${await at('design-mu-max-at')})`,
      'dc-extended': `${await at('design-dc-extended-at')}, ${await at('design-dc-extended-theta4')}`,
      'dc-folded': `${await at('design-dc-folded-at')}, ${await at('design-dc-folded-theta4')}`,
      swing: await at('design-swing'),
      'time-ratio': await at('design-time-ratio'),
      theta3: await at('analysis-theta3'),
      theta4: await at('analysis-theta4'),
      omega3: await at('motion-omega3'),
      omega4: await at('motion-omega4'),
      alpha3: await at('motion-alpha3'),
      alpha4: await at('motion-alpha4'),
      mu: await at('analysis-mu'),
      // The input and units: the length unit chosen and ω2 as its field shows it (the default unit, rad/s).
      'length-unit': await page
        .getByRole('radio', { checked: true, name: /^(mm|cm|m|in)$/ })
        .evaluate((el) => (el as HTMLInputElement).labels?.[0]?.textContent?.trim() ?? ''),
      omega2: `${await page.getByRole('textbox', { name: /^ω2\b/ }).inputValue()} rad/s`,
    };

    await page.emulateMedia({ media: 'print' });
    const sheet = page.getByTestId('print-report');
    await expect(sheet).toBeVisible();
    await expect(sheet.getByRole('heading', { level: 1 })).toHaveText(w.title);
    // The figure (the canvas's drawing with r1..r4) and the chosen plots (θ3 and θ4) are SVG drawings.
    const figure = sheet.locator('.report-figure svg');
    await expect(figure).toBeVisible();
    // Each label is drawn twice, its white halo and its text.
    for (const r of ['r1', 'r2', 'r3', 'r4'])
      expect(await figure.locator('text', { hasText: new RegExp(`^${r}$`) }).count(), r).toBeGreaterThan(0);
    await expect(sheet.locator('[data-report="lengths"]')).toContainText('r1 = 6, r2 = 2, r3 = 5, r4 = 5');
    await expect(sheet.locator('.report-plot svg')).toHaveCount(2);
    // Every value the report prints is its panel's, and the report prints no value that is not compared here.
    const printed = await sheet
      .locator('[data-report]')
      .evaluateAll((els) => els.map((el) => el.getAttribute('data-report')));
    expect([...printed].sort()).toEqual(Object.keys(panels).sort());
    for (const [key, value] of Object.entries(panels)) {
      if (key === 'lengths') expect(await report(page, key), key).toContain(value);
      else expect(await report(page, key), key).toBe(value);
    }
    // No control of the app is shown: no button, field, slider or menu.
    const shownControls = await page.evaluate(() =>
      [...document.querySelectorAll('button, input, select, textarea, a[href]')]
        .filter((el) => (el as HTMLElement).getClientRects().length > 0)
        .map((el) => el.outerHTML.slice(0, 80)),
    );
    expect(shownControls).toEqual([]);
    // Nothing of the report is cut off by its one-page box (PrintReport.css clips what would not fit).
    expect(await sheet.evaluate((el) => el.scrollHeight - el.clientHeight)).toBeLessThanOrEqual(1);
    await page.screenshot({ path: artifact(`print-${lang}.png`), fullPage: true });
    for (const format of ['A4', 'Letter'] as const) {
      const pdf = await page.pdf({ format });
      expect(pdfPages(pdf), format).toBe(1);
    }
    // Back on screen, the report goes.
    await page.emulateMedia({ media: 'screen' });
    await expect(page.getByTestId('print-report')).toHaveCount(0);
  });
}

test('the report prints the chosen plots: the velocity plot when velocities are shown', async ({ page }) => {
  await page.goto('./?plot=vel&plots=together');
  await waitReady(page);
  await page.emulateMedia({ media: 'print' });
  const sheet = page.getByTestId('print-report');
  await expect(sheet).toBeVisible();
  await expect(sheet.locator('.report-plot svg')).toHaveCount(1);
  await expect(sheet.locator('.report-plot svg text', { hasText: /^ω3/ }).first()).toBeAttached();
  expect(await sheet.evaluate((el) => el.scrollHeight - el.clientHeight)).toBeLessThanOrEqual(1);
  const pdf = await page.pdf({ format: 'A4' });
  expect(pdfPages(pdf)).toBe(1);
});

test('with Forces on and a synthesized design: the forces panel, the coupler point, placement and targets (issue 34, 12)', async ({
  page,
}) => {
  const tg = '1.5,2;-0.25,3.125';
  await page.goto(`./?frc=1&ox=1.5&oy=-2&og=30&pd=2.5&pa=-15&tg=${encodeURIComponent(tg)}&t2=60`);
  await waitReady(page);
  await expect(page.getByTestId('forces-torque')).toBeVisible();
  await expect(page.getByTestId('forces-flywheel')).not.toHaveText('');
  const keys = [
    'torque',
    'F12',
    'F32',
    'F43',
    'F14',
    'shakingForce',
    'shakingMoment',
    'mean',
    'rms',
    'peak',
    'energy',
    'flywheel',
  ];
  const panels: Record<string, string> = {};
  for (const k of keys) panels[`forces-${k}`] = (await page.getByTestId(`forces-${k}`).innerText()).trim();
  await page.emulateMedia({ media: 'print' });
  const sheet = page.getByTestId('print-report');
  await expect(sheet).toBeVisible();
  // Every force the report prints is the panel's, and it prints them all.
  const printed = await sheet
    .locator('[data-report^="forces-"]')
    .evaluateAll((els) => els.map((el) => el.getAttribute('data-report')));
  expect([...printed].sort()).toEqual(Object.keys(panels).sort());
  for (const [key, value] of Object.entries(panels)) expect(await report(page, key), key).toBe(value);
  // The synthesized design's coupler point, placement and targets: the numbers the link gave.
  const numbers = async (key: string) =>
    (await report(page, key)).match(/[-−]?\d+(\.\d+)?/g)!.map((x) => Number(x.replace('−', '-')));
  expect(await numbers('coupler')).toEqual([2.5, -15]);
  expect(await numbers('placement')).toEqual([2, 1.5, -2, 30]);
  expect(await numbers('targets')).toEqual([1, 1.5, 2, 2, -0.25, 3.125]);
  expect(await report(page, 'length-unit')).toBe('m');
  await expect(sheet.getByRole('heading', { name: 'Forces', exact: true })).toBeVisible();
  await page.screenshot({ path: artifact('print-forces-synthesized.png'), fullPage: true });
  // The forces run onto a second page, nothing cut off.
  const pdf = await page.pdf({ format: 'A4' });
  expect(pdfPages(pdf)).toBeLessThanOrEqual(2);
});

/** A plot's pixels read back as values: y pixel → value by the y axis's own tick labels (two or more), x likewise. */
async function plotEnds(svg: Locator): Promise<{ first: Pt; last: Pt; marker: Pt | null }> {
  return svg.evaluate((el) => {
    const num = (s: string) => Number(s.replace(/\u2212/g, '-').replace(/,/g, ''));
    const ticks = (cls: string, axis: 0 | 1) =>
      [...el.querySelectorAll(`g.${cls} g.tick`)].map((g) => {
        const m = /translate\(([-\d.e]+),\s*([-\d.e]+)\)/.exec(g.getAttribute('transform') ?? '')!;
        // d3-axis sets its ticks half a pixel off at devicePixelRatio 1 (crisp 1-pixel lines): the data's pixel is 0.5 less.
        const half = window.devicePixelRatio > 1 ? 0 : 0.5;
        return { px: Number(m[axis + 1]) - half, v: num(g.querySelector('text')?.textContent ?? '') };
      });
    const fit = (t: { px: number; v: number }[]) => {
      const [a, b] = [t[0], t[t.length - 1]];
      return (px: number) => a.v + ((px - a.px) * (b.v - a.v)) / (b.px - a.px);
    };
    const fx = fit(ticks('axis-x', 0));
    const fy = fit(ticks('axis-y', 1));
    const solid = [...el.querySelectorAll('g.lines path')].find((p) => !p.getAttribute('stroke-dasharray'))!;
    const pts = [...(solid.getAttribute('d') ?? '').matchAll(/[ML]([-\d.e]+),([-\d.e]+)/g)].map((m) => ({
      x: fx(Number(m[1])),
      y: fy(Number(m[2])),
    }));
    const dot = el.querySelector('g.marker circle');
    const marker = dot ? { x: fx(Number(dot.getAttribute('cx'))), y: fy(Number(dot.getAttribute('cy'))) } : null;
    return { first: pts[0], last: pts[pts.length - 1], marker };
  });
}

test('with Forces on, the report prints the chosen force plot with its axes and units, its ends the oracle’s (issue 34, 12)', async ({
  page,
}) => {
  // forces.spec.ts's crank-rocker in mm with every load, θ2 = 60°.
  await page.goto(
    './?r1=600&r2=200&r3=500&r4=500&pd=250&pa=30&lu=mm&frc=1&rho=2.5&pfx=40&pfy=-25&tl=-3&w2=7.5&a2=20&t2=60&plot=trq',
  );
  await waitReady(page);
  const shown = (await page.getByTestId('forces-torque').innerText()).trim();
  await page.emulateMedia({ media: 'print' });
  const sheet = page.getByTestId('print-report');
  await expect(sheet).toBeVisible();
  const plot = sheet.locator('[data-report-plot="torque"] svg');
  await expect(plot).toBeVisible();
  // The figure sits in the Forces section, with its title, its axis labels and units.
  const forces = sheet.locator('section', { has: page.getByRole('heading', { name: 'Forces', exact: true }) });
  await expect(forces.locator('[data-report-plot="torque"]')).toHaveCount(1);
  await expect(plot.locator('text', { hasText: /^θ2 \(°\)$/ }).first()).toBeAttached();
  await expect(plot.locator('text', { hasText: /^T12 \(N·m\)$/ }).first()).toBeAttached();
  await expect(plot.locator('text', { hasText: /^Input torque T12 against θ2$/ }).first()).toBeAttached();
  // Its ends are θ2 = 0° and 360°, both at the oracle's T12(0°) (the same pose); its marker at θ2 = 60° is the panel's.
  const ends = await plotEnds(plot);
  const ref0 = oracleTorque(0);
  const ref60 = oracleTorque(60);
  const span = Math.abs(ref0) + Math.abs(ref60);
  // Read from pixels (3 decimals) through the tick labels: within 0.5 % of the torques' size.
  expect(Math.abs(ends.first.x)).toBeLessThan(0.05);
  expect(Math.abs(ends.last.x - 360)).toBeLessThan(0.05);
  expect(Math.abs(ends.first.y - ref0), 'T12 at 0°').toBeLessThan(5e-3 * span);
  expect(Math.abs(ends.last.y - ref0), 'T12 at 360°').toBeLessThan(5e-3 * span);
  expect(Math.abs(ends.marker!.x - 60)).toBeLessThan(0.05);
  const panelTorque = Number(shown.replace('\u2212', '-').split(' ')[0]);
  expect(Math.abs(panelTorque - ref60)).toBeLessThanOrEqual(5e-6 * Math.abs(ref60));
  expect(Math.abs(ends.marker!.y - panelTorque), 'marker').toBeLessThan(5e-3 * span);
  await page.screenshot({ path: artifact('print-forces-plot.png'), fullPage: true });
  const pdf = await page.pdf({ format: 'A4' });
  expect(pdfPages(pdf)).toBeLessThanOrEqual(2);
});

test('with Forces on and Pin forces chosen, the report prints the pin-force plot instead', async ({ page }) => {
  await page.goto('./?frc=1&plot=pin&lang=zh-TW');
  await waitReady(page);
  await page.emulateMedia({ media: 'print' });
  const plot = page.locator('[data-testid="print-report"] [data-report-plot="pinForces"] svg');
  await expect(plot).toBeVisible();
  await expect(plot.locator('g.lines path')).toHaveCount(4);
  await expect(plot.locator('text', { hasText: /^\|F\| \(k?N\)$/ }).first()).toBeAttached();
});
