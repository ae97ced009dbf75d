import type { BrowserContext, Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { KNOWN, knownPose } from '../tests/features/synthesis/motion/knownLinkage';
import type { P2 } from '../tests/features/synthesis/motion/knownLinkage';
import { artifact, waitSimulatorUrl } from './helpers';

// The Motion mode against the synthesis module's own oracle: poses computed here from a known linkage (circle
// intersection, tests/features/synthesis/motion/knownLinkage.ts) lead back to its pivots.

const deg = (d: number) => (d * Math.PI) / 180;
const THREE = [30, 100, 170].map((t) => knownPose(deg(t)));
const poseText = (poses: { x: number; y: number; angleDeg: number }[]) =>
  poses.map((p) => `${p.x},${p.y},${p.angleDeg}`).join(';');
const pointText = (points: P2[]) => points.map((p) => `${p.x},${p.y}`).join(';');
/** URL of the Motion mode with these poses (and pivots). */
const motionUrl = (poses: { x: number; y: number; angleDeg: number }[], extra = '') =>
  `./?page=syn&syn=motion&ps=${encodeURIComponent(poseText(poses))}${extra}`;
/** Poses are exact in the URL (angles to 1e-9°): the pivots come back to far better than this. */
const NEAR = 1e-6;

/** The fixed pivots of the design shown, read from the facts' data attributes (full precision). */
async function fixedPivots(page: Page): Promise<{ O2: P2; O4: P2 }> {
  const facts = page.getByTestId('motion-pivots');
  await expect(facts).toBeVisible();
  const read = async (name: string) => {
    const [x, y] = ((await facts.getAttribute(name)) ?? '').split(',').map(Number);
    return { x, y };
  };
  return { O2: await read('data-o2'), O4: await read('data-o4') };
}

function expectNear(p: P2, q: P2, tol = NEAR): void {
  expect(Math.hypot(p.x - q.x, p.y - q.y), `${JSON.stringify(p)} vs ${JSON.stringify(q)}`).toBeLessThan(tol);
}

/** The screen points (page pixels) of each pose's point and turning handle, from the canvas's data-poses. */
async function poseHandles(page: Page): Promise<{ point: P2; handle: P2 }[]> {
  const canvas = page.getByTestId('motion-canvas');
  const box = await canvas.boundingBox();
  if (!box) throw new Error('no canvas box');
  const text = (await canvas.getAttribute('data-poses')) ?? '';
  return text.split(';').map((row) => {
    const [x, y, hx, hy] = row.split(',').map(Number);
    return { point: { x: box.x + x, y: box.y + y }, handle: { x: box.x + hx, y: box.y + hy } };
  });
}

async function drag(page: Page, from: P2, to: P2): Promise<void> {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= 6; k++)
    await page.mouse.move(from.x + ((to.x - from.x) * k) / 6, from.y + ((to.y - from.y) * k) / 6);
  await page.mouse.up();
}

const cell = (page: Page, name: string) => page.getByRole('textbox', { name, exact: true });

test.describe('synthesis: motion generation', () => {
  test('three poses from a URL lead to the known fixed pivots, with no defect', async ({ page }) => {
    await page.goto(motionUrl(THREE, `&pv=${encodeURIComponent(pointText([KNOWN.a, KNOWN.b]))}`));
    const { O2, O4 } = await fixedPivots(page);
    expectNear(O2, KNOWN.O2);
    expectNear(O4, KNOWN.O4);
    await expect(page.getByTestId('motion-defects')).toHaveText(/No order, branch or Grashof defect/);
    await expect(page.getByTestId('motion-links')).toContainText('r2 = 0.55');
    await page.screenshot({ path: artifact('synthesis-motion-1280.png') });
  });

  test('three poses typed into the table lead to the known pivots, moving or fixed', async ({ page }) => {
    await page.goto('./?page=syn&syn=motion');
    await expect(page.getByTestId('motion-mode')).toHaveAttribute('data-count', '3');
    for (const [i, p] of THREE.entries()) {
      await cell(page, `Pose ${i + 1} x`).fill(String(p.x));
      await cell(page, `Pose ${i + 1} y`).fill(String(p.y));
      await cell(page, `Pose ${i + 1} angle (°)`).fill(String(p.angleDeg));
    }
    for (const [name, q] of [
      ['A', KNOWN.a],
      ['B', KNOWN.b],
    ] as const) {
      await cell(page, `${name} x`).fill(String(q.x));
      await cell(page, `${name} y`).fill(String(q.y));
    }
    let pivots = await fixedPivots(page);
    expectNear(pivots.O2, KNOWN.O2);
    expectNear(pivots.O4, KNOWN.O4);
    // Switching to fixed pivots keeps the linkage; placing the known fixed pivots finds the known moving ones.
    await page.getByRole('radio', { name: 'Fixed pivots' }).check();
    await expect(cell(page, 'O2 x')).toHaveValue('-1');
    await cell(page, 'O2 x').fill(String(KNOWN.O2.x));
    await cell(page, 'O2 y').fill(String(KNOWN.O2.y));
    await cell(page, 'O4 x').fill(String(KNOWN.O4.x));
    await cell(page, 'O4 y').fill(String(KNOWN.O4.y));
    pivots = await fixedPivots(page);
    expectNear(pivots.O2, KNOWN.O2);
    await expect(page.getByTestId('motion-links')).toContainText('r2 = 0.55');
    await expect(page.getByTestId('motion-links')).toContainText('r4 = 1.45');
  });

  test('a bad number in the table is refused with a message naming the cell, and the pose kept', async ({ page }) => {
    await page.goto('./?page=syn&syn=motion');
    await cell(page, 'Pose 2 y').fill('1..3');
    await expect(page.getByRole('alert')).toHaveText('Pose 2 y: “1..3” is not a number; keeping 1.3.');
    await expect(page).not.toHaveURL(/ps=/);
  });

  test('dragging a pose’s point moves it and dragging its handle turns it', async ({ page }) => {
    await page.goto('./?page=syn&syn=motion');
    const [first] = await poseHandles(page);
    await drag(page, first.point, { x: first.point.x + 60, y: first.point.y + 30 });
    await expect(cell(page, 'Pose 1 x')).not.toHaveValue('-0.9');
    await expect(cell(page, 'Pose 1 y')).not.toHaveValue('0.6');
    expect(Number(await cell(page, 'Pose 1 x').inputValue())).toBeGreaterThan(-0.9);
    expect(Number(await cell(page, 'Pose 1 y').inputValue())).toBeLessThan(0.6);
    const [moved] = await poseHandles(page);
    // The handle swung to point straight down from the pose: −90°.
    await drag(page, moved.handle, { x: moved.point.x, y: moved.point.y + 45 });
    await expect(cell(page, 'Pose 1 angle (°)')).toHaveValue('-90');
    await expect(page).toHaveURL(/ps=/);
  });

  test('the keyboard selects, moves and turns a pose', async ({ page }) => {
    await page.goto('./?page=syn&syn=motion');
    const canvas = page.getByTestId('motion-canvas');
    await canvas.focus();
    await page.keyboard.press('2');
    await expect(canvas).toHaveAttribute('aria-label', /Pose 2 selected/);
    await page.keyboard.press('ArrowRight');
    expect(Number(await cell(page, 'Pose 2 x').inputValue())).toBeGreaterThan(-2);
    await page.keyboard.press('[');
    await expect(cell(page, 'Pose 2 angle (°)')).toHaveValue('31');
  });

  test('four poses: the curves are drawn and two dyads picked on the centre-point curve make a linkage', async ({
    page,
  }) => {
    const four = [20, 80, 140, 230].map((t) => knownPose(deg(t)));
    await page.goto(motionUrl(four));
    await expect(page.getByTestId('motion-method')).toHaveText(/centre-point curve/);
    await expect(page.getByTestId('dyads-picked')).toHaveText('Dyads picked: 0 of 2');
    await expect(page.getByTestId('motion-problem')).toHaveText('Pick two dyads on the centre-point curve.');
    // One pick by clicking the curve where the slider's dyad is drawn, one by the keyboard (slider and button).
    const canvas = page.getByTestId('motion-canvas');
    const box = await canvas.boundingBox();
    const [cx, cy] = ((await canvas.getAttribute('data-cursor')) ?? '').split(',').map(Number);
    await page.mouse.click(box!.x + cx, box!.y + cy);
    await expect(page.getByTestId('dyads-picked')).toHaveText('Dyads picked: 1 of 2');
    const slider = page.getByRole('slider', { name: 'Point on the centre-point curve' });
    await slider.focus();
    for (let k = 0; k < 3; k++) await page.keyboard.press('PageUp');
    await page.getByRole('button', { name: 'Pick this dyad' }).click();
    await expect(page.getByTestId('dyads-picked')).toHaveText('Dyads picked: 2 of 2');
    await expect(page.getByTestId('motion-design')).toBeVisible();
    await expect(page.getByTestId('motion-defects')).toHaveText(/defect|input/i);
    await page.screenshot({ path: artifact('synthesis-motion-four-1280.png') });
  });

  test('five poses: the Burmester points are marked and their four-bars listed, the known one among them', async ({
    page,
  }) => {
    const five = [20, 75, 130, 200, 270].map((t) => knownPose(deg(t)));
    await page.goto(motionUrl(five));
    await expect(page.getByTestId('burmester-count')).toHaveText(/^(2|4) Burmester points/);
    const radios = page.getByTestId('burmester-fourbars').getByRole('radio');
    const n = await radios.count();
    expect([1, 6]).toContain(n);
    let found = false;
    for (let i = 0; i < n && !found; i++) {
      await radios.nth(i).check();
      const { O2, O4 } = await fixedPivots(page);
      const hits = (p: P2) =>
        Math.hypot(p.x - KNOWN.O2.x, p.y - KNOWN.O2.y) < NEAR || Math.hypot(p.x - KNOWN.O4.x, p.y - KNOWN.O4.y) < NEAR;
      found = hits(O2) && hits(O4);
    }
    expect(found).toBe(true);
  });

  test('two poses: the rocker turns about their pole', async ({ page }) => {
    const C = { x: 2, y: -1 };
    const turn = deg(40);
    const P1 = { x: 4, y: 0.5 };
    const P2 = {
      x: C.x + Math.cos(turn) * (P1.x - C.x) - Math.sin(turn) * (P1.y - C.y),
      y: C.y + Math.sin(turn) * (P1.x - C.x) + Math.cos(turn) * (P1.y - C.y),
    };
    await page.goto(
      motionUrl([
        { ...P1, angleDeg: 10 },
        { ...P2, angleDeg: 50 },
      ]),
    );
    await expect(page.getByTestId('motion-pole')).toContainText('Pole (rocker pivot O4) at (2, −1)');
    const { O4 } = await fixedPivots(page);
    expectNear(O4, C);
    await expect(page.getByTestId('motion-facts')).toContainText('Crank-rocker');
  });

  test('Open in simulator carries the design and marks the poses', async ({ page }) => {
    await page.goto(motionUrl(THREE, `&pv=${encodeURIComponent(pointText([KNOWN.a, KNOWN.b]))}`));
    await page.getByRole('button', { name: 'Open in simulator' }).click();
    await expect(page.getByRole('tab', { name: 'Simulator' })).toHaveAttribute('aria-selected', 'true');
    const params = await waitSimulatorUrl(page);
    // The poses came through the URL rounded to 1e-9°: r2 is the known 0.55 to far better than 1e-6.
    expect(Math.abs(Number(params.get('r2')) - KNOWN.r2)).toBeLessThan(NEAR);
    expect(Math.abs(Number(params.get('r4')) - KNOWN.r4)).toBeLessThan(NEAR);
    const targets = (params.get('tg') ?? '').split(';');
    expect(targets).toHaveLength(3);
    const [x, y] = targets[0].split(',').map(Number);
    expectNear({ x, y }, THREE[0]);
  });
});

test.describe('synthesis: motion generation in zh-TW and on a phone', () => {
  test('speaks zh-TW: 中心點曲線 and 圓點曲線', async ({ page }) => {
    const four = [20, 80, 140, 230].map((t) => knownPose(deg(t)));
    await page.goto(`${motionUrl(four)}&lang=zh-TW`);
    await expect(page.getByTestId('motion-method')).toContainText('中心點曲線');
    await expect(page.getByTestId('motion-method')).toContainText('圓點曲線');
    await expect(page.getByRole('heading', { name: '姿態' })).toBeVisible();
    await page.screenshot({ path: artifact('synthesis-motion-zh-TW.png') });
  });

  test('works at 390×844: a finger drags a pose, nothing overflows sideways', async ({ browser }) => {
    const context: BrowserContext = await browser.newContext({
      viewport: { width: 390, height: 844 },
      hasTouch: true,
      isMobile: true,
    });
    const page = await context.newPage();
    await page.goto(`${test.info().project.use.baseURL}?page=syn&syn=motion`);
    const canvas = page.getByTestId('motion-canvas');
    await canvas.scrollIntoViewIfNeeded();
    await expect(canvas).toHaveAttribute('data-poses', /;/);
    const [first] = await poseHandles(page);
    const cdp = await context.newCDPSession(page);
    const touch = (type: 'touchStart' | 'touchMove' | 'touchEnd', p: P2) =>
      cdp.send('Input.dispatchTouchEvent', {
        type,
        touchPoints: type === 'touchEnd' ? [] : [{ x: p.x, y: p.y, id: 1 }],
      });
    await touch('touchStart', first.point);
    for (let k = 1; k <= 5; k++) await touch('touchMove', { x: first.point.x + 8 * k, y: first.point.y + 6 * k });
    await touch('touchEnd', first.point);
    await expect.poll(async () => Number(await cell(page, 'Pose 1 x').inputValue())).toBeGreaterThan(-0.9);
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    expect(overflow).toBeLessThanOrEqual(0);
    await page.screenshot({ path: artifact('synthesis-motion-390.png'), fullPage: true });
    await context.close();
  });
});

test.describe('synthesis: motion, the Burmester curves in view (issue 34, item 8)', () => {
  const defaults = [
    { x: -0.9, y: 0.6, angleDeg: 34 },
    { x: -2, y: 1.3, angleDeg: 26 },
    { x: -3.8, y: 0.8, angleDeg: 24 },
    { x: -5.4, y: -0.6, angleDeg: 27 },
    { x: -6.1, y: -2.3, angleDeg: 36 },
  ];

  /** The curve slider's mark (the sample nearest the poses) on the canvas, CSS pixels, and the canvas's size. */
  async function cursorOnCanvas(page: Page): Promise<{ x: number; y: number; width: number; height: number }> {
    const canvas = page.getByTestId('motion-canvas');
    await expect(canvas).toHaveAttribute('data-cursor', /,/);
    const box = await canvas.boundingBox();
    const [x, y] = ((await canvas.getAttribute('data-cursor')) ?? '').split(',').map(Number);
    return { x, y, width: box!.width, height: box!.height };
  }

  for (const viewport of [
    { width: 1280, height: 800 },
    { width: 390, height: 844 },
  ]) {
    test(`four poses at ${viewport.width}×${viewport.height}: the curves near the poses are in view, and again after Fit the view`, async ({
      page,
    }) => {
      await page.setViewportSize(viewport);
      await page.goto(motionUrl(defaults.slice(0, 4)));
      const inView = async () => {
        const c = await cursorOnCanvas(page);
        expect(c.x).toBeGreaterThan(0);
        expect(c.x).toBeLessThan(c.width);
        expect(c.y).toBeGreaterThan(0);
        expect(c.y).toBeLessThan(c.height);
      };
      await inView();
      await page.screenshot({ path: artifact(`synthesis-motion-four-fit-${viewport.width}.png`), fullPage: true });
      for (let k = 0; k < 4; k++) await page.getByRole('button', { name: 'Zoom in' }).first().click();
      await page.getByRole('button', { name: 'Fit the view' }).first().click();
      await inView();
    });
  }

  test('five poses: the Burmester points are in view, numbered as the four-bars name them', async ({ page }) => {
    await page.goto(motionUrl(defaults));
    await expect(page.getByTestId('burmester-count')).toHaveText(/^4 Burmester points/);
    await expect(page.getByTestId('burmester-fourbars')).toContainText('+');
    await page.screenshot({ path: artifact('synthesis-motion-five-fit-1280.png') });
  });
});

test.describe('synthesis: motion, six to twenty poses by least squares (issue 34, item 9)', () => {
  test('eight poses of the known linkage: its four-bar first, an error per pose near zero', async ({ page }) => {
    const eight = [10, 50, 90, 130, 170, 210, 250, 290].map((t) => knownPose(deg(t)));
    await page.goto(motionUrl(eight));
    await expect(page.getByTestId('motion-method')).toHaveText(/^Six or more poses/);
    await expect(page.getByTestId('approx-fourbars').getByRole('radio').first()).toBeChecked();
    const { O2 } = await fixedPivots(page);
    expectNear(O2, KNOWN.O2);
    const rows = page.getByTestId('motion-errors').locator('tbody tr');
    await expect(rows).toHaveCount(8);
    const errors = await rows.evaluateAll((trs) => trs.map((tr) => Number(tr.getAttribute('data-position'))));
    for (const e of errors) expect(e).toBeLessThan(1e-6);
    await page.screenshot({ path: artifact('synthesis-motion-eight-1280.png'), fullPage: true });
  });

  test('Add pose goes past five into least squares and offers a four-bar; at 390×844 too', async ({ browser }) => {
    const context = await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
    const page = await context.newPage();
    await page.goto(`${test.info().project.use.baseURL}?page=syn&syn=motion`);
    for (let k = 0; k < 3; k++) await page.getByRole('button', { name: 'Add pose' }).click();
    await expect(page.getByTestId('motion-mode')).toHaveAttribute('data-count', '6');
    await expect(page.getByTestId('approx-count')).toHaveText(/best-fit dyads/);
    // The sixth pose is the default crank-rocker's next: a four-bar fits all six (it was none, "pivots coincide").
    await expect(page.getByTestId('approx-fourbars').getByRole('radio').first()).toBeChecked();
    await expect(page.getByTestId('motion-problem')).toHaveCount(0);
    await expect(page.getByTestId('motion-errors').locator('tbody tr')).toHaveCount(6);
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    expect(overflow).toBeLessThanOrEqual(0);
    await page.screenshot({ path: artifact('synthesis-motion-six-390.png'), fullPage: true });
    await context.close();
  });
});
