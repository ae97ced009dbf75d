import AxeBuilder from '@axe-core/playwright';
import type { Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { readFile } from 'node:fs/promises';
import Decimal from 'decimal.js';
import { artifact } from './helpers';

// The mechanism page (issue 33) driven as a person does: the gallery and tpl=, a drag that changes the traced
// curve, a slider-crank built from nothing by keyboard and by pointer whose exported CSV is checked against the
// slider-crank's closed form (decimal.js, 40 digits), a mobility-2 linkage that refuses to run, a corrupted mech=,
// undo and redo, the phone, zh-TW and axe.

Decimal.set({ precision: 40 });

/** The templates' keys and their URL values, as the issue names them (tpl=slider-crank, tpl=jansen). */
const TEMPLATES: [key: string, tpl: string, name: string][] = [
  ['fourBar', 'four-bar', 'Four-bar'],
  ['sliderCrank', 'slider-crank', 'Slider-crank'],
  ['invertedSliderCrank', 'inverted-slider-crank', 'Inverted slider-crank'],
  ['whitworth', 'whitworth', 'Whitworth quick return'],
  ['scotchYoke', 'scotch-yoke', 'Scotch yoke'],
  ['pistonDriven', 'piston-driven', 'Piston-driven crank'],
  ['wattI', 'watt-i', 'Watt I six-bar'],
  ['wattII', 'watt-ii', 'Watt II six-bar'],
  ['stephensonI', 'stephenson-i', 'Stephenson I six-bar'],
  ['stephensonII', 'stephenson-ii', 'Stephenson II six-bar'],
  ['stephensonIII', 'stephenson-iii', 'Stephenson III six-bar'],
  ['jansen', 'jansen', 'Jansen’s leg'],
  ['klann', 'klann', 'Klann’s leg'],
  ['peaucellier', 'peaucellier', 'Peaucellier–Lipkin'],
  ['chebyshev', 'chebyshev', 'Chebyshev straight line'],
  ['hoekens', 'hoekens', 'Hoekens straight line'],
];

const workspace = (page: Page) => page.locator('.mech-workspace');
/** The canvas's box: data-input is the input drawn, data-pose a digest of the pose drawn. */
const stage = (page: Page) => page.locator('.mech-stage');
const status = (page: Page) => page.getByTestId('mech-status');

/** Types a number into a labelled field of the joints table and commits it with Enter. */
async function typeField(page: Page, name: string, value: string): Promise<void> {
  const f = page.getByRole('textbox', { name, exact: true });
  await f.fill(value);
  await f.press('Enter');
}

/** The CSV of the page's Export CSV, parsed into a header and rows of numbers. */
/** Where the canvas draws a joint as drawn (input 0), in page pixels: its coordinates from the table, the view from data-view. */
async function screenOf(page: Page, id: string): Promise<{ x: number; y: number }> {
  const canvas = page.getByTestId('mech-canvas');
  const box = (await canvas.boundingBox())!;
  const [scale, cx, cy, panX, panY] = (await canvas.getAttribute('data-view'))!.split(' ').map(Number);
  const x = Number(await page.getByRole('textbox', { name: `x of ${id}`, exact: true }).inputValue());
  const y = Number(await page.getByRole('textbox', { name: `y of ${id}`, exact: true }).inputValue());
  return {
    x: box.x + box.width / 2 + (x - cx) * scale + panX,
    y: box.y + box.height / 2 - (y - cy) * scale + panY,
  };
}

async function exportedCsv(page: Page): Promise<{ header: string[]; rows: number[][] }> {
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'Export CSV' }).click(),
  ]);
  const text = await readFile((await download.path())!, 'utf8');
  const [head, ...lines] = text.trim().split('\n');
  return { header: head.split(','), rows: lines.map((l) => l.split(',').map(Number)) };
}

/**
 * The slider pin B of the offset slider-crank at crank angle θ (rad), from its drawn pin positions, in 40 digits:
 * A = r (cos θ, sin θ) about O = (0, 0), B on the line y = e, B.x = A.x + √(l² − (e − A.y)²).
 */
function sliderPinX(a0: [string, string], b0: [string, string], theta: number): Decimal {
  const [ax0, ay0] = a0.map((s) => new Decimal(s));
  const [bx0, by0] = b0.map((s) => new Decimal(s));
  const r = ax0.pow(2).plus(ay0.pow(2)).sqrt();
  const l2 = bx0.minus(ax0).pow(2).plus(by0.minus(ay0).pow(2));
  const th = new Decimal(theta).plus(Decimal.atan2(ay0, ax0));
  const ax = r.times(Decimal.cos(th));
  const ay = r.times(Decimal.sin(th));
  return ax.plus(l2.minus(by0.minus(ay).pow(2)).sqrt());
}

/**
 * The input torque (N·m) of the offset slider-crank at crank angle θ (rad), its crank r and rod l uniform bars of
 * rho kg/m, its block massless, gravity g down and the crank at a constant ω: the power balance in closed form,
 * derived here (' = d/dθ; l sin φ = e − r sin θ; G2 = A/2, G3 = A + (l/2)(cos φ, sin φ)):
 * T = ω² (m2 G2''·G2' + m3 G3''·G3' + I3 φ'' φ') + g (m2 G2'y + m3 G3'y), in 40 digits.
 */
function sliderCrankTorque(r: number, l: number, e: number, rho: number, g: number, w: number, theta: number): number {
  const D = (x: number) => new Decimal(x);
  const [R, L, E] = [D(r), D(l), D(e)];
  const c = Decimal.cos(theta);
  const s = Decimal.sin(theta);
  const sphi = E.minus(R.times(s)).div(L);
  const cphi = D(1).minus(sphi.pow(2)).sqrt();
  const p1 = R.times(c).neg().div(L.times(cphi));
  const p2 = R.times(s)
    .plus(L.times(sphi).times(p1.pow(2)))
    .div(L.times(cphi));
  const m2 = D(rho).times(R);
  const m3 = D(rho).times(L);
  const i3 = m3.times(L.pow(2)).div(12);
  const h = L.div(2);
  const g2d = [R.times(s).neg().div(2), R.times(c).div(2)];
  const g2dd = [R.times(c).neg().div(2), R.times(s).neg().div(2)];
  const g3d = [R.times(s).neg().minus(h.times(sphi).times(p1)), R.times(c).plus(h.times(cphi).times(p1))];
  const g3dd = [
    R.times(c)
      .neg()
      .minus(h.times(cphi.times(p1.pow(2)).plus(sphi.times(p2)))),
    R.times(s)
      .neg()
      .minus(h.times(sphi.times(p1.pow(2)).minus(cphi.times(p2)))),
  ];
  const dot = (u: Decimal[], v: Decimal[]) => u[0].times(v[0]).plus(u[1].times(v[1]));
  const inertial = m2
    .times(dot(g2dd, g2d))
    .plus(m3.times(dot(g3dd, g3d)))
    .plus(i3.times(p2).times(p1));
  return D(w)
    .pow(2)
    .times(inertial)
    .plus(D(g).times(m2.times(g2d[1]).plus(m3.times(g3d[1]))))
    .toNumber();
}

/** A number as the page writes it (U+2212 minus, a unit after it). */
const shownNumber = (text: string) => Number(text.replace(/\u2212/g, '-').split(' ')[0]);

test.describe('mechanism page', () => {
  test('opens every template from the gallery and from tpl=, each assembled and running', async ({ page }) => {
    await page.goto('./?page=mech');
    await expect(page.getByRole('tab', { name: 'Mechanisms' })).toHaveAttribute('aria-selected', 'true');
    for (const [key, , name] of TEMPLATES) {
      await page.locator(`.mech-template[data-template="${key}"]`).click();
      await expect(page.locator('.mech-name-title')).toHaveText(name);
      await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
      await expect(page.getByTestId('mech-mobility')).toHaveText('Mobility 1');
    }
    for (const [, tpl, name] of TEMPLATES.filter((_, i) => i % 5 === 1)) {
      await page.goto(`./?page=mech&tpl=${tpl}`);
      await expect(page.locator('.mech-name-title')).toHaveText(name);
      await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    }
    await page.screenshot({ path: artifact('mechanism-klann-1280.png') });
  });

  test('a dragged joint changes the traced curve, and undo and redo move it back and forth', async ({ page }) => {
    await page.goto('./?page=mech&tpl=four-bar');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    const before = await workspace(page).getAttribute('data-trace');
    const canvas = page.getByTestId('mech-canvas');
    const x0 = Number(await page.getByRole('textbox', { name: 'x of O4', exact: true }).inputValue());
    await page.getByRole('radio', { name: 'Choose B' }).check();
    // Arrow keys on the canvas move the chosen joint (the keyboard's drag): 10 px right, then a pointer drag.
    await canvas.focus();
    await canvas.press('Shift+ArrowRight');
    await expect(workspace(page)).not.toHaveAttribute('data-trace', before!);
    const afterKeys = await workspace(page).getAttribute('data-trace');
    await expect(page).toHaveURL(/mech=m1/);
    // Undo brings the template back (no mech= in the link), redo the edit.
    await page.getByRole('button', { name: 'Undo' }).click();
    await expect(workspace(page)).toHaveAttribute('data-trace', before!);
    await page.getByRole('button', { name: 'Redo' }).click();
    await expect(workspace(page)).toHaveAttribute('data-trace', afterKeys!);
    // A pointer drag of the rocker's pivot O4, grabbed where the canvas draws it (its view in data-view).
    const at = await screenOf(page, 'O4');
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    await page.mouse.move(at.x + 30, at.y - 20, { steps: 4 });
    await page.mouse.up();
    await expect(workspace(page)).not.toHaveAttribute('data-trace', afterKeys!);
    const x1 = Number(await page.getByRole('textbox', { name: 'x of O4', exact: true }).inputValue());
    const scale = Number((await page.getByTestId('mech-canvas').getAttribute('data-view'))!.split(' ')[0]);
    expect(x1 - x0).toBeCloseTo(30 / scale, 1);
    await page.getByRole('button', { name: 'Undo' }).click();
    await expect(workspace(page)).toHaveAttribute('data-trace', afterKeys!);
  });

  test('a held drag redraws the linkage at each move and its traced curve once the pointer rests, one undo step', async ({
    page,
  }) => {
    await page.goto('./?page=mech&tpl=jansen');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    const trace0 = (await workspace(page).getAttribute('data-trace'))!;
    const pose0 = (await stage(page).getAttribute('data-pose'))!;
    const at = await screenOf(page, 'G');
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    await page.mouse.move(at.x + 12, at.y, { steps: 3 });
    // Held: the linkage is drawn moved, and once the pointer rests its curve follows, before it is let go.
    await expect(stage(page)).not.toHaveAttribute('data-pose', pose0);
    await expect(workspace(page)).not.toHaveAttribute('data-trace', trace0);
    await expect(page).not.toHaveURL(/mech=/);
    await page.mouse.up();
    await expect(page).toHaveURL(/mech=m1/);
    const trace1 = (await workspace(page).getAttribute('data-trace'))!;
    await page.getByRole('button', { name: 'Undo' }).click();
    await expect(workspace(page)).toHaveAttribute('data-trace', trace0);
    await expect(stage(page)).toHaveAttribute('data-pose', pose0);
    await page.getByRole('button', { name: 'Redo' }).click();
    await expect(workspace(page)).toHaveAttribute('data-trace', trace1);
  });

  test('builds a slider-crank from nothing by keyboard, plays it, and exports a CSV that matches the closed form', async ({
    page,
  }) => {
    await page.goto('./?page=mech&tpl=four-bar');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    const press = async (name: string) => {
      const b = page.getByRole('button', { name, exact: true });
      await b.focus();
      await b.press('Enter');
    };
    await press('New (empty)');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'noInput');
    await press('Add link');
    await press('Add pin');
    await press('Add link');
    await press('Add pin');
    await press('Add link');
    await press('Add pin');
    // The slider: its block is link3, its guide the ground.
    await page.getByRole('combobox', { name: 'First link of a new part' }).selectOption('link3');
    await page.getByRole('combobox', { name: 'Second link of a new part (a slider’s guide)' }).selectOption('ground');
    await press('Add slider');
    await expect(page.getByTestId('mech-mobility')).toHaveText('Mobility 1');
    // Exact coordinates: crank 2 along +x, rod to the slider line y = 1 (l = 5 from the coordinates).
    const bx = String(2 + Math.sqrt(24));
    await typeField(page, 'x of J1', '0');
    await typeField(page, 'y of J1', '0');
    await typeField(page, 'x of J2', '2');
    await typeField(page, 'y of J2', '0');
    await typeField(page, 'x of J3', bx);
    await typeField(page, 'y of J3', '1');
    await typeField(page, 'x of S1', bx);
    await typeField(page, 'y of S1', '1');
    await page.getByRole('combobox', { name: 'Input' }).selectOption('J1');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    await expect(status(page)).toHaveText('The input turns fully.');
    // Play, wait for the input to move, pause.
    await page.getByRole('button', { name: 'Play' }).press('Enter');
    await expect(stage(page)).not.toHaveAttribute('data-input', '0');
    await page.getByRole('button', { name: 'Pause' }).press('Enter');
    const csv = await exportedCsv(page);
    expect(csv.header).toEqual(['input', 'J1_x', 'J1_y', 'J2_x', 'J2_y', 'J3_x', 'J3_y', 'S1_x', 'S1_y']);
    expect(csv.rows).toHaveLength(360);
    expect(csv.rows[0][0]).toBe(0);
    for (const k of [0, 37, 90, 181, 270, 359]) {
      const row = csv.rows[k];
      expect(row[0]).toBeCloseTo((k * Math.PI) / 180, 14);
      const want = sliderPinX(['2', '0'], [bx, '1'], row[0]);
      // The pin is solved by the engine to rounding: 1e-9 of the linkage's size is far above its error.
      expect(Math.abs(row[5] - want.toNumber()), `J3_x at ${k}°`).toBeLessThan(1e-9);
      expect(row[6]).toBeCloseTo(1, 12);
    }
  });

  test('builds a slider-crank by pointer: taps place the parts, the table’s menus join them, Play runs', async ({
    page,
  }) => {
    await page.goto('./?page=mech&tpl=four-bar');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    const canvas = page.getByTestId('mech-canvas');
    const box = (await canvas.boundingBox())!;
    const tap = (fx: number, fy: number) => page.mouse.click(box.x + fx * box.width, box.y + fy * box.height);
    await page.getByRole('button', { name: 'New (empty)' }).click();
    await page.getByRole('button', { name: 'Add link' }).click();
    await page.getByRole('button', { name: 'Add pin' }).click();
    await expect(page.getByText('Tap the canvas where the pin goes')).toBeVisible();
    await tap(0.3, 0.5);
    await page.getByRole('button', { name: 'Add link' }).click();
    await page.getByRole('button', { name: 'Add pin' }).click();
    await tap(0.4, 0.35);
    await page.getByRole('button', { name: 'Add link' }).click();
    await page.getByRole('button', { name: 'Add pin' }).click();
    await tap(0.75, 0.5);
    await page.getByRole('combobox', { name: 'First link of a new part' }).selectOption('link3');
    await page.getByRole('combobox', { name: 'Second link of a new part (a slider’s guide)' }).selectOption('ground');
    await page.getByRole('button', { name: 'Add slider' }).click();
    // A tap on the pin J3 places the slider on it (an armed tool snaps to the joint under the pointer).
    const j3 = await screenOf(page, 'J3');
    await page.mouse.click(j3.x, j3.y);
    await expect(page.getByRole('textbox', { name: 'x of S1', exact: true })).toHaveValue(
      await page.getByRole('textbox', { name: 'x of J3', exact: true }).inputValue(),
    );
    await page.getByRole('combobox', { name: 'Input' }).selectOption('J1');
    await expect(page.getByTestId('mech-mobility')).toHaveText('Mobility 1');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    await page.getByRole('button', { name: 'Play' }).click();
    await expect(stage(page)).not.toHaveAttribute('data-input', '0');
    await page.getByRole('button', { name: 'Pause' }).click();
  });

  test('with Forces on, the slider-crank’s input torque at 30° is the closed form’s', async ({ page }) => {
    // Lengths in metres (lu=m), bars of 2 kg/m (mrho), the crank at 12 rad/s (mw), gravity 9.81 m/s² down.
    await page.goto('./?page=mech&tpl=slider-crank&lu=m&mrho=2&mw=12');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    await page.getByRole('checkbox', { name: 'Solve the forces' }).check();
    await expect(page).toHaveURL(/mfrc=1/);
    await page.getByRole('slider', { name: /Input angle/ }).fill('30');
    await expect(page.getByTestId('mech-input-value')).toHaveText('30°');
    const effort = page.getByTestId('mech-effort');
    await expect(effort).toHaveText(/N·m$/);
    await expect(effort).not.toHaveText(/^—/);
    const expected = sliderCrankTorque(2, 5, 1, 2, 9.81, 12, Math.PI / 6);
    const shown = shownNumber((await effort.textContent())!);
    // Six significant digits are shown.
    expect(Math.abs(shown - expected)).toBeLessThan(1e-5 * Math.abs(expected));
    await expect(page.getByTestId('mech-force-chart-1')).toBeVisible();
    await page.getByRole('checkbox', { name: 'Reaction arrows' }).check();
    await page.locator('.mech-forces').scrollIntoViewIfNeeded();
    await page.screenshot({ path: artifact('mechanism-forces-1280.png') });
    await page.setViewportSize({ width: 390, height: 844 });
    await page.locator('.mech-force-values').scrollIntoViewIfNeeded();
    await page.screenshot({ path: artifact('mechanism-forces-390.png') });
  });

  test('Save after an edit writes the mechanism section, and Open in a fresh page gives the same joints back', async ({
    page,
    browser,
  }) => {
    // Two pages, a download, an upload and a CSV export: more than the default minute on a busy machine.
    test.slow();
    await page.goto('./?page=mech&tpl=slider-crank');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    // A typed coordinate (the crank pin moved off the line), the input at 30° by keyboard, plot 2 and the arrows.
    await typeField(page, 'x of A', '1.5');
    await typeField(page, 'y of A', '0.5');
    const b0: [string, string] = [
      await page.getByRole('textbox', { name: 'x of B', exact: true }).inputValue(),
      await page.getByRole('textbox', { name: 'y of B', exact: true }).inputValue(),
    ];
    const slider = page.getByRole('slider', { name: /^Input angle at O2/ });
    await slider.focus();
    for (let i = 0; i < 30; i++) await slider.press('ArrowRight');
    await expect(page.getByTestId('mech-input-value')).toHaveText('30°');
    await page.getByRole('combobox', { name: 'Plot 2' }).selectOption('accel:B');
    await page.getByRole('checkbox', { name: 'Velocity vectors' }).check();
    await page.getByRole('button', { name: 'Reverse' }).click();
    await expect(page).toHaveURL(/mdir=rev/);

    const download = page.waitForEvent('download');
    await page.getByRole('button', { name: 'Save design' }).click();
    const saved = await download;
    expect(saved.suggestedFilename()).toBe('mechanism_slider-crank_edited.fourbar.json');
    const path = artifact('mechanism.fourbar.json');
    await saved.saveAs(path);
    const file = JSON.parse(await readFile(path, 'utf8'));
    expect(file.page).toBe('mech');
    // The slider-crank is the default template: tpl is left out, as in a link.
    expect(file.mechanism).toMatchObject({ mdir: 'rev', mvel: true, mp: '2*slide%3AS*accel%3AB' });
    expect(file.mechanism).not.toHaveProperty('tpl');
    expect(file.mechanism.mi).toBeCloseTo(Math.PI / 6, 12);
    expect(file.mechanism.mech.joints[1]).toMatchObject({ id: 'A', x: 1.5, y: 0.5 });

    // A fresh browser (no autosave, no history), on the simulator: Open switches to the Mechanisms page.
    const fresh = await browser.newContext({ acceptDownloads: true });
    const other = await fresh.newPage();
    await other.goto('./');
    const chooser = other.waitForEvent('filechooser');
    await other.getByRole('button', { name: 'Open design' }).click();
    await (await chooser).setFiles(path);
    await expect(other.getByRole('tab', { name: 'Mechanisms' })).toHaveAttribute('aria-selected', 'true');
    await expect(workspace(other)).toHaveAttribute('data-mech-state', 'ok');
    await expect(other.locator('.mech-name-title')).toHaveText('Slider-crank (edited)');
    await expect(other.getByRole('textbox', { name: 'x of A', exact: true })).toHaveValue('1.5');
    await expect(other.getByRole('textbox', { name: 'y of A', exact: true })).toHaveValue('0.5');
    await expect(other.getByTestId('mech-input-value')).toHaveText('30°');
    await expect(other.getByRole('combobox', { name: 'Plot 2' })).toHaveValue('accel:B');
    await expect(other.getByRole('checkbox', { name: 'Velocity vectors' })).toBeChecked();
    await expect(other.getByRole('button', { name: 'Reverse' })).toHaveAttribute('aria-pressed', 'true');
    await expect(other).toHaveURL(/page=mech/);
    // The slider pin B over the cycle is the closed form's for the typed crank pin (not a value read from the app).
    const csv = await exportedCsv(other);
    expect(csv.header.slice(0, 7)).toEqual(['input', 'O2_x', 'O2_y', 'A_x', 'A_y', 'B_x', 'B_y']);
    for (const k of [0, 30, 123, 300]) {
      const row = csv.rows[k];
      const want = sliderPinX(['1.5', '0.5'], b0, row[0]);
      expect(Math.abs(row[5] - want.toNumber()), `B_x at ${k}°`).toBeLessThan(1e-9);
    }
    await other.evaluate(() => window.scrollTo(0, 0));
    await other.screenshot({ path: artifact('mechanism-reopened-1280.png') });
    await fresh.close();
  });

  test('a mobility-2 linkage refuses to run and says what to do', async ({ page }) => {
    // A five-bar: ground and four moving links in a loop, five pins: mobility 3·4 − 2·5 = 2.
    const fiveBar = {
      links: ['ground', 'a', 'b', 'c', 'd'],
      joints: [
        { id: 'O1', kind: 'R', links: ['ground', 'a'], x: 0, y: 0 },
        { id: 'A', kind: 'R', links: ['a', 'b'], x: 1, y: 2 },
        { id: 'B', kind: 'R', links: ['b', 'c'], x: 3, y: 3 },
        { id: 'C', kind: 'R', links: ['c', 'd'], x: 5, y: 2 },
        { id: 'O2', kind: 'R', links: ['d', 'ground'], x: 6, y: 0 },
      ],
      input: { joint: 'O1' },
    };
    await page.goto(`./?page=mech&mech=${encodeURIComponent(JSON.stringify(fiveBar))}`);
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'mobility');
    await expect(page.getByTestId('mech-mobility')).toHaveText('Mobility 2');
    await expect(status(page)).toHaveText(/^Mobility 2: the linkage has 1 freedom too many\. Add a link/);
    await expect(page.getByRole('button', { name: 'Play' })).toBeDisabled();
    await expect(page.getByRole('button', { name: 'Export CSV' })).toBeDisabled();
  });

  test('a corrupted mech= is refused and named, and the last good linkage is kept', async ({ page }) => {
    await page.goto('./?page=mech&tpl=jansen&mech=m1*3*ground*crank');
    await expect(page.getByTestId('url-notice')).toContainText('mech');
    await expect(page.getByTestId('mech-refused')).toContainText('the code ends before links[2]');
    await expect(page.locator('.mech-name-title')).toHaveText('Jansen’s leg');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
  });

  test('the phone layout keeps Play and the input in reach at 390×844', async ({ page }) => {
    await page.setViewportSize({ width: 390, height: 844 });
    await page.goto('./?page=mech&tpl=jansen');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    const play = page.getByRole('button', { name: 'Play' });
    await expect(play).toBeInViewport();
    const b = (await play.boundingBox())!;
    expect(b.y + b.height).toBeLessThanOrEqual(844);
    expect(b.height).toBeGreaterThanOrEqual(32);
    await page.screenshot({ path: artifact('mechanism-jansen-390.png') });
    // Scrolled to the editor, the bar stays on screen.
    await page.locator('.mech-table').scrollIntoViewIfNeeded();
    await expect(play).toBeInViewport();
    await page.setViewportSize({ width: 360, height: 740 });
    await expect(play).toBeInViewport();
  });

  test('the embed shows the page at 600×450: the linkage, Play and the plots', async ({ page }) => {
    await page.setViewportSize({ width: 600, height: 450 });
    await page.goto('./embed.html?page=mech&tpl=slider-crank');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    await expect(page.getByRole('button', { name: 'Play' })).toBeInViewport();
    await expect(page.getByRole('button', { name: 'Add pin' })).toBeHidden();
    await page.screenshot({ path: artifact('mechanism-embed-600.png') });
  });

  test('the embed with lock=edit says editing is locked (en and zh-TW), and a drag moves nothing', async ({ page }) => {
    await page.setViewportSize({ width: 600, height: 450 });
    await page.goto('./embed.html?page=mech&tpl=four-bar&lock=edit');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    const hint = page.getByTestId('mech-edit-locked');
    await expect(hint).toHaveText('Editing locked');
    await expect(hint).toBeInViewport();
    await expect(page.getByTestId('mech-canvas')).toHaveAccessibleName(/editing locked/);
    const pose = (await stage(page).getAttribute('data-pose'))!;
    const box = (await page.getByTestId('mech-canvas').boundingBox())!;
    const [scale, cx, cy, panX, panY] = (await page.getByTestId('mech-canvas').getAttribute('data-view'))!
      .split(' ')
      .map(Number);
    // The crank's pivot O2 at (0, 0), where the canvas draws it (the embed has no joints table); unlocked, this drag
    // would move it.
    const o2 = { x: box.x + box.width / 2 - cx * scale + panX, y: box.y + box.height / 2 + cy * scale + panY };
    await page.mouse.move(o2.x, o2.y);
    await page.mouse.down();
    await page.mouse.move(o2.x + 40, o2.y + 25, { steps: 3 });
    await page.mouse.up();
    await expect(stage(page)).toHaveAttribute('data-pose', pose);
    await expect(page).not.toHaveURL(/mech=/);
    await page.screenshot({ path: artifact('mechanism-embed-locked-600.png') });
    await page.goto('./embed.html?page=mech&tpl=four-bar&lock=edit&lang=zh-TW');
    await expect(page.getByTestId('mech-edit-locked')).toHaveText('編輯已鎖定');
  });

  test('speaks zh-TW and has no axe violations', async ({ page }) => {
    await page.goto('./?page=mech&tpl=slider-crank&lang=zh-TW&mfrc=1');
    await expect(page.getByRole('tab', { name: '機構', exact: true })).toHaveAttribute('aria-selected', 'true');
    await expect(page.locator('.mech-name-title')).toHaveText('曲柄滑塊');
    await expect(status(page)).toHaveText('輸入可轉整圈。');
    await expect(page.getByRole('button', { name: '播放' })).toBeVisible();
    await expect(page.getByRole('checkbox', { name: '求解力' })).toBeChecked();
    await expect(page.getByTestId('mech-effort')).toHaveText(/N·m$/);
    await page.screenshot({ path: artifact('mechanism-zh-tw-1280.png') });
    const results = await new AxeBuilder({ page }).include('.mech').analyze();
    expect(results.violations.map((v) => `${v.id} (${v.impact}): ${v.nodes[0]?.target}`)).toEqual([]);
  });
});

/** The live stage's canvas (a worker draws Play and a joint's drag on it): data-mode, data-frames, data-input, … */
const live = (page: Page) => page.getByTestId('mech-live');

/** The live canvas's newest frame as one reading: its run, frames, input, pose digest and chosen joint's place. */
async function liveFrame(page: Page) {
  return live(page).evaluate((el: HTMLElement) => ({
    mode: el.dataset.mode ?? '',
    frames: Number(el.dataset.frames ?? 0),
    input: Number(el.dataset.input),
    pose: Number(el.dataset.pose),
    at: (el.dataset.selectedAt ?? '').split(' ').map(Number),
  }));
}

/** The world point (length unit) under page pixel p, from the canvas's box and its view (data-view). */
async function worldAt(page: Page, p: { x: number; y: number }): Promise<{ x: Decimal; y: Decimal }> {
  const canvas = page.getByTestId('mech-canvas');
  const box = (await canvas.boundingBox())!;
  const [scale, cx, cy, panX, panY] = (await canvas.getAttribute('data-view'))!.split(' ').map((s) => new Decimal(s));
  return {
    x: cx.plus(
      new Decimal(p.x)
        .minus(box.x + box.width / 2)
        .minus(panX)
        .div(scale),
    ),
    y: cy.minus(
      new Decimal(p.y)
        .minus(box.y + box.height / 2)
        .minus(panY)
        .div(scale),
    ),
  };
}

/**
 * The 6-2-5-5 four-bar's poses come from a 1° grid by linear interpolation: its crank pin A (radius 2 about O2) is off
 * its circle by at most 2 (1 − cos 0.5°) ≈ 7.6e-5; 2e-4 is above that and far below a wrong angle (1° ≈ 0.035).
 */
const GRID_TOL = 2e-4;

/** Opens the 6-2-5-5 four-bar and waits for its live stage's worker to have drawn once (a run then starts warm). */
async function openFourBarWithStage(page: Page): Promise<void> {
  await page.goto('./?page=mech&tpl=four-bar');
  await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
  await expect(live(page)).toHaveAttribute('data-stage', 'ready');
}

test.describe('mechanism page: the live stage', () => {
  test('Play is drawn by the worker, the crank pin where the input puts it, and Pause hands the canvas back there', async ({
    page,
  }) => {
    await openFourBarWithStage(page);
    await page.getByRole('radio', { name: 'Choose A' }).check();
    await page.getByRole('button', { name: 'Play' }).click();
    await expect(live(page)).toBeVisible();
    await expect(live(page)).toHaveAttribute('data-mode', 'play');
    await expect.poll(async () => (await liveFrame(page)).frames).toBeGreaterThan(5);
    // A frame the worker drew: the chosen pin A on the crank's circle at the frame's input, 2 (cos t, sin t).
    const f = await liveFrame(page);
    const t = new Decimal(f.input);
    const ax = Decimal.cos(t).times(2);
    const ay = Decimal.sin(t).times(2);
    expect(Math.hypot(f.at[0] - ax.toNumber(), f.at[1] - ay.toNumber()), `A at input ${f.input}`).toBeLessThan(
      GRID_TOL,
    );
    // The worker goes on drawing: more frames, other inputs.
    await expect.poll(async () => (await liveFrame(page)).input).not.toBe(f.input);
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(live(page)).toBeHidden();
    // The page's own canvas shows the worker's last frame: its input and pose (no jump), and the readout says it.
    const last = await liveFrame(page);
    await expect(stage(page)).toHaveAttribute('data-input', String(last.input));
    expect(Number(await stage(page).getAttribute('data-pose'))).toBe(last.pose);
    // The readout writes 4 significant digits and a degree sign.
    const deg = (last.input * 180) / Math.PI;
    const shown = parseFloat((await page.getByTestId('mech-input-value').textContent())!.replace(/\u2212/g, '-'));
    expect(Math.abs(shown - deg)).toBeLessThanOrEqual(Math.abs(deg) * 5e-4 + 1e-9);
  });

  test('a joint’s drag is drawn by the worker with the pin under the pointer, and the release hands it back there', async ({
    page,
  }) => {
    await openFourBarWithStage(page);
    const at = await screenOf(page, 'O4');
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    const to = { x: at.x + 30, y: at.y - 20 };
    await page.mouse.move(to.x, to.y, { steps: 4 });
    await expect(live(page)).toBeVisible();
    await expect(live(page)).toHaveAttribute('data-mode', 'show');
    // The dragged pivot O4 (chosen by the grab) drawn by the worker where the pointer is, in the canvas's world.
    const want = await worldAt(page, to);
    const scale = Number((await page.getByTestId('mech-canvas').getAttribute('data-view'))!.split(' ')[0]);
    // Half a CSS pixel: the pointer's position is whole pixels in the events.
    await expect
      .poll(async () => {
        const [x, y] = (await liveFrame(page)).at;
        return Math.hypot(x - want.x.toNumber(), y - want.y.toNumber()) * scale;
      })
      .toBeLessThan(0.75);
    const held = await liveFrame(page);
    await page.mouse.up();
    await expect(live(page)).toBeHidden();
    await expect(page).toHaveURL(/mech=m1/);
    // The page's canvas draws the released linkage as the worker last drew it, and the table holds the pin's place.
    expect(Number(await stage(page).getAttribute('data-pose'))).toBeCloseTo(held.pose, 4);
    const x = Number(await page.getByRole('textbox', { name: 'x of O4', exact: true }).inputValue());
    const y = Number(await page.getByRole('textbox', { name: 'y of O4', exact: true }).inputValue());
    expect(Math.hypot(x - held.at[0], y - held.at[1])).toBeLessThan(1e-9);
  });

  test('a new template during Play gets the stage’s canvas anew: its Play is drawn by the worker too', async ({
    page,
  }) => {
    await openFourBarWithStage(page);
    await page.getByRole('button', { name: 'Play' }).click();
    await expect(live(page)).toBeVisible();
    await page.locator('.mech-template[data-template="sliderCrank"]').click();
    await expect(page.locator('.mech-name-title')).toHaveText('Slider-crank');
    // The new canvas view's stage canvas, handed to the same worker, hidden until its own run draws.
    await expect(live(page)).toHaveAttribute('data-stage', 'attached');
    await expect(live(page)).toBeHidden();
    await page.getByRole('button', { name: 'Play' }).click();
    await expect(live(page)).toBeVisible();
    await expect.poll(async () => (await liveFrame(page)).frames).toBeGreaterThan(3);
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(live(page)).toBeHidden();
    await expect(stage(page)).toHaveAttribute('data-input', String((await liveFrame(page)).input));
  });

  test('at a limit the worker’s Play reverses and the page says why', async ({ page }) => {
    await page.goto('./?page=mech&tpl=piston-driven');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    await expect(live(page)).toHaveAttribute('data-stage', 'ready');
    // The fastest speed, by keyboard on its slider.
    await page.getByRole('slider', { name: 'Speed' }).press('End');
    await page.getByRole('button', { name: 'Play', exact: true }).click();
    await expect(live(page)).toHaveAttribute('data-mode', 'play');
    await expect(status(page)).toHaveText(/At a limit \(input .+\): the linkage cannot go on this way/);
    // Still drawn by the worker after the turn: the input moves on, back from the limit.
    const turned = await liveFrame(page);
    await expect.poll(async () => (await liveFrame(page)).input).not.toBe(turned.input);
    await expect(live(page)).toBeVisible();
    await page.getByRole('button', { name: 'Pause', exact: true }).click();
    await expect(live(page)).toBeHidden();
  });

  test('without OffscreenCanvas the page draws Play and a drag itself', async ({ page }) => {
    await page.addInitScript(() => {
      delete (window as unknown as { OffscreenCanvas?: unknown }).OffscreenCanvas;
      delete (HTMLCanvasElement.prototype as unknown as { transferControlToOffscreen?: unknown })
        .transferControlToOffscreen;
    });
    await page.goto('./?page=mech&tpl=four-bar');
    await expect(workspace(page)).toHaveAttribute('data-mech-state', 'ok');
    await expect(live(page)).toHaveCount(0);
    await page.getByRole('button', { name: 'Play' }).click();
    const inputs = new Set<string>();
    await expect
      .poll(async () => {
        inputs.add((await stage(page).getAttribute('data-input'))!);
        return inputs.size;
      })
      .toBeGreaterThan(3);
    await page.getByRole('button', { name: 'Pause' }).click();
    const pose0 = (await stage(page).getAttribute('data-pose'))!;
    const at = await screenOf(page, 'O4');
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    await page.mouse.move(at.x + 30, at.y - 20, { steps: 4 });
    await expect(stage(page)).not.toHaveAttribute('data-pose', pose0);
    await page.mouse.up();
    await expect(page).toHaveURL(/mech=m1/);
  });
});
