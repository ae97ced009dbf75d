import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import Decimal from 'decimal.js';
import { artifact, pngFacts } from './helpers';

// The Spatial page (issue 32). Oracles are computed here with decimal.js at 40 digits from the conventions of
// docs/spatial.md, not taken from the app: A = Rz(θ2)·(sin a2, 0, cos a2), B on the rocker's circle about O4 with
// A·B = cos a3, the open branch where (A − B)·∂B/∂θ4 > 0, rates from the differentiated constraint.

const D = Decimal.clone({ precision: 40 });
type V = [Decimal, Decimal, Decimal];
const d = (x: number | string) => new D(x);
const rad = (deg: number) => d(deg).times(D.acos(-1)).div(180);
const dot = (a: V, b: V) => a[0].times(b[0]).plus(a[1].times(b[1])).plus(a[2].times(b[2]));
const add = (a: V, b: V): V => [a[0].plus(b[0]), a[1].plus(b[1]), a[2].plus(b[2])];
const mul = (k: Decimal, a: V): V => [a[0].times(k), a[1].times(k), a[2].times(k)];
const cross = (a: V, b: V): V => [
  a[1].times(b[2]).minus(a[2].times(b[1])),
  a[2].times(b[0]).minus(a[0].times(b[2])),
  a[0].times(b[1]).minus(a[1].times(b[0])),
];

/** The open-branch pose of a spherical four-bar (degrees in), with rates for ω2 = 1 rad/s, α2 = 0. */
function sphericalOracle(a1Deg: number, a2Deg: number, a3Deg: number, a4Deg: number, t2Deg: number) {
  const [a1, a2, a3, a4, t2] = [rad(a1Deg), rad(a2Deg), rad(a3Deg), rad(a4Deg), rad(t2Deg)];
  const A: V = [a2.sin().times(t2.cos()), a2.sin().times(t2.sin()), a2.cos()];
  const dA: V = [a2.sin().times(t2.sin()).neg(), a2.sin().times(t2.cos()), d(0)];
  const ddA: V = [a2.sin().times(t2.cos()).neg(), a2.sin().times(t2.sin()).neg(), d(0)];
  const O4: V = [a1.sin(), d(0), a1.cos()];
  const u: V = [a1.cos(), d(0), a1.sin().neg()];
  const y: V = [d(0), d(1), d(0)];
  // A·B = cos a3 as P cos θ4 + Q sin θ4 = R.
  const P = a4.sin().times(dot(A, u));
  const Q = a4.sin().times(dot(A, y));
  const R = a3.cos().minus(a4.cos().times(dot(A, O4)));
  const phi = D.atan2(Q, P);
  const psi = D.acos(R.div(P.pow(2).plus(Q.pow(2)).sqrt()));
  const at = (t4: Decimal) => {
    const B = add(mul(a4.cos(), O4), mul(a4.sin(), add(mul(t4.cos(), u), mul(t4.sin(), y))));
    const dB = mul(a4.sin(), add(mul(t4.sin().neg(), u), mul(t4.cos(), y)));
    const ddB = mul(a4.sin(), add(mul(t4.cos().neg(), u), mul(t4.sin().neg(), y)));
    return { t4, B, dB, ddB };
  };
  const open = [at(phi.minus(psi)), at(phi.plus(psi))].find((c) => dot(add(A, mul(d(-1), c.B)), c.dB).gt(0))!;
  const { B, dB, ddB } = open;
  const F2 = dot(dA, B);
  const F4 = dot(A, dB);
  const omega4 = F2.neg().div(F4);
  const alpha4 = dot(ddA, B)
    .plus(dot(dA, dB).times(omega4).times(2))
    .plus(dot(A, ddB).times(omega4.pow(2)))
    .neg()
    .div(F4);
  // θ4 wrapped to (−180, 180] degrees.
  let t4Deg = open.t4.times(180).div(D.acos(-1));
  while (t4Deg.gt(180)) t4Deg = t4Deg.minus(360);
  while (t4Deg.lte(-180)) t4Deg = t4Deg.plus(360);
  return { A, B, t4Deg, omega4, alpha4 };
}

/** The coupler point at arc pd from A, turned by pa about A from the arc A→B (degrees in). */
function couplerOracle(A: V, B: V, pdDeg: number, paDeg: number): V {
  const n0 = cross(A, B);
  const n = mul(d(1).div(dot(n0, n0).sqrt()), n0);
  const t = cross(n, A);
  const [pd, pa] = [rad(pdDeg), rad(paDeg)];
  return add(mul(pd.cos(), A), mul(pd.sin(), add(mul(pa.cos(), t), mul(pa.sin(), n))));
}

/** The pin's shown x, y, z (seven significant digits). */
async function shownPin(page: Page, pin: 'A' | 'B' | 'P'): Promise<number[]> {
  const out: number[] = [];
  for (const axis of ['x', 'y', 'z']) {
    const text = await page.getByTestId(`pin-${pin}-${axis}`).innerText();
    // Every minus: a coordinate under 1e-4 reads in exponent form, its exponent's minus a '−' too (formatNumber).
    out.push(Number(text.replace(/−/g, '-')));
  }
  return out;
}

/** Expects the shown values to be the oracle's to the seven digits shown. */
function expectNear(shown: number[], oracle: V, what: string): void {
  oracle.forEach((v, i) => expect(Math.abs(shown[i] - v.toNumber()), `${what}[${i}]`).toBeLessThan(6e-7));
}

/** The largest difference between shown values and the oracle's. */
function farthest(shown: number[], oracle: V): number {
  return Math.max(...oracle.map((v, i) => Math.abs(shown[i] - v.toNumber())));
}

/**
 * The x domain a plot's axis draws (data units at its two ends), read from the SVG as a person's ruler would: the
 * axis line's pixel ends and two labelled ticks' positions, interpolated linearly.
 */
async function xAxisDomain(page: Page, testId: string): Promise<[number, number]> {
  return page.getByTestId(testId).evaluate((svg) => {
    const axis = svg.querySelector('g.axis-x')!;
    const d = axis.querySelector('path.domain')!.getAttribute('d')!;
    const m = /M([-\d.e]+),[-\d.e]+H([-\d.e]+)/.exec(d)!;
    const ticks = [...axis.querySelectorAll('g.tick')].map((t) => ({
      px: Number(/translate\(([-\d.e]+)/.exec(t.getAttribute('transform')!)![1]),
      v: Number(t.querySelector('text')!.textContent!.replace('−', '-')),
    }));
    const [a, b] = [ticks[0], ticks[ticks.length - 1]];
    const at = (px: number) => a.v + ((px - a.px) * (b.v - a.v)) / (b.px - a.px);
    return [at(Number(m[1])), at(Number(m[2]))] as [number, number];
  });
}

/**
 * Share of a PNG's pixels (bytes) that differ from a reference pixel's colour by more than threshold in a channel,
 * decoded by the browser's image decoder, not by the app (and on a page canvas: some tests delete OffscreenCanvas).
 * The reference: the corner, or the bottom's middle 5 px up (the card's colour, below the sphere at 1280x800).
 */
async function inkShare(page: Page, bytes: Buffer, threshold: number, reference: 'corner' | 'bottom'): Promise<number> {
  return page.evaluate(
    async ([b64, threshold, reference]) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.naturalWidth;
      c.height = img.naturalHeight;
      const ctx = c.getContext('2d')!;
      ctx.drawImage(img, 0, 0);
      const d = ctx.getImageData(0, 0, c.width, c.height).data;
      const o = reference === 'corner' ? 0 : 4 * ((c.height - 5) * c.width + (c.width >> 1));
      let n = 0;
      for (let i = 0; i < d.length; i += 4) {
        const diff = Math.max(Math.abs(d[i] - d[o]), Math.abs(d[i + 1] - d[o + 1]), Math.abs(d[i + 2] - d[o + 2]));
        if (diff > threshold) n++;
      }
      return n / (c.width * c.height);
    },
    [bytes.toString('base64'), threshold, reference] as const,
  );
}

/** Share of a PNG's pixels (bytes as downloaded) more than 24 from its corner's colour: 0 for a blank image. */
const pngInk = (page: Page, bytes: Buffer) => inkShare(page, bytes, 24, 'corner');

/**
 * Share of a view's screenshot not in the card's colour by more than 8 of 255: the faint sphere counts, so a view
 * without its fixed parts shows far less.
 */
const viewInk = (page: Page, bytes: Buffer) => inkShare(page, bytes, 8, 'bottom');

/** The PNG the Export 3D view PNG button downloads: its facts and bytes. */
async function exportPng(page: Page) {
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'Export 3D view PNG' }).click(),
  ]);
  return { facts: await pngFacts(download), bytes: readFileSync(await download.path()) };
}

/** The θ2 field's value (degrees). */
async function theta2Field(page: Page): Promise<number> {
  return Number(await page.getByRole('textbox', { name: 'Input angle θ2' }).inputValue());
}

async function openSpatial(page: Page, query = 'page=3d'): Promise<void> {
  await page.goto(`./?${query}`);
  await expect(page.getByTestId('spatial-page')).toBeVisible({ timeout: 20_000 });
}

test.describe('Spatial page', () => {
  test('opens from its tab, draws the sphere with WebGL and shows the numbers of the oracle', async ({ page }) => {
    await page.goto('./');
    await page.getByRole('tab', { name: 'Spatial' }).click();
    await expect(page.getByRole('heading', { name: 'Spatial four-bars' })).toBeVisible({ timeout: 20_000 });
    await expect.poll(() => new URL(page.url()).searchParams.get('page')).toBe('3d');
    // Headless Chromium here has --disable-gpu: WebGL comes from SwiftShader; the view must reach "ready".
    await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
    // SwiftShader is a software WebGL: the view draws its lean look (renderQuality), without MSAA (the context's own
    // attribute, read where the context lives: in the view's worker, which this browser can hand a canvas to).
    const canvas = page.getByTestId('spatial-canvas');
    await expect(canvas).toHaveAttribute('data-route', 'worker');
    await expect(canvas).toHaveAttribute('data-quality', 'lean');
    await expect(canvas).toHaveAttribute('data-antialias', 'false');
    const o = sphericalOracle(60, 20, 55, 45, 30);
    expectNear(await shownPin(page, 'A'), o.A, 'A');
    expectNear(await shownPin(page, 'B'), o.B, 'B');
    expectNear(await shownPin(page, 'P'), couplerOracle(o.A, o.B, 25, 40), 'P');
    await expect(page.getByTestId('spatial-type')).toHaveText('crank-rocker');
    // The canvas gets drawn: not one colour (as the screen shows it; the worker owns the canvas's pixels, and its
    // frame with the linkage reaches the screen after the view is ready).
    await expect.poll(async () => pngInk(page, await canvas.screenshot())).toBeGreaterThan(0.05);
    await page.screenshot({ path: artifact('spatial-desktop.png') });
  });

  test('a typed arc moves the pins to the oracle; a bad value is named and refused', async ({ page }) => {
    await openSpatial(page, 'page=3d&t2=75');
    const a2 = page.getByRole('textbox', { name: 'Crank arc a2' });
    await a2.fill('35');
    const o = sphericalOracle(60, 35, 55, 45, 75);
    await expect.poll(async () => (await shownPin(page, 'A'))[0]).toBeCloseTo(o.A[0].toNumber(), 6);
    expectNear(await shownPin(page, 'A'), o.A, 'A');
    expectNear(await shownPin(page, 'B'), o.B, 'B');
    await expect(page.getByTestId('spatial-theta4')).toHaveText(`${o.t4Deg.toFixed(4).replace('-', '−')}°`);
    await expect.poll(() => new URL(page.url()).searchParams.get('a2')).toBe('35');
    const a1 = page.getByRole('textbox', { name: 'Ground arc a1' });
    await a1.fill('200');
    await expect(page.getByRole('alert')).toContainText('Ground arc a1');
    await expect(page.getByRole('alert')).toContainText('200');
    // The last valid value is kept.
    expectNear(await shownPin(page, 'B'), o.B, 'B kept');
  });

  test('each preset opens, with its kind, type and keys in the link', async ({ page }) => {
    await openSpatial(page);
    const preset = page.getByRole('combobox', { name: 'Preset' });
    const cases = [
      ['Spherical drag link', 'double crank (drag link)', { sk: 'sph', a1: '20', a2: '45', pd: '0' }],
      ['Universal joint (90° arcs)', null, { a1: '30', a2: '90', a3: '90', a4: '90' }],
      ['RSSR skew drive', null, { sk: 'rssr', r2: '1', r3: '4', r4: '2', a: '3', beta: '60' }],
      ['RSSR = planar 6-2-5-5', 'crank-rocker', { sk: 'rssr', r2: '2', r3: '5', r4: '5', a: '6', beta: '0', h2: '0' }],
      ['Spherical crank-rocker', 'crank-rocker', { sk: 'sph', a1: '60', pd: '25', r2: '2' }],
    ] as const;
    for (const [name, type, keys] of cases) {
      await preset.selectOption({ label: name });
      if (type) await expect(page.getByTestId('spatial-type')).toHaveText(type);
      for (const [k, v] of Object.entries(keys)) {
        await expect.poll(() => new URL(page.url()).searchParams.get(k), `${name}: ${k}`).toBe(v);
      }
      await expect(page.getByTestId('pin-A-x')).not.toHaveText('—');
    }
    await preset.selectOption({ label: 'RSSR skew drive' });
    await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'ready');
    await page.waitForTimeout(300);
    await page.screenshot({ path: artifact('spatial-rssr.png') });
  });

  test('a rocking input: the plots span its reachable range, not a full turn; a crank gets the full turn', async ({
    page,
  }) => {
    // Arcs 50, 40, 30, 35: the arc d from A to O4 runs over [10°, 90°] and must stay within [|a3 − a4|, a3 + a4] =
    // [5°, 65°], so the crank rocks through |θ2| ≤ acos((cos 65° − cos 50° cos 40°) / (sin 50° sin 40°)), about 98.15°.
    await openSpatial(page, 'page=3d&sk=sph&a1=50&a2=40&a3=30&a4=35&pd=0&t2=10');
    const [a1, a2, a3, a4] = [rad(50), rad(40), rad(30), rad(35)];
    const tMax = D.acos(a3.plus(a4).cos().minus(a1.cos().times(a2.cos())).div(a1.sin().times(a2.sin())))
      .times(180)
      .div(D.acos(-1))
      .toNumber();
    await expect(page.getByTestId('spatial-type')).not.toHaveText('crank-rocker');
    for (const id of ['theta4', 'omega4', 'alpha4', 'mu']) {
      await expect(page.getByTestId(`spatial-plot-${id}`).locator('g.axis-x g.tick').first()).toBeAttached();
      const [lo, hi] = await xAxisDomain(page, `spatial-plot-${id}`);
      // The range the test computed, to a hundredth of a degree (the axis' pixels are not rounded).
      expect(Math.abs(lo + tMax), `${id} lower end ${lo}`).toBeLessThan(0.01);
      expect(Math.abs(hi - tMax), `${id} upper end ${hi}`).toBeLessThan(0.01);
    }
    await page.screenshot({ path: artifact('spatial-rocking.png'), fullPage: true });
    // The spherical crank-rocker preset turns fully: 0 to 360.
    await page.getByRole('combobox', { name: 'Preset' }).selectOption({ label: 'Spherical crank-rocker' });
    await expect(page.getByTestId('spatial-type')).toHaveText('crank-rocker');
    await expect
      .poll(async () => (await xAxisDomain(page, 'spatial-plot-theta4')).map((v) => Math.round(v * 1e6) / 1e6))
      .toEqual([0, 360]);
  });

  test("exports the CSV with the issue's columns; its first row is the oracle's", async ({ page }) => {
    await openSpatial(page);
    const [download] = await Promise.all([
      page.waitForEvent('download'),
      page.getByRole('button', { name: 'Export CSV' }).click(),
    ]);
    expect(download.suggestedFilename()).toBe('spatial_sph_60-20-55-45_open.csv');
    const lines = readFileSync(await download.path(), 'utf8')
      .trim()
      .split('\n');
    expect(lines[0]).toBe('theta2_deg,A_x,A_y,A_z,B_x,B_y,B_z,P_x,P_y,P_z,theta4_deg,omega4_rad_s,alpha4_rad_s2');
    expect(lines.length).toBe(1 + 361);
    const row = lines[1].split(',').map(Number);
    const o = sphericalOracle(60, 20, 55, 45, 0);
    const P = couplerOracle(o.A, o.B, 25, 40);
    const want = [d(0), ...o.A, ...o.B, ...P, o.t4Deg, o.omega4, o.alpha4];
    // Full precision: each number within a few ulps of its size (1e-13 relative, 1e-15 absolute near 0).
    want.forEach((w, i) => {
      const x = w.toNumber();
      expect(Math.abs(row[i] - x), `column ${i}`).toBeLessThanOrEqual(1e-13 * Math.max(1, Math.abs(x)));
    });
  });

  test('the input speed and acceleration (w2, al2) set the rates of the numbers and the CSV', async ({ page }) => {
    // With ω4 = g(θ2) ω2: α4 = g'(θ2) ω2² + g(θ2) α2, g and g' being the oracle's ω4 and α4 at ω2 = 1, α2 = 0.
    await openSpatial(page, 'page=3d&w2=2.5&al2=-3');
    await expect(page.getByRole('textbox', { name: 'Input speed ω2' })).toHaveValue('2.5');
    await expect(page.getByRole('textbox', { name: 'Input acceleration α2' })).toHaveValue('-3');
    const [w2, al2] = [d('2.5'), d(-3)];
    const at = (t2: number) => {
      const o = sphericalOracle(60, 20, 55, 45, t2);
      return { omega4: o.omega4.times(w2), alpha4: o.alpha4.times(w2.pow(2)).plus(o.omega4.times(al2)) };
    };
    const shown = at(30);
    await expect(page.getByTestId('spatial-omega4')).toContainText(
      shown.omega4.toSignificantDigits(6).toString().replace('-', '−'),
    );
    const [download] = await Promise.all([
      page.waitForEvent('download'),
      page.getByRole('button', { name: 'Export CSV' }).click(),
    ]);
    const lines = readFileSync(await download.path(), 'utf8')
      .trim()
      .split('\n');
    for (const t2 of [0, 90]) {
      const row = lines[1 + t2].split(',').map(Number);
      const o = at(t2);
      for (const [i, w] of [
        [11, o.omega4],
        [12, o.alpha4],
      ] as const) {
        const x = w.toNumber();
        expect(Math.abs(row[i] - x), `θ2 = ${t2}, column ${i}`).toBeLessThanOrEqual(1e-13 * Math.max(1, Math.abs(x)));
      }
    }
  });

  test('exports a PNG of the 3D view, drawn by its worker: twice the size and not blank', async ({ page }) => {
    await openSpatial(page);
    await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
    await expect(page.getByTestId('spatial-canvas')).toHaveAttribute('data-route', 'worker');
    const png = await exportPng(page);
    expect(png.facts.signatureOk).toBe(true);
    const box = (await page.getByTestId('spatial-canvas').boundingBox())!;
    expect(png.facts.width).toBe(Math.round(box.width) * 2);
    expect(png.facts.bytes).toBeGreaterThan(10_000);
    // The sphere, links and pins cover a good part of the view (a blank or one-colour image gives 0).
    expect(await pngInk(page, png.bytes)).toBeGreaterThan(0.1);
  });

  test('Play and orbit are drawn by the worker; the panels follow and Pause keeps the pose of the oracle', async ({
    page,
  }) => {
    await openSpatial(page, 'page=3d&t2=30');
    const canvas = page.getByTestId('spatial-canvas');
    await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
    await expect(canvas).toHaveAttribute('data-route', 'worker');
    const frames = async () => Number(await canvas.getAttribute('data-frames'));
    let f0 = await frames();
    await page.getByRole('button', { name: 'Play' }).click();
    // The worker's frames count on, and the θ2 field follows the worker's Play.
    await expect.poll(frames, { timeout: 20_000 }).toBeGreaterThan(f0 + 10);
    await expect.poll(() => theta2Field(page), { timeout: 20_000 }).not.toBe(30);
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
    const t2 = await theta2Field(page);
    // Pause commits the frame on screen: the numbers are the oracle's at the field's θ2, which rounds the committed θ2
    // to 0.01°: a pin moves at most |dB/dθ2| ≤ 3 (this linkage, unit sphere) × 0.005° = 2.6e-4 for that rounding.
    const o = sphericalOracle(60, 20, 55, 45, t2);
    await expect.poll(async () => farthest(await shownPin(page, 'A'), o.A)).toBeLessThan(3e-4);
    expect(farthest(await shownPin(page, 'B'), o.B)).toBeLessThan(3e-4);
    await expect.poll(() => new URL(page.url()).searchParams.get('t2')).not.toBe('30');
    // Orbit by keys and by a drag: the worker draws each.
    f0 = await frames();
    await page.locator('.spatial-canvas-host').press('ArrowRight');
    await expect.poll(frames).toBeGreaterThan(f0);
    f0 = await frames();
    const box = (await canvas.boundingBox())!;
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 20, { steps: 4 });
    await page.mouse.up();
    await expect.poll(frames).toBeGreaterThan(f0);
  });

  test('a held arrow key turns the view on the worker’s frames until it is released, or its repeats stop', async ({
    page,
  }) => {
    await openSpatial(page, 'page=3d');
    const canvas = page.getByTestId('spatial-canvas');
    await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
    await expect(canvas).toHaveAttribute('data-route', 'worker');
    const host = page.locator('.spatial-canvas-host');
    await host.focus();
    const frames = async () => Number(await canvas.getAttribute('data-frames'));
    const key = (type: 'keydown' | 'keyup', repeat: boolean) =>
      host.evaluate(
        (h, [t, r]) =>
          h.dispatchEvent(new KeyboardEvent(t, { key: 'ArrowRight', code: 'ArrowRight', repeat: r, bubbles: true })),
        [type, repeat] as const,
      );
    // True once the view has drawn nothing over 60 of the page's animation frames (the rest frame after a move included).
    const still = () =>
      canvas.evaluate(
        (c: HTMLCanvasElement) =>
          new Promise<boolean>((done) => {
            let last = c.dataset.frames;
            let quiet = 0;
            const tick = () => {
              quiet = c.dataset.frames === last ? quiet + 1 : 0;
              last = c.dataset.frames;
              if (quiet >= 60) done(true);
              else requestAnimationFrame(tick);
            };
            requestAnimationFrame(tick);
          }),
      );
    await still();
    // A press and one repeat, and then no event at all: only the worker's own clock can draw 20 more frames.
    let f0 = await frames();
    await key('keydown', false);
    await key('keydown', true);
    await expect.poll(frames, { timeout: 20_000 }).toBeGreaterThan(f0 + 20);
    // One more repeat just before the release (as a held key sends them), so the hold's grace starts again there.
    await key('keydown', true);
    await key('keyup', false);
    const released = await frames();
    expect(await still()).toBe(true);
    // The release stops it at once: the hold's 600 ms of grace would draw about 36 frames more at 60 Hz.
    expect(await frames()).toBeLessThan(released + 20);
    // A held key whose release never comes (focus taken away by the system) stops when its repeats stop.
    f0 = await frames();
    await key('keydown', false);
    await key('keydown', true);
    await expect.poll(frames, { timeout: 20_000 }).toBeGreaterThan(f0 + 20);
    expect(await still()).toBe(true);
    const f1 = await frames();
    expect(await still()).toBe(true);
    expect(await frames()).toBe(f1);
  });

  test('without OffscreenCanvas the page draws the view itself: Play, the look and the PNG', async ({ page }) => {
    await page.addInitScript(() => {
      delete (globalThis as { OffscreenCanvas?: unknown }).OffscreenCanvas;
    });
    await openSpatial(page);
    const canvas = page.getByTestId('spatial-canvas');
    await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
    await expect(canvas).toHaveAttribute('data-route', 'main');
    await expect(canvas).toHaveAttribute('data-quality', 'lean');
    // The page's own context: its attribute read directly.
    expect(
      await canvas.evaluate(
        (c: HTMLCanvasElement) => (c.getContext('webgl2') ?? c.getContext('webgl'))?.getContextAttributes()?.antialias,
      ),
    ).toBe(false);
    const frames = async () => Number(await canvas.getAttribute('data-frames'));
    const f0 = await frames();
    await page.getByRole('button', { name: 'Play' }).click();
    await expect.poll(frames, { timeout: 20_000 }).toBeGreaterThan(f0 + 10);
    await expect.poll(() => theta2Field(page), { timeout: 20_000 }).not.toBe(30);
    await page.getByRole('button', { name: 'Pause' }).click();
    const t2 = await theta2Field(page);
    const o = sphericalOracle(60, 20, 55, 45, t2);
    // As above: within 3e-4 for the field's rounding of θ2.
    await expect.poll(async () => farthest(await shownPin(page, 'A'), o.A)).toBeLessThan(3e-4);
    const png = await exportPng(page);
    expect(png.facts.width).toBe(Math.round((await canvas.boundingBox())!.width) * 2);
    expect(await pngInk(page, png.bytes)).toBeGreaterThan(0.1);
  });

  test('the lean look draws Play with half the pixels and the view at rest at full resolution', async ({ page }) => {
    await openSpatial(page);
    const canvas = page.getByTestId('spatial-canvas');
    await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
    await expect(canvas).toHaveAttribute('data-quality', 'lean');
    const buffer = () => canvas.evaluate((c: HTMLCanvasElement) => ({ width: c.width, css: c.clientWidth }));
    // deviceScaleFactor 1; the worker's buffer size reaches the page's canvas with its first frame.
    await expect.poll(async () => (await buffer()).width).toBe((await buffer()).css);
    const rest = await buffer();
    await page.getByRole('button', { name: 'Play' }).click();
    // renderQuality's movingPixelRatio (0.5) while frames follow each other.
    await expect.poll(async () => (await buffer()).width).toBe(Math.floor(rest.css * 0.5));
    await page.getByRole('button', { name: 'Pause' }).click();
    // At rest (no frame for REST_MS) one more frame at full resolution: what a screenshot or the eye sees.
    await expect.poll(async () => (await buffer()).width).toBe(rest.css);
  });

  test("Play with the camera still draws on the fixed parts' layer, in the worker and on the page's thread", async ({
    page,
  }) => {
    for (const route of ['worker', 'main']) {
      if (route === 'main') {
        await page.addInitScript(() => {
          delete (globalThis as { OffscreenCanvas?: unknown }).OffscreenCanvas;
        });
      }
      await openSpatial(page);
      const canvas = page.getByTestId('spatial-canvas');
      await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
      await expect(canvas).toHaveAttribute('data-route', route);
      await expect(canvas).toHaveAttribute('data-quality', 'lean');
      const count = async (name: string) => Number((await canvas.getAttribute(name)) ?? 0);
      // The sphere covers much of the view once drawn (0.40 of it, at this size).
      const ink = async () => viewInk(page, await canvas.screenshot());
      await expect.poll(ink, { timeout: 20_000 }).toBeGreaterThan(0.25);
      const rest = await ink();
      const layer0 = await count('data-layer-frames');
      await page.getByRole('button', { name: 'Play' }).click();
      await expect.poll(() => count('data-layer-frames'), { timeout: 20_000 }).toBeGreaterThan(layer0 + 10);
      // A frame of Play on the layer shows the fixed parts too (the sphere, axes, paths), not the links alone.
      // (Without them: 0.11.)
      expect(await ink(), route).toBeGreaterThan(0.8 * rest);
      // Orbiting during Play draws in full: the view changes every frame.
      const f0 = await count('data-frames');
      const full0 = f0 - (await count('data-layer-frames'));
      const host = page.locator('.spatial-canvas-host');
      await host.press('ArrowRight');
      await expect.poll(() => count('data-frames')).toBeGreaterThan(f0);
      await expect
        .poll(async () => (await count('data-frames')) - (await count('data-layer-frames')))
        .toBeGreaterThan(full0);
      await page.getByRole('button', { name: 'Pause' }).click();
    }
  });

  test('reads in Traditional Chinese', async ({ page }) => {
    await openSpatial(page, 'page=3d&lang=zh-TW');
    await expect(page.getByRole('tab', { name: '空間機構' })).toHaveAttribute('aria-selected', 'true');
    await expect(page.getByRole('heading', { name: '空間四連桿' })).toBeVisible();
    await expect(page.getByRole('button', { name: '匯出 CSV' })).toBeVisible();
    await expect(page.getByTestId('spatial-type')).toHaveText('曲柄搖桿');
    await page.screenshot({ path: artifact('spatial-zh-TW.png') });
  });

  test('without WebGL: a clear message, and the numbers, plots and CSV still work', async ({ page }) => {
    await page.addInitScript(() => {
      const original = HTMLCanvasElement.prototype.getContext;
      HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, id: string, ...rest: unknown[]) {
        if (/webgl/i.test(id)) return null;
        return (original as (...a: unknown[]) => RenderingContext | null).call(this, id, ...rest);
      } as typeof original;
    });
    await openSpatial(page);
    await expect(page.getByTestId('spatial-no-webgl')).toContainText('WebGL', { timeout: 20_000 });
    await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'no-webgl');
    const o = sphericalOracle(60, 20, 55, 45, 30);
    expectNear(await shownPin(page, 'B'), o.B, 'B');
    // The PNG of the 3D view cannot be made: its button is off and says why; the CSV and the link stay on.
    const png = page.getByRole('button', { name: 'Export 3D view PNG' });
    await expect(png).toBeDisabled();
    await expect(png).toHaveAccessibleDescription(/needs WebGL/);
    await expect(page.getByText('The PNG of the 3D view needs WebGL')).toBeVisible();
    await expect(page.getByRole('button', { name: 'Export CSV' })).toBeEnabled();
    await expect(page.getByRole('button', { name: 'Copy link' })).toBeEnabled();
    await expect(page.getByTestId('spatial-plot-theta4').locator('path').first()).toBeAttached();
    const [download] = await Promise.all([
      page.waitForEvent('download'),
      page.getByRole('button', { name: 'Export CSV' }).click(),
    ]);
    expect(download.suggestedFilename()).toMatch(/\.csv$/);
    await page.screenshot({ path: artifact('spatial-no-webgl.png') });
  });

  for (const v of [
    { width: 390, height: 844 },
    { width: 360, height: 740 },
  ]) {
    test(`a ${v.width}x${v.height} phone: one column, the view first, no horizontal scroll`, async ({ browser }) => {
      const context = await browser.newContext({ viewport: v, deviceScaleFactor: 2, hasTouch: true, isMobile: true });
      const page = await context.newPage();
      await openSpatial(page);
      await expect(page.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
      const scroll = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
      expect(scroll).toBeLessThanOrEqual(0);
      const view = (await page.getByTestId('spatial-canvas').boundingBox())!;
      const field = (await page.getByRole('textbox', { name: 'Ground arc a1' }).boundingBox())!;
      expect(field.y).toBeGreaterThan(view.y + view.height);
      expect(view.width).toBeGreaterThan(v.width - 60);
      await page.screenshot({ path: artifact(`spatial-phone-${v.width}.png`) });
      await page.screenshot({ path: artifact(`spatial-phone-${v.width}-full.png`), fullPage: true });
      await context.close();
    });
  }
});
