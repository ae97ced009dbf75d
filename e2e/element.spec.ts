import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, test } from '@playwright/test';
import Decimal from 'decimal.js';
import type { Page } from '@playwright/test';
import { ORIGIN } from './helpers';

// The custom element from `npm run build:element` (npm run test:e2e builds it first), on a plain course page:
// fourbar-lab.js and its folder fourbar-lab/ (the element's module, its lazy chunks, its workers) beside the page.
const DIST = join(dirname(fileURLToPath(import.meta.url)), '..', 'dist-element');
const PAGE = `${ORIGIN}/e2e-course/element.html`;
/** A string only three.js's WebGLRenderer carries (its messages' prefix): marks a script that holds three.js. */
const THREE_MARK = 'THREE.WebGLRenderer';

/** The element's files the page fetched, in order: their path under dist-element and whether they hold three.js. */
interface Served {
  path: string;
  three: boolean;
}

/** Serves dist-element's files beside the course page; returns the list of those the page fetched, as it grows. */
async function serveElement(page: Page): Promise<Served[]> {
  if (!existsSync(join(DIST, 'fourbar-lab.js')))
    throw new Error(`${DIST} has no fourbar-lab.js: run npm run build:element`);
  const served: Served[] = [];
  await page.route(/\/e2e-course\/fourbar-lab(\.js|\/[^?#]+)$/, (route) => {
    const path = new URL(route.request().url()).pathname.replace('/e2e-course/', '');
    const file = join(DIST, ...path.split('/'));
    if (!existsSync(file)) return route.fulfill({ status: 404, body: 'not found' });
    const body = readFileSync(file, 'utf8');
    served.push({ path, three: body.includes(THREE_MARK) });
    return route.fulfill({ contentType: 'text/javascript', body });
  });
  return served;
}

interface Fired {
  id: string;
  detail: Record<string, unknown>;
}

function fired(page: Page): Promise<Fired[]> {
  return page.evaluate(() => (window as unknown as { fired: Fired[] }).fired);
}

/**
 * Opens a course page titled title whose body is body (fourbar-lab elements), each element's own change events
 * recorded in window.fired; returns the page's uncaught errors as they come.
 */
async function openCoursePage(page: Page, title: string, body: string): Promise<string[]> {
  await page.route(PAGE, (route) =>
    route.fulfill({
      contentType: 'text/html',
      body: `<!doctype html><html lang="en"><head><title>${title}</title>
<script src="./fourbar-lab.js"></script></head><body>
${body}
<script>
  window.fired = [];
  for (const el of document.querySelectorAll('fourbar-lab'))
    el.addEventListener('change', (e) => { if (e.target === el) window.fired.push({ id: el.id, detail: e.detail }); });
</script></body></html>`,
    }),
  );
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(PAGE);
  return errors;
}

test.describe('the <fourbar-lab> custom element', () => {
  test('two elements on one page keep their own state, styles and change events', async ({ page }) => {
    await serveElement(page);
    const errors = await openCoursePage(
      page,
      'Week 3',
      `<h1>Week 3</h1><div class="embed-bar" id="probe">A page element that shares a class name with the widget.</div>
<fourbar-lab id="a" r1="6" r2="2" r3="5" r4="5" t2="60" panels="controls"></fourbar-lab>
<fourbar-lab id="b" r1="6" r2="2" r3="4.5" r4="5" t2="30" panels="controls,info" lock="r1" style="height:600px"></fourbar-lab>`,
    );
    const a = page.locator('#a');
    const b = page.locator('#b');
    await expect(a.locator('[data-ready="true"]')).toHaveCount(1, { timeout: 20_000 });
    await expect(b.locator('[data-ready="true"]')).toHaveCount(1, { timeout: 20_000 });
    await expect(a.getByRole('textbox', { name: /^r3/ })).toHaveValue('5');
    await expect(b.getByRole('textbox', { name: /^r3/ })).toHaveValue('4.5');
    await expect(b.getByRole('textbox', { name: /^r1/ })).toBeDisabled();
    await expect(a.getByRole('textbox', { name: /^r1/ })).toBeEnabled();
    await expect(b.getByTestId('linkage-type')).toBeVisible();
    await expect(a.getByTestId('linkage-type')).toHaveCount(0);
    await expect(page.getByText(/main thread/)).toHaveCount(0);

    // Styles stay inside the shadow roots: the page's own .embed-bar is not turned into the widget's flex bar,
    // and the element's host size comes from the page (b) or the default (a).
    expect(await page.locator('#probe').evaluate((el) => getComputedStyle(el).display)).toBe('block');
    expect(await page.evaluate(() => document.styleSheets.length)).toBe(0);
    expect((await a.boundingBox())?.height).toBe(520);
    expect((await b.boundingBox())?.height).toBe(600);

    // A person changes r3 in a: a fires change with r3 = 4; b neither changes nor fires.
    const r3 = a.getByRole('textbox', { name: /^r3/ });
    await r3.fill('4');
    await r3.press('Enter');
    await expect.poll(async () => (await fired(page)).find((f) => f.id === 'a')?.detail.r3).toBe(4);
    expect((await fired(page)).filter((f) => f.id === 'b')).toEqual([]);
    await expect(b.getByRole('textbox', { name: /^r3/ })).toHaveValue('4.5');
    expect(await b.evaluate((el) => (el as unknown as { state: { r3: number } }).state.r3)).toBe(4.5);

    // The page changes an attribute of b: b follows and fires its own change; a keeps its state.
    await b.evaluate((el) => el.setAttribute('t2', '90'));
    await expect(b.getByRole('img', { name: /^Linkage view\. θ2 90\.00°/ })).toBeVisible();
    await expect.poll(async () => (await fired(page)).find((f) => f.id === 'b')?.detail.t2).toBe(90);
    await expect(a.getByRole('img', { name: /^Linkage view\. θ2 60\.00°/ })).toBeVisible();
    expect((await fired(page)).filter((f) => f.id === 'a').every((f) => f.detail.t2 === 60)).toBe(true);
    // Panels follow their attribute too.
    await a.evaluate((el) => el.setAttribute('panels', 'controls,info'));
    await expect(a.getByTestId('linkage-type')).toBeVisible();
    // So do the locks: a later lock on a freezes r3 and θ2 there and keeps what was typed; dropping b's lock frees r1.
    await a.evaluate((el) => el.setAttribute('lock', 'r3,theta2'));
    await expect(a.getByRole('textbox', { name: /^r3/ })).toBeDisabled();
    await expect(a.getByRole('textbox', { name: /^r3/ })).toHaveValue('4');
    await expect(a.getByRole('slider', { name: /^θ2/ })).toBeDisabled();
    await expect(a.getByRole('textbox', { name: /^r1/ })).toBeEnabled();
    await b.evaluate((el) => el.removeAttribute('lock'));
    await expect(b.getByRole('textbox', { name: /^r1/ })).toBeEnabled();
    await expect(b.getByRole('textbox', { name: /^r3/ })).toHaveValue('4.5');
    // The page author may still set a locked key (README: attributes are the author's), the reader may not.
    await a.evaluate((el) => el.setAttribute('r3', '3'));
    await expect.poll(() => a.evaluate((el) => (el as unknown as { state: { r3: number } }).state.r3)).toBe(3);
    await expect(a.getByRole('textbox', { name: /^r3/ })).toHaveValue('3');
    await expect(a.getByRole('textbox', { name: /^r3/ })).toBeDisabled();
    expect(errors).toEqual([]);
  });
});

test.describe('the <fourbar-lab> custom element in Traditional Chinese', () => {
  test('lang="zh-TW" draws in Traditional Chinese from the first frame, as its language menu says', async ({
    page,
  }) => {
    await serveElement(page);
    await page.route(PAGE, (route) =>
      route.fulfill({
        contentType: 'text/html',
        body: `<!doctype html><html lang="zh-Hant"><head><title>第三週</title>
<script src="./fourbar-lab.js"></script></head><body>
<fourbar-lab id="z" lang="zh-TW" panels="controls"></fourbar-lab></body></html>`,
      }),
    );
    await page.goto(PAGE);
    const z = page.locator('#z');
    await expect(z.locator('[data-ready="true"]')).toHaveCount(1, { timeout: 20_000 });
    await expect(z.getByRole('combobox')).toHaveValue('zh-TW');
    await expect(z.getByRole('button', { name: '播放' })).toBeVisible();
    await expect(z.getByRole('button', { name: 'Play' })).toHaveCount(0);
  });
});

test.describe('the <fourbar-lab> custom element with a bad attribute', () => {
  test('names the attribute in a notice that speaks of the element, not of a link', async ({ page }) => {
    await serveElement(page);
    await page.route(PAGE, (route) =>
      route.fulfill({
        contentType: 'text/html',
        body: `<!doctype html><html lang="en"><head><title>Week 3</title>
<script src="./fourbar-lab.js"></script></head><body>
<fourbar-lab id="bad" r3="abc" panels="controls"></fourbar-lab></body></html>`,
      }),
    );
    await page.goto(PAGE);
    const el = page.locator('#bad');
    await expect(el.locator('[data-ready="true"]')).toHaveCount(1, { timeout: 20_000 });
    await expect(el.getByTestId('url-notice')).toHaveText(
      /^This element has an attribute value the lab cannot use, so the default is shown instead: r3 = “abc”\./,
    );
    await expect(el.getByTestId('url-notice')).not.toContainText('link');
    // The notice sits in the element's own box, not over a corner of the course page.
    const [box, notice] = await Promise.all([el.boundingBox(), el.getByTestId('url-notice').boundingBox()]);
    expect(box && notice).toBeTruthy();
    if (!box || !notice) return;
    expect(notice.x).toBeGreaterThanOrEqual(box.x);
    expect(notice.y).toBeGreaterThanOrEqual(box.y);
    expect(notice.x + notice.width).toBeLessThanOrEqual(box.x + box.width + 0.5);
    expect(notice.y + notice.height).toBeLessThanOrEqual(box.y + box.height + 0.5);
  });
});

test.describe('the <fourbar-lab> custom element on the Mechanisms and Spatial pages', () => {
  test('page="mech" and page="3d" show their pages; r2 is the RSSR crank; a bad attribute is named', async ({
    page,
  }) => {
    await serveElement(page);
    const errors = await openCoursePage(
      page,
      'Week 9',
      `<fourbar-lab id="m" page="mech" tpl="jansen" panels="controls,info" lock="template,edit"></fourbar-lab>
<fourbar-lab id="s" page="3d" sk="rssr" r2="1.5" h2="0.5" t2="30" a1="200" panels="info" style="height:600px"></fourbar-lab>`,
    );
    const m = page.locator('#m');
    const s = page.locator('#s');
    await expect(m.locator('.mech-workspace')).toHaveAttribute('data-mech-state', 'ok', { timeout: 20_000 });
    await expect(m.locator('.mech-name-title')).toHaveText('Jansen’s leg');
    await expect(m.getByRole('table', { name: 'Joint positions at the input' })).toBeVisible();
    await expect(m.getByRole('combobox', { name: 'Templates' })).toBeDisabled();
    await expect(s.getByTestId('spatial-page')).toBeVisible({ timeout: 20_000 });
    // a1 (a spherical arc, read whatever the kind) = 200 is outside (0, 180): refused and named.
    await expect(s.getByTestId('url-notice')).toContainText('a1');
    // A = (r2 cos θ2, r2 sin θ2, h2) (docs/spatial.md): r2 = 1.5 is the RSSR crank, not the simulator's r2.
    const pinA = async () =>
      Promise.all(
        ['x', 'y', 'z'].map(async (a) => Number((await s.getByTestId(`pin-A-${a}`).innerText()).replace('−', '-'))),
      );
    const oracle = (t2Deg: number) => {
      const t = new Decimal(t2Deg).times(Decimal.acos(-1)).div(180);
      return [t.cos().times(1.5), t.sin().times(1.5), new Decimal(0.5)].map((v) => v.toNumber());
    };
    await expect.poll(async () => (await pinA())[0]).toBeCloseTo(oracle(30)[0], 6);
    (await pinA()).forEach((v, i) => expect(Math.abs(v - oracle(30)[i]), `A[${i}]`).toBeLessThan(6e-7));
    // The page author moves θ2: the pin follows and the change event carries the page's keys.
    await s.evaluate((el) => el.setAttribute('t2', '60'));
    await expect.poll(async () => (await pinA())[1]).toBeCloseTo(oracle(60)[1], 6);
    await expect
      .poll(async () => (await fired(page)).find((f) => f.id === 's' && f.detail.t2 === 60)?.detail)
      .toMatchObject({ sk: 'rssr', r2: 1.5, h2: 0.5 });
    expect(errors).toEqual([]);
  });
});

test.describe('the <fourbar-lab> custom element loads three.js only for page="3d"', () => {
  test('a simulator element fetches no three.js; a page="3d" element added later fetches it and draws', async ({
    page,
  }) => {
    const served = await serveElement(page);
    const errors = await openCoursePage(page, 'Week 4', `<fourbar-lab id="sim" panels="controls,plots"></fourbar-lab>`);
    const sim = page.locator('#sim');
    await expect(sim.locator('[data-ready="true"]')).toHaveCount(1, { timeout: 20_000 });
    await expect(sim.getByRole('heading', { level: 1 })).toHaveText('Four-bar linkage simulator');
    // The simulator drew from the loader and the element's module and its first-load chunk: none holds three.js.
    expect(served.map((f) => f.path)).toContain('fourbar-lab.js');
    expect(served.some((f) => f.path.startsWith('fourbar-lab/widget-'))).toBe(true);
    expect(served.filter((f) => f.three)).toEqual([]);

    // The page adds a Spatial element: its chunks (three.js among them) load from beside the script, and it draws.
    await page.evaluate(() =>
      document.body.insertAdjacentHTML(
        'beforeend',
        '<fourbar-lab id="sp" page="3d" sk="sph" panels="info" style="height:600px"></fourbar-lab>',
      ),
    );
    const sp = page.locator('#sp');
    await expect(sp.locator('.spatial-view')).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
    await expect.poll(() => sp.getByTestId('spatial-canvas').getAttribute('data-frames')).not.toBeNull();
    expect(Number(await sp.getByTestId('spatial-canvas').getAttribute('data-frames'))).toBeGreaterThan(0);
    expect(served.filter((f) => f.three).length).toBe(1);
    // Its title names the page it shows.
    await expect(sp.getByRole('heading', { level: 1 })).toHaveText('Spatial four-bar linkages');
    expect(errors).toEqual([]);
  });
});
