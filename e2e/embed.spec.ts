import { expect, test } from '@playwright/test';
import type { FrameLocator, Page } from '@playwright/test';
import Decimal from 'decimal.js';
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

// The embeds of the Mechanisms (page=mech) and Spatial (page=3d) pages: their views, their locks (on screen and
// against the host's set-state), the generator's snippet for them and a bad parameter named. Oracles are computed
// here with decimal.js from the linkages' closed forms, not read from the app.

const D = Decimal.clone({ precision: 40 });
const degToRad = (deg: number) => new D(deg).times(D.acos(-1)).div(180);

/** A course page with one sandboxed frame of src; send() posts a set-state, warnings holds the frame's console warnings. */
async function hostPage(page: Page, src: string): Promise<{ frame: FrameLocator; warnings: string[] }> {
  const url = `${ORIGIN}/e2e-course/pages.html`;
  await page.route(url, (route) =>
    route.fulfill({
      contentType: 'text/html',
      body: `<!doctype html><html><head><title>Pages</title></head><body style="margin:20px">
<iframe id="w" title="Embed" sandbox="allow-scripts" src="${src}" width="600" height="450"></iframe>
<script>
  window.events = [];
  const frame = document.getElementById('w');
  window.addEventListener('message', (e) => {
    if (e.source === frame.contentWindow && e.data && e.data.source === 'fourbar-lab') window.events.push(e.data);
  });
  window.send = (state) => frame.contentWindow.postMessage({ target: 'fourbar-lab', type: 'set-state', state }, '*');
</script></body></html>`,
    }),
  );
  const warnings: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'warning' && m.text().startsWith('fourbar-lab:')) warnings.push(m.text());
  });
  await page.goto(url);
  const frame = page.frameLocator('#w');
  await waitReady(frame);
  return { frame, warnings };
}

/** The host's last state event from its frame (URL keys and values). */
async function lastEvent(page: Page): Promise<Record<string, unknown> | undefined> {
  return page.evaluate(
    () => (window as unknown as { events: { state: Record<string, unknown> }[] }).events.at(-1)?.state,
  );
}

async function send(page: Page, state: Record<string, unknown>): Promise<void> {
  await page.evaluate((s) => (window as unknown as { send: (x: object) => void }).send(s), state);
}

/** A number as the widgets print it (U+2212 for minus) read back. */
const num = (text: string) => Number(text.replace('−', '-'));

/** A joint's x and y from the mech embed's positions table (panel info). */
async function mechPos(frame: FrameLocator, id: string): Promise<[number, number]> {
  const x = num(await frame.getByTestId(`mech-pos-${id}-x`).innerText());
  const y = num(await frame.getByTestId(`mech-pos-${id}-y`).innerText());
  return [x, y];
}

/**
 * Drags the mech embed's canvas from where it draws the point at (world units; its view from data-view) px pixels up;
 * returns the view's scale (pixels per length).
 */
async function dragUp(page: Page, frame: FrameLocator, at: [number, number], px: number): Promise<number> {
  const canvas = frame.getByTestId('mech-canvas');
  const box = (await canvas.boundingBox())!;
  const [scale, cx, cy, panX, panY] = (await canvas.getAttribute('data-view'))!.split(' ').map(Number);
  const x = box.x + box.width / 2 + (at[0] - cx) * scale + panX;
  const y = box.y + box.height / 2 - (at[1] - cy) * scale + panY;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x, y - px, { steps: 4 });
  await page.mouse.up();
  return scale;
}

/** A spatial pin's x, y, z from the numbers panel (seven significant digits). */
async function spatialPin(frame: FrameLocator, pin: 'A' | 'B'): Promise<number[]> {
  const out: number[] = [];
  for (const axis of ['x', 'y', 'z']) out.push(num(await frame.getByTestId(`pin-${pin}-${axis}`).innerText()));
  return out;
}

/** The spherical crank pin A = Rz(θ2)·(sin a2, 0, cos a2) (docs/spatial.md), degrees in. */
function sphericalCrankPin(a2Deg: number, t2Deg: number): number[] {
  const [a2, t2] = [degToRad(a2Deg), degToRad(t2Deg)];
  return [a2.sin().times(t2.cos()), a2.sin().times(t2.sin()), a2.cos()].map((v) => v.toNumber());
}

test.describe('the embed of the Mechanisms page (page=mech)', () => {
  test('shows the template, its joints against the slider-crank’s closed form, and honours lock=template,edit', async ({
    page,
  }) => {
    test.slow(); // a frame, two inputs, a drag and a host command on a shared machine
    const src = `${ORIGIN}/embed.html?page=mech&tpl=slider-crank&panels=controls,info&lock=template,edit`;
    const { frame, warnings } = await hostPage(page, src);
    await expect(frame.locator('.mech-workspace')).toHaveAttribute('data-mech-state', 'ok');
    await expect(frame.locator('.mech-name-title')).toHaveText('Slider-crank');
    // The page's view: its canvas, Play and the positions table; no plots (panel off), no editor, no simulator.
    await expect(frame.getByTestId('mech-canvas')).toBeVisible();
    await expect(frame.getByRole('button', { name: 'Play' })).toBeVisible();
    await expect(frame.getByRole('table', { name: 'Joint positions at the input' })).toBeVisible();
    await expect(frame.locator('.mech-plots')).toBeHidden();
    await expect(frame.getByRole('button', { name: 'Add pin' })).toBeHidden();
    await expect(frame.locator('canvas.linkage-canvas')).toHaveCount(0);
    // lock=template: the template list is shown, not changeable.
    await expect(frame.getByRole('combobox', { name: 'Templates' })).toBeDisabled();

    // The slider-crank as drawn (input 0): crank O2→A, coupler A→S, S on a horizontal guide at S's height.
    const O2 = await mechPos(frame, 'O2');
    const A0 = await mechPos(frame, 'A');
    const S0 = await mechPos(frame, 'S');
    const r2 = D.hypot(A0[0] - O2[0], A0[1] - O2[1]);
    const r3 = D.hypot(S0[0] - A0[0], S0[1] - A0[1]);
    expect(Math.atan2(A0[1] - O2[1], A0[0] - O2[0])).toBeCloseTo(0, 6); // the crank is drawn at input 0
    // The input at 30°: A on the crank circle, S where the coupler meets the guide (the branch drawn, S right of A).
    await frame.getByRole('slider', { name: /^Input angle/ }).fill('30');
    await expect(frame.getByTestId('mech-input-value')).toHaveText('30°');
    const t = degToRad(30);
    const Ax = r2.times(t.cos()).plus(O2[0]);
    const Ay = r2.times(t.sin()).plus(O2[1]);
    const Sx = Ax.plus(r3.pow(2).minus(Ay.minus(S0[1]).pow(2)).sqrt());
    // Six significant digits shown, and r2, r3 read from six-digit numbers: 1e-4 of a length near 5.
    await expect.poll(async () => (await mechPos(frame, 'A'))[0]).toBeCloseTo(Ax.toNumber(), 4);
    expect((await mechPos(frame, 'A'))[1]).toBeCloseTo(Ay.toNumber(), 4);
    expect((await mechPos(frame, 'S'))[0]).toBeCloseTo(Sx.toNumber(), 4);
    expect((await mechPos(frame, 'S'))[1]).toBeCloseTo(S0[1], 4);

    // lock=edit: a drag of A on the canvas leaves the linkage as it was.
    await frame.getByRole('slider', { name: /^Input angle/ }).fill('0');
    await expect(frame.getByTestId('mech-input-value')).toHaveText('0°');
    await dragUp(page, frame, A0, 40);
    expect(await mechPos(frame, 'A')).toEqual(A0);

    // The host cannot change the locked keys: tpl (template) and mech (edit) are refused by name, mrho is applied.
    await send(page, { tpl: 'jansen', mech: 'm1', mrho: 5 });
    await expect.poll(async () => (await lastEvent(page))?.mrho).toBe(5);
    expect((await lastEvent(page))?.tpl).toBeUndefined(); // the default template, slider-crank
    await expect(frame.locator('.mech-name-title')).toHaveText('Slider-crank');
    expect(warnings).toContain('fourbar-lab: ignoring tpl from the parent: locked (template).');
    expect(warnings).toContain('fourbar-lab: ignoring mech from the parent: locked (edit).');
  });

  test('without locks the same drag edits the linkage and the host may change the template', async ({ page }) => {
    const { frame } = await hostPage(page, `${ORIGIN}/embed.html?page=mech&tpl=slider-crank&panels=controls,info`);
    await expect(frame.locator('.mech-workspace')).toHaveAttribute('data-mech-state', 'ok');
    await expect(frame.getByRole('combobox', { name: 'Templates' })).toBeEnabled();
    const A0 = await mechPos(frame, 'A');
    const scale = await dragUp(page, frame, A0, 40);
    // 40 px up is 40 / scale lengths up (the canvas's y points down).
    await expect.poll(async () => (await mechPos(frame, 'A'))[1]).toBeCloseTo(A0[1] + 40 / scale, 1);
    await send(page, { tpl: 'jansen' });
    await expect(frame.locator('.mech-name-title')).toHaveText('Jansen’s leg');
    await expect.poll(async () => (await lastEvent(page))?.tpl).toBe('jansen');
  });

  test('a bad parameter is refused with a notice naming it; a lock the page does not offer too', async ({ page }) => {
    await page.goto('./embed.html?page=mech&tpl=walking-robot&lock=r1');
    await waitReady(page);
    const notice = page.getByTestId('url-notice');
    await expect(notice).toContainText('tpl');
    await expect(notice).toContainText('walking-robot');
    await expect(notice).toContainText('lock');
    await expect(notice).toContainText('r1');
    await expect(page.locator('.mech-name-title')).toHaveText('Slider-crank');
  });
});

test.describe('the embed of the Spatial page (page=3d)', () => {
  test('shows the 3D view and the numbers of the linkage; lock=params,branch disables them and the host cannot change them', async ({
    page,
  }) => {
    const src = `${ORIGIN}/embed.html?page=3d&sk=sph&a2=20&t2=30&panels=controls,info&lock=params,branch`;
    const { frame, warnings } = await hostPage(page, src);
    await expect(frame.getByTestId('spatial-page')).toBeVisible();
    await expect(frame.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
    // The widget's title names the page it shows, not the simulator.
    await expect(frame.getByRole('heading', { level: 1 })).toHaveText('Spatial four-bar linkages');
    // The page's view without its title, exports or plots (panel off); no simulator canvas.
    await expect(frame.getByRole('heading', { name: 'Spatial four-bars' })).toHaveCount(0);
    await expect(frame.getByRole('button', { name: 'Export CSV' })).toHaveCount(0);
    await expect(frame.locator('.spatial-plots-section')).toHaveCount(0);
    await expect(frame.locator('canvas.linkage-canvas')).toHaveCount(0);
    // lock=params: the kind, the preset and every value locked; branch too; θ2 and Play free.
    await expect(frame.getByRole('radio', { name: 'RSSR' })).toBeDisabled();
    await expect(frame.getByRole('combobox', { name: 'Preset' })).toBeDisabled();
    await expect(frame.getByRole('textbox', { name: /^Crank arc a2/ })).toHaveAttribute('readonly', '');
    await expect(frame.getByRole('slider', { name: /^Crank arc a2/ })).toBeDisabled();
    await expect(frame.getByRole('slider', { name: /^Input speed ω2/ })).toBeDisabled();
    await expect(frame.getByRole('radio', { name: 'Crossed' })).toBeDisabled();
    await expect(frame.getByRole('slider', { name: /^Input angle θ2/ })).toBeEnabled();
    await expect(frame.getByRole('button', { name: 'Play' })).toBeEnabled();
    const A = sphericalCrankPin(20, 30);
    (await spatialPin(frame, 'A')).forEach((v, i) => expect(Math.abs(v - A[i]), `A[${i}]`).toBeLessThan(6e-7));

    // The host's a2 and br are refused (locked), its t2 is applied: A moves to the oracle's A at a2 = 20, θ2 = 75.
    await send(page, { a2: 35, br: 'crossed', t2: 75 });
    await expect.poll(async () => (await lastEvent(page))?.t2).toBe(75);
    expect(await lastEvent(page)).toMatchObject({ a2: 20, br: 'open', sk: 'sph' });
    const A75 = sphericalCrankPin(20, 75);
    await expect.poll(async () => (await spatialPin(frame, 'A'))[0]).toBeCloseTo(A75[0], 6);
    (await spatialPin(frame, 'A')).forEach((v, i) => expect(Math.abs(v - A75[i]), `A75[${i}]`).toBeLessThan(6e-7));
    expect(warnings).toContain('fourbar-lab: ignoring a2 from the parent: locked (params).');
    expect(warnings).toContain('fourbar-lab: ignoring br from the parent: locked (branch).');
  });

  test('an RSSR embed: r2 is the RSSR crank; with θ2 locked the host’s t2 is refused and its r2 applied', async ({
    page,
  }) => {
    const src = `${ORIGIN}/embed.html?page=3d&sk=rssr&r2=1&h2=0.5&t2=30&panels=controls,info&lock=theta2`;
    const { frame, warnings } = await hostPage(page, src);
    await expect(frame.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 20_000 });
    await expect(frame.getByRole('slider', { name: /^Input angle θ2/ })).toBeDisabled();
    await expect(frame.getByRole('button', { name: /^Step/ }).first()).toBeDisabled();
    await expect(frame.getByRole('textbox', { name: /^Crank r2/ })).not.toHaveAttribute('readonly', '');
    await send(page, { r2: 1.5, t2: 90 });
    await expect.poll(async () => (await lastEvent(page))?.r2).toBe(1.5);
    expect((await lastEvent(page))?.t2).toBe(30);
    // A = (r2 cos θ2, r2 sin θ2, h2) (docs/spatial.md) at r2 = 1.5, θ2 = 30°.
    const t = degToRad(30);
    const A = [t.cos().times(1.5), t.sin().times(1.5), new D(0.5)].map((v) => v.toNumber());
    await expect.poll(async () => (await spatialPin(frame, 'A'))[0]).toBeCloseTo(A[0], 6);
    (await spatialPin(frame, 'A')).forEach((v, i) => expect(Math.abs(v - A[i]), `A[${i}]`).toBeLessThan(6e-7));
    expect(warnings).toContain('fourbar-lab: ignoring t2 from the parent: locked (theta2).');
  });

  test('a bad parameter is refused with a notice naming it', async ({ page }) => {
    await page.goto('./embed.html?page=3d&sk=sph&a1=200&panels=controls,export');
    await waitReady(page);
    await expect(page).toHaveTitle('Spatial four-bar linkages');
    const notice = page.getByTestId('url-notice');
    await expect(notice).toContainText('a1');
    await expect(notice).toContainText('200');
    await expect(notice).toContainText('panels');
    await expect(page.getByRole('textbox', { name: /^Ground arc a1/ })).toHaveValue('60');
  });
});

test.describe('the embed generator for the Mechanisms and Spatial pages', () => {
  test('its snippet carries page= and the page’s linkage and locks, and its preview shows that page', async ({
    page,
  }) => {
    test.slow(); // three pages and a preview frame on a shared machine
    // The linkages to embed: Jansen's leg on the Mechanisms page, an edited arc on the Spatial page.
    await page.goto('./?page=mech&tpl=jansen');
    await expect(page.locator('.mech-workspace')).toHaveAttribute('data-mech-state', 'ok');
    await page.getByRole('tab', { name: 'Spatial' }).click();
    await page.getByRole('textbox', { name: 'Crank arc a2' }).fill('35');
    await expect.poll(() => new URL(page.url()).searchParams.get('a2')).toBe('35');
    await page.getByRole('tab', { name: 'Simulator' }).click();
    await waitReady(page);
    await page.getByText('Embed generator: size, panels, locks, preview').click();
    const code = page.getByRole('textbox', { name: 'Embed code' });
    const query = async () =>
      new URL(/src="([^"]+)"/.exec(await code.inputValue())![1].replaceAll('&amp;', '&')).searchParams;

    await page.getByRole('radio', { name: 'Mechanisms' }).check();
    await page.getByRole('checkbox', { name: 'Template' }).check();
    await expect.poll(async () => (await query()).get('lock')).toBe('template');
    expect((await query()).get('page')).toBe('mech');
    expect((await query()).get('tpl')).toBe('jansen');
    await expect(code).toHaveValue(/ title="Planar linkage mechanisms" /);
    // The simulator's locks are not offered for this page.
    await expect(page.getByRole('checkbox', { name: 'r1', exact: true })).toHaveCount(0);
    const preview = page.frameLocator('.embed-preview iframe');
    await expect(preview.locator('.mech-name-title')).toHaveText('Jansen’s leg', { timeout: 20_000 });
    await expect(preview.getByRole('combobox', { name: 'Templates' })).toBeDisabled();

    await page.getByRole('radio', { name: 'Spatial' }).check();
    await expect.poll(async () => (await query()).get('page')).toBe('3d');
    await expect(code).toHaveValue(/ title="Spatial four-bar linkages" /);
    expect((await query()).get('lock')).toBeNull(); // template is not a lock of this page
    await page.getByRole('checkbox', { name: 'Parameters' }).check();
    await expect.poll(async () => (await query()).get('lock')).toBe('params');
    expect(Object.fromEntries(await query())).toMatchObject({ sk: 'sph', a1: '60', a2: '35', a3: '55', a4: '45' });
    await expect(preview.getByRole('textbox', { name: /^Crank arc a2/ })).toHaveValue('35', { timeout: 20_000 });
    await expect(preview.getByRole('textbox', { name: /^Crank arc a2/ })).toHaveAttribute('readonly', '');
  });
});
