import { expect, test } from '@playwright/test';
import type { BrowserContext, CDPSession, ElementHandle, Locator, Page } from '@playwright/test';
import {
  artifact,
  chartPath,
  inkedPixels,
  ORIGIN,
  shownTheta2InPage,
  theta2Slider,
  waitReady,
  withoutLiveStage,
} from './helpers';

/**
 * The app at 6x CPU from the first load with every overlay on (query), once its live stage's worker is ready: the
 * slow page starts it from its first draws, before any drag or Play (seconds at 6x on a busy machine).
 */
async function slowPageWithStage(
  page: Page,
  context: BrowserContext,
  query: string,
): Promise<{ cdp: CDPSession; live: Locator }> {
  const cdp = await context.newCDPSession(page);
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: 6 });
  await page.goto(`./?${query}`);
  await waitReady(page, 60_000);
  const live = page.locator('canvas.linkage-live');
  // The page judges itself from its first draws. At 6x with every overlay it is slow, and the stage's worker starts
  // at once (ready before any Play or drag); but CDP's throttle lets short draws through at full speed, so on a quick
  // machine its first draws can read quick, and then the worker starts at the first Play or drag instead.
  await expect(live).toHaveAttribute('data-page', /^(quick|slow)$/, { timeout: 60_000 });
  if ((await live.getAttribute('data-page')) === 'slow')
    await expect(live).toHaveAttribute('data-stage', 'ready', { timeout: 60_000 });
  return { cdp, live };
}

test.describe('the simulator', () => {
  test('renders the default linkage, its numbers and its plots', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await expect(page.getByRole('heading', { name: 'Four-bar linkage lab' })).toBeVisible();
    await expect(page.getByRole('textbox', { name: /^r1/ })).toHaveValue('6');
    await expect(page.getByRole('textbox', { name: /^r2/ })).toHaveValue('2');
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('45');
    await expect(page.getByTestId('linkage-type')).toHaveText('Crank-rocker');
    await expect(page.getByText('I-2 GCRR')).toBeVisible();
    await expect(page.getByTestId('grashof-sums')).toContainText('S + L = 8 < P + Q = 10');
    await expect(page.getByRole('img', { name: /Linkage view\. θ2 45\.00°, θ3 44\.18°/ })).toBeVisible();
    expect(await inkedPixels(page)).toBeGreaterThan(2000);
    expect((await chartPath(page, 0)).length).toBeGreaterThan(200);
    expect((await chartPath(page, 1)).length).toBeGreaterThan(200);
    await expect(page.getByTestId('nr-iterations')).toHaveText(/^\d+$/);
    await page.screenshot({ path: artifact('default.png') });
  });

  test('the canvas keeps its box when the lazily loaded transmission plot arrives after ready', async ({ page }) => {
    // Hold the transmission plot's chunk until the page is ready: its arrival must not resize the canvas under a
    // pointer that aims at what ready showed.
    let release = () => {};
    const held = new Promise<void>((resolve) => (release = resolve));
    await page.route(/TransmissionPanel[^/]*\.(js|css)$/, async (route) => {
      await held;
      await route.continue().catch(() => undefined);
    });
    await page.goto('./');
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    const before = { box: await canvas.boundingBox(), p: await canvas.getAttribute('data-p') };
    release();
    await expect(page.locator('svg.transmission-svg')).toHaveCount(1);
    expect({ box: await canvas.boundingBox(), p: await canvas.getAttribute('data-p') }).toEqual(before);
  });

  test('redraws the plots while a slider is dragged and ends on the last value', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const before = await chartPath(page, 0);
    const slider = page.getByRole('slider', { name: /^r2/ });
    await slider.focus();
    for (let i = 0; i < 25; i++) await page.keyboard.press('ArrowRight');
    await expect(page.getByRole('textbox', { name: /^r2/ })).toHaveValue('2.25');
    await expect.poll(() => chartPath(page, 0)).not.toBe(before);
    const afterKeys = await chartPath(page, 0);
    // A real pointer drag along the r3 slider.
    const box = await page.getByRole('slider', { name: /^r3/ }).boundingBox();
    if (!box) throw new Error('r3 slider has no box');
    const y = box.y + box.height / 2;
    await page.mouse.move(box.x + box.width * 0.25, y);
    await page.mouse.down();
    for (let i = 1; i <= 15; i++) await page.mouse.move(box.x + box.width * (0.25 + i * 0.004), y);
    await page.mouse.up();
    const r3 = Number(await page.getByRole('textbox', { name: /^r3/ }).inputValue());
    expect(r3).not.toBe(5);
    await expect.poll(() => chartPath(page, 0)).not.toBe(afterKeys);
    await expect(page.getByTestId('grashof-sums')).not.toHaveText(/P \+ Q = 10$/);
  });

  test('Play advances theta2 and Pause stops it', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const theta2 = page.getByRole('textbox', { name: /^θ2/ });
    await expect(theta2).toHaveValue('45');
    await page.getByRole('button', { name: 'Play' }).click();
    await expect(page.getByRole('button', { name: 'Pause' })).toBeVisible();
    await expect.poll(async () => Number(await theta2.inputValue()), { timeout: 5000 }).toBeGreaterThan(50);
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
    const stopped = await theta2.inputValue();
    await page.waitForTimeout(600);
    await expect(theta2).toHaveValue(stopped);
  });

  test('Step forward turns the crank in the chosen direction, Step back the other way', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const theta2 = page.getByRole('textbox', { name: /^θ2/ });
    // 360 samples per turn: one step is 1°.
    await page.getByRole('button', { name: 'Step forward' }).click();
    await expect(theta2).toHaveValue('46');
    // The numbers (the worker's answer) follow the step too.
    await expect(page.getByRole('heading', { name: 'At θ2 = 46.00°' })).toBeVisible();
    await page.getByRole('radio', { name: 'Clockwise', exact: true }).check();
    await page.getByRole('button', { name: 'Step forward' }).click();
    await expect(theta2).toHaveValue('45');
    await page.getByRole('button', { name: 'Step forward' }).click();
    await expect(theta2).toHaveValue('44');
    await page.getByRole('button', { name: 'Step back' }).click();
    await expect(theta2).toHaveValue('45');
    await expect(page.getByRole('img', { name: /^Linkage view\. θ2 45\.00°/ })).toBeVisible();
  });

  test('draws a new pose in every animation frame while playing, on the page where no worker can draw', async ({
    page,
  }) => {
    await withoutLiveStage(page);
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('button', { name: 'Play' }).click();
    await expect(page.getByRole('button', { name: 'Pause' })).toBeVisible();
    // Over 30 frames, the canvas's pose (its label names θ2) changes in each one: no frame waits on the worker.
    const labels = await page.locator('canvas.linkage-canvas').evaluate(
      (c) =>
        new Promise<string[]>((resolve) => {
          const seen: string[] = [];
          const tick = () => {
            seen.push(c.getAttribute('aria-label') ?? '');
            if (seen.length < 30) requestAnimationFrame(tick);
            else resolve(seen);
          };
          requestAnimationFrame(tick);
        }),
    );
    await page.getByRole('button', { name: 'Pause' }).click();
    const changes = labels.slice(1).filter((l, i) => l !== labels[i]).length;
    expect(changes).toBe(labels.length - 1);
    await expect(page.locator('canvas.linkage-live')).toHaveCount(0);
  });

  test('Play is drawn in a worker over the canvas: every frame it draws is a new pose, and Pause hands the canvas back', async ({
    page,
  }) => {
    await page.goto('./');
    await waitReady(page);
    const live = page.locator('canvas.linkage-live');
    await expect(live).toBeHidden();
    await page.getByRole('button', { name: 'Play' }).click();
    // The worker starts at this first Play (a quick page does not load it before): its start-up is the wait.
    await expect(live).toBeVisible({ timeout: 30_000 });
    // 30 of the worker's frames as the page hears of them: each names a new θ2, further along (a crank turns on).
    const drawn = await live.evaluate(
      (c: HTMLCanvasElement) =>
        new Promise<number[]>((resolve) => {
          const seen: number[] = [];
          new MutationObserver((_records, observer) => {
            seen.push(Number(c.dataset.theta2));
            if (seen.length < 30) return;
            observer.disconnect();
            resolve(seen);
          }).observe(c, { attributes: true, attributeFilter: ['data-theta2'] });
        }),
    );
    const steps = drawn.slice(1).map((d, i) => (d - drawn[i] + 360) % 360);
    expect(
      steps.every((s) => s > 0 && s < 30),
      steps.join(' '),
    ).toBe(true);
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(live).toBeHidden();
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
    // Another page and back: the simulator's canvas is a new element, and the worker draws on it.
    await page.getByRole('tab', { name: 'Solver lab' }).click();
    await page.getByRole('tab', { name: 'Simulator' }).click();
    await page.getByRole('button', { name: 'Play' }).click();
    const again = page.locator('canvas.linkage-live');
    await expect(again).toBeVisible();
    const before = await again.getAttribute('data-theta2');
    await expect.poll(() => again.getAttribute('data-theta2')).not.toBe(before);
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(again).toBeHidden();
  });

  for (const [plots, query] of [
    ['angle', ''],
    ['velocity', '?plot=vel'],
    ['input torque', '?frc=1&plot=trq'],
  ] as const) {
    test(`while the worker draws Play, each ${plots} plot's marker follows its frames: every move is to a θ2 it drew`, async ({
      page,
    }) => {
      await page.goto(`./${query}`);
      await waitReady(page);
      await page.getByRole('button', { name: 'Play' }).click();
      const live = page.locator('canvas.linkage-live');
      await expect(live).toBeVisible({ timeout: 30_000 });
      // Recorded in the page: the θ2 of each frame the worker draws, and each marker's moves as the θ2 on its own
      // chart's x scale (data-x over the plot's width), 20 moves of each marker.
      const followed = await page.evaluate(() => {
        const canvas = document.querySelector<HTMLCanvasElement>('canvas.linkage-live');
        // The charts against θ2 on screen: those with a marker box over their SVG (one below the fold keeps its
        // marker still until it is scrolled to).
        const boxes = [...document.querySelectorAll<HTMLElement>('.chart-box')].filter((b) => {
          const r = b.getBoundingClientRect();
          const shown = r.bottom > 0 && r.top < window.innerHeight;
          return shown && b.querySelector('.chart-marker') && b.querySelector('svg g.axis-x path.domain');
        });
        if (!canvas || boxes.length === 0) throw new Error('no live canvas or no θ2 chart');
        const drawn: number[] = [];
        // The page's own frames, counted as they come.
        let pageFrames = 0;
        const count = () => {
          pageFrames++;
          requestAnimationFrame(count);
        };
        requestAnimationFrame(count);
        new MutationObserver(() => drawn.push(Number(canvas.dataset.theta2))).observe(canvas, {
          attributes: true,
          attributeFilter: ['data-theta2'],
        });
        return Promise.all(
          boxes.map(
            (box) =>
              new Promise<{ label: string; moves: { theta2: number; off: number; pageFrame: number }[] }>((resolve) => {
                const svg = box.querySelector('svg') as SVGSVGElement;
                const width = (svg.querySelector('g.axis-x path.domain') as SVGPathElement).getBBox().width;
                const marker = box.querySelector<HTMLElement>('.chart-marker') as HTMLElement;
                const moves: { theta2: number; off: number; pageFrame: number }[] = [];
                new MutationObserver((_r, observer) => {
                  // From the worker's tenth frame the page hears of: a move to a frame drawn before the page
                  // listened (a busy page starts some frames behind) could not be told from a wrong one.
                  if (drawn.length < 10) return;
                  const theta2 = (Number(marker.dataset.x) / width) * 360;
                  // How far that θ2 is from the nearest of the worker's last 30 frames (degrees, around the turn).
                  const recent = drawn.slice(-30);
                  const off = Math.min(...recent.map((d) => Math.abs(((theta2 - d + 540) % 360) - 180)));
                  moves.push({ theta2, off, pageFrame: pageFrames });
                  if (moves.length < 20) return;
                  observer.disconnect();
                  resolve({ label: svg.getAttribute('aria-label') ?? '', moves });
                }).observe(marker, { attributes: true, attributeFilter: ['data-x'] });
              }),
          ),
        );
      });
      for (const { label, moves } of followed) {
        // The frame's θ2 on a chart some 300 px wide: half a degree is a pixel's rounding, not another frame.
        expect(
          moves.every((m) => m.off < 0.5),
          `${label}: ${moves.map((m) => `${m.theta2.toFixed(1)} (${m.off.toFixed(2)})`).join(' ')}`,
        ).toBe(true);
        // It follows the page's frames, not the state's commits (at most five a second, fewer on a page that drops
        // frames): a move in about every page frame, whatever the machine's load.
        const pageFramesPerMove = (moves[moves.length - 1].pageFrame - moves[0].pageFrame) / (moves.length - 1);
        expect(pageFramesPerMove, label).toBeLessThan(2);
        // The marker moves on (a commit may place it again at the same θ2).
        expect(new Set(moves.map((m) => m.theta2.toFixed(1))).size, label).toBeGreaterThanOrEqual(15);
      }
      expect(followed.length).toBeGreaterThanOrEqual(plots === 'input torque' ? 1 : 2);
      await page.getByRole('button', { name: 'Pause' }).click();
      await expect(live).toBeHidden();
    });
  }

  test('on a slow page a θ2 drag is drawn by the worker over the canvas, and the release hands the canvas back at its value', async ({
    page,
    context,
  }) => {
    // 6x CPU from the first load: the page's own drawing of every overlay is slow, so the drag goes to the stage.
    test.setTimeout(120_000);
    const { cdp, live } = await slowPageWithStage(page, context, 't2=45&vel=1&acc=1&dc=1&ic=1&frc=1&fv=1');
    const field = page.getByRole('textbox', { name: /^θ2/ });
    // What the stage's canvas shows at each of its changes, with the field's value then (read in the page: a poll
    // from here takes long enough on a busy machine for the drag to rest and end between two reads).
    const fieldElement = await field.elementHandle();
    await live.evaluate(
      (c: HTMLCanvasElement, input) => {
        const seen: { shown: boolean; theta2: number; field: number }[] = [];
        (window as unknown as { stageSeen: typeof seen }).stageSeen = seen;
        new MutationObserver(() => {
          seen.push({ shown: !c.hidden, theta2: Number(c.dataset.theta2), field: Number(input?.value) });
        }).observe(c, { attributes: true, attributeFilter: ['hidden', 'data-theta2'] });
      },
      fieldElement as ElementHandle<HTMLInputElement> | null,
    );
    const { x, y } = await theta2Slider(page);
    // A page its first draws judged quick (slowPageWithStage) draws a drag's first moves itself; at 12x its draws
    // judge it slow within a few moves, and the stage takes the drag over (the next test checks that route).
    if ((await live.getAttribute('data-page')) === 'quick')
      await cdp.send('Emulation.setCPUThrottlingRate', { rate: 12 });
    await page.mouse.move(x(45), y);
    await page.mouse.down();
    for (let deg = 46; deg <= 90; deg += 1) await page.mouse.move(x(deg), y);
    // While the pointer is down the stage shows the value the field shows, and the drag went past 85°.
    await expect
      .poll(
        () =>
          page.evaluate(() =>
            (window as unknown as { stageSeen: { shown: boolean; theta2: number; field: number }[] }).stageSeen.some(
              (s) => s.shown && s.field > 85 && Math.abs(s.theta2 - s.field) < 1e-9,
            ),
          ),
        { timeout: 30_000 },
      )
      .toBe(true);
    await page.mouse.up();
    await expect(live).toBeHidden();
    const dragged = Number(await field.inputValue());
    expect(Math.abs((await page.evaluate(shownTheta2InPage)) - dragged)).toBeLessThanOrEqual(0.006);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: 1 });
  });

  test('a θ2 drag the page draws goes over to the worker once the page turns slow, and stays there to the release', async ({
    page,
    context,
  }) => {
    test.setTimeout(120_000);
    await page.goto('./?t2=45');
    await waitReady(page);
    const live = page.locator('canvas.linkage-live');
    // The page judges itself from its first draws (at idle after the load; no overlays, so most machines find it
    // quick at 1x). A busy machine can find it slow: then every drag is the stage's from its first move, and this
    // test checks that instead.
    await expect(live).toHaveAttribute('data-page', /^(quick|slow)$/, { timeout: 30_000 });
    const judgedQuick = (await live.getAttribute('data-page')) === 'quick';
    test.info().annotations.push({ type: 'page judged', description: judgedQuick ? 'quick' : 'slow' });
    const cdp = await context.newCDPSession(page);
    const { x, y } = await theta2Slider(page);
    await page.mouse.move(x(45), y);
    await page.mouse.down();
    await page.mouse.move(x(50), y);
    let deg = 50;
    if (judgedQuick) {
      // The page draws the drag's first moves itself.
      await expect.poll(() => page.evaluate(shownTheta2InPage)).toBeGreaterThan(49);
      await expect(live).toBeHidden();
      // The page turns slow in the middle of the drag: its draws at 12x judge it slow, and a later move of the same
      // drag goes to the stage.
      await cdp.send('Emulation.setCPUThrottlingRate', { rate: 12 });
      // Its draws judge it within a few moves (six draws at most); sixty are plenty on a busy machine.
      while (deg < 110 && !(await live.isVisible())) await page.mouse.move(x(++deg), y);
    }
    await expect(live).toBeVisible();
    await expect(live).toHaveAttribute('data-page', 'slow');
    // From here to the release the stage keeps the drag: its canvas is never hidden again before the pointer is up.
    await live.evaluate((c: HTMLCanvasElement) => {
      const hidden: boolean[] = [];
      (window as unknown as { liveHidden: boolean[] }).liveHidden = hidden;
      new MutationObserver(() => hidden.push(c.hidden)).observe(c, { attributes: true, attributeFilter: ['hidden'] });
    });
    const last = deg + 10;
    while (deg < last) await page.mouse.move(x(++deg), y);
    await expect.poll(async () => Number(await live.getAttribute('data-theta2'))).toBeGreaterThan(last - 2);
    expect(await page.evaluate(() => (window as unknown as { liveHidden: boolean[] }).liveHidden)).not.toContain(true);
    await page.mouse.up();
    await expect(live).toBeHidden();
    const dragged = Number(await page.getByRole('textbox', { name: /^θ2/ }).inputValue());
    expect(Math.abs((await page.evaluate(shownTheta2InPage)) - dragged)).toBeLessThanOrEqual(0.006);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: 1 });
  });

  test('on a slow page Pause keeps the frame the worker drew last, though the page is frames behind it', async ({
    page,
    context,
  }) => {
    test.setTimeout(120_000);
    const { cdp, live } = await slowPageWithStage(page, context, 'vel=1&acc=1&dc=1&ic=1&frc=1&fv=1');
    await page.getByRole('button', { name: 'Play' }).click();
    // From the stage's third frame of the run (the page's thread at 6x on a busy machine hears of them slowly).
    await expect(live).toBeVisible({ timeout: 30_000 });
    await expect
      .poll(async () => Number(await live.getAttribute('data-theta2')), { timeout: 30_000 })
      .toBeGreaterThan(80);
    const shown = await page.getByRole('button', { name: 'Pause' }).evaluate(shownTheta2InPage);
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
    await expect(live).toBeHidden();
    const field = page.getByRole('textbox', { name: /^θ2/ });
    await expect.poll(async () => Math.abs(Number(await field.inputValue()) - shown)).toBeLessThanOrEqual(0.006);
    expect(Math.abs((await page.evaluate(shownTheta2InPage)) - shown)).toBeLessThanOrEqual(0.006);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: 1 });
  });

  test('Pause keeps the pose on screen: the θ2 field, the plots and the address bar take it, nothing jumps back', async ({
    page,
  }) => {
    await page.goto('./');
    await waitReady(page);
    const canvas = page.locator('canvas.linkage-canvas');
    const canvasTheta2 = async () =>
      Number(/θ2 (-?[\d.]+)°/.exec((await canvas.getAttribute('aria-label')) ?? '')?.[1]);
    const start = await canvasTheta2();
    await page.getByRole('button', { name: 'Play' }).click();
    // Well past the first commit of the playhead to the state (a few times a second).
    await expect.poll(() => page.evaluate(shownTheta2InPage)).toBeGreaterThan(start + 40);
    // The pose on screen at the moment of the click (the live stage's, Play drawn in a worker), read in the same
    // task as the click.
    const shown = await page.getByRole('button', { name: 'Pause' }).evaluate(shownTheta2InPage);
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
    // The field and the address bar show the paused pose (the label rounds to hundredths), and the canvas stays there.
    const field = page.getByRole('textbox', { name: /^θ2/ });
    await expect.poll(async () => Math.abs(Number(await field.inputValue()) - shown)).toBeLessThanOrEqual(0.006);
    await expect
      .poll(() => Math.abs(Number(new URL(page.url()).searchParams.get('t2')) - shown))
      .toBeLessThanOrEqual(0.006);
    expect(Math.abs((await canvasTheta2()) - shown)).toBeLessThanOrEqual(0.006);
    await expect(page.locator('canvas.linkage-live')).toBeHidden();
    // The plot marker sits at the same θ2: its x on the θ3 plot is that θ2 on the chart's own x scale.
    const markerX = await page.locator('.chart-marker').first().getAttribute('data-x');
    const plotWidth = await page
      .getByRole('img', { name: 'θ3 against θ2' })
      .evaluate((svg) => (svg.querySelector('g.axis-x path.domain') as SVGPathElement).getBBox().width);
    expect(Math.abs((Number(markerX) / plotWidth) * 360 - shown)).toBeLessThan(0.5);
  });

  test("the page's canvas under the worker's is not drawn during Play; Pause draws it at the paused pose", async ({
    page,
  }) => {
    // The app's draw marks (benchMarks.ts): each draw of the page's canvas marks its θ2.
    await page.addInitScript(() => {
      (globalThis as Record<string, unknown>).__FOURBAR_BENCH__ = true;
    });
    await page.goto('./');
    await waitReady(page);
    const draws = () =>
      page.evaluate(() =>
        performance
          .getEntriesByName('fourbar:canvas')
          .map((m) => ((m as PerformanceMark).detail as { theta2Rad: number }).theta2Rad),
      );
    await page.getByRole('button', { name: 'Play' }).click();
    await expect(page.locator('canvas.linkage-live')).toBeVisible({ timeout: 30_000 });
    // Two of Play's commits to the state: the θ2 field takes a new value twice.
    const field = page.getByRole('textbox', { name: /^θ2/ });
    const before = (await draws()).length;
    for (let i = 0; i < 2; i++) {
      const value = await field.inputValue();
      await expect.poll(() => field.inputValue()).not.toBe(value);
    }
    expect((await draws()).length).toBe(before);
    const shown = await page.getByRole('button', { name: 'Pause' }).evaluate(shownTheta2InPage);
    await expect(page.locator('canvas.linkage-live')).toBeHidden();
    await expect
      .poll(async () => {
        const last = (await draws()).at(-1) ?? Number.NaN;
        return Math.abs((((last * 180) / Math.PI) % 360) - shown);
      })
      .toBeLessThanOrEqual(0.006);
  });

  test('while Play runs, a results card off screen keeps its numbers until it is scrolled to; Pause brings all to the pose', async ({
    page,
  }) => {
    await page.goto('./');
    await waitReady(page);
    // At 1280x800 the analysis card is on screen and the motion card below it, off screen in the results column.
    const analysisAt = page
      .locator('#sec-analysis')
      .locator('xpath=..')
      .getByText(/^At θ2 = /);
    const motion = page.locator('section[aria-labelledby="sec-motion-results"]');
    const motionAt = motion.getByRole('heading', { name: /^Rates, θ2 = / });
    await expect(motion).not.toBeInViewport();
    await page.getByRole('button', { name: 'Play' }).click();
    // Three of Play's commits as the analysis card shows them; the motion card keeps the θ2 it showed after the first.
    let shownAt = await analysisAt.textContent();
    await expect.poll(() => analysisAt.textContent()).not.toBe(shownAt);
    const held = await motionAt.textContent();
    for (let i = 0; i < 2; i++) {
      shownAt = await analysisAt.textContent();
      await expect.poll(() => analysisAt.textContent()).not.toBe(shownAt);
    }
    expect(await motionAt.textContent()).toBe(held);
    // Scrolled to, it takes Play's frames again.
    await motion.scrollIntoViewIfNeeded();
    await expect.poll(() => motionAt.textContent()).not.toBe(held);
    await motion.evaluate((el) => el.closest('aside')?.scrollTo(0, 0));
    await expect(motion).not.toBeInViewport();
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
    // Paused, every card shows the paused pose, the ones off screen included.
    const theta2Of = (text: string | null) => /θ2 = ([\d.]+)°/.exec(text ?? '')?.[1];
    await expect
      .poll(async () => theta2Of(await motionAt.textContent()))
      .toBe(theta2Of(await analysisAt.textContent()));
    expect(theta2Of(await analysisAt.textContent())).toBe(
      Number(await page.getByRole('textbox', { name: /^θ2/ }).inputValue()).toFixed(2),
    );
  });

  test('while Play runs, a plot below the fold keeps its marker still; scrolled to, it shows the paused θ2 and follows Play', async ({
    page,
  }) => {
    await page.goto('./');
    await waitReady(page);
    // At 1280x800 the angle plots are on screen and the transmission plot below them, off screen.
    const below = page.locator('.transmission-card .chart-box');
    const belowMarker = below.locator('.chart-marker');
    const shownMarker = page.locator('.plots .chart-marker').first();
    await expect(belowMarker).toHaveAttribute('data-x', /\d/);
    await expect(below).not.toBeInViewport();
    await page.getByRole('button', { name: 'Play' }).click();
    await expect(page.locator('canvas.linkage-live')).toBeVisible({ timeout: 30_000 });
    const still = await belowMarker.getAttribute('data-x');
    // The plot on screen moves its marker again and again meanwhile.
    for (let i = 0; i < 3; i++) {
      const x = await shownMarker.getAttribute('data-x');
      await expect.poll(() => shownMarker.getAttribute('data-x')).not.toBe(x);
    }
    expect(await belowMarker.getAttribute('data-x')).toBe(still);
    // Paused off screen, then scrolled to: the marker is drawn at the paused θ2 (on its chart's own x scale).
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
    const paused = Number(await page.getByRole('textbox', { name: /^θ2/ }).inputValue());
    await below.scrollIntoViewIfNeeded();
    const width = await below.evaluate(
      (box) => (box.querySelector('svg g.axis-x path.domain') as SVGPathElement).getBBox().width,
    );
    await expect
      .poll(async () => Math.abs((Number(await belowMarker.getAttribute('data-x')) / width) * 360 - paused))
      .toBeLessThan(0.5);
    // On screen, it follows Play.
    await page.getByRole('button', { name: 'Play' }).click();
    const at = await belowMarker.getAttribute('data-x');
    await expect.poll(() => belowMarker.getAttribute('data-x')).not.toBe(at);
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
  });

  test('switches to Traditional Chinese and back', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('combobox', { name: 'Language' }).selectOption('zh-TW');
    await expect(page.getByRole('heading', { name: '四連桿機構實驗室' })).toBeVisible();
    await expect(page.getByRole('button', { name: '播放' })).toBeVisible();
    await expect(page.getByTestId('linkage-type')).toHaveText('曲柄搖桿');
    await expect(page.locator('html')).toHaveAttribute('lang', 'zh-Hant-TW');
    await expect.poll(() => new URL(page.url()).searchParams.get('lang')).toBe('zh-TW');
    await page.screenshot({ path: artifact('zh-TW.png') });
    await page.getByRole('combobox', { name: '語言' }).selectOption('en');
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
  });

  test('picks Traditional Chinese from the browser language', async ({ browser }) => {
    const context = await browser.newContext({ locale: 'zh-TW', viewport: { width: 1280, height: 800 } });
    const page = await context.newPage();
    await page.goto(`${ORIGIN}/`);
    await expect(page.getByRole('button', { name: '播放' })).toBeVisible();
    await context.close();
  });

  test('shows an inline message for bad input and keeps the last valid linkage', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const r2 = page.getByRole('textbox', { name: /^r2/ });
    const cases: [string, RegExp][] = [
      ['', /r2: enter a number/],
      ['abc', /r2: “abc” is not a number/],
      ['0', /r2 must be greater than 0, got 0/],
      ['-1', /r2 must not be negative, got -1/],
      ['1e308', /r2: 1e308 is out of range/],
    ];
    for (const [text, message] of cases) {
      await r2.fill(text);
      await expect(page.getByRole('alert').filter({ hasText: message })).toBeVisible();
      await expect(r2).toHaveAttribute('aria-invalid', 'true');
      await expect(page.getByTestId('grashof-sums')).toContainText('S + L = 8 < P + Q = 10');
    }
    await expect(page.getByRole('alert').first()).toContainText('Keeping the last valid value, 2.');
    await page.screenshot({ path: artifact('bad-input.png') });
    expect(await inkedPixels(page)).toBeGreaterThan(2000);
    await r2.fill('2.5');
    await expect(page.getByRole('alert')).toHaveCount(0);
    await expect(page.getByTestId('grashof-sums')).toContainText('S + L = 8.5');
  });

  test('says the linkage cannot assemble instead of drawing it torn, and the plots have gaps', async ({ page }) => {
    await page.goto('./?r1=4&r2=3&r3=3.5&r4=3&t2=180');
    await waitReady(page);
    await expect(page.getByRole('status').filter({ hasText: 'Cannot assemble at θ2 = 180.00°' })).toHaveCount(1);
    await expect(page.getByTestId('linkage-type')).toHaveText('Triple rocker');
    const d = await chartPath(page, 0);
    expect(d.split('M').length - 1).toBeGreaterThanOrEqual(2);
    expect(d).not.toContain('NaN');
    await page.screenshot({ path: artifact('cannot-assemble.png') });
  });

  test('never draws NaN into the page', async ({ page }) => {
    await page.goto('./?r1=10&r2=1&r3=2&r4=3');
    await waitReady(page);
    // Said on the canvas, and on the export panel's status line (its buttons wait for a linkage that assembles).
    await expect(
      page.locator('.stage').getByRole('status').filter({ hasText: 'cannot be assembled at any input angle' }),
    ).toHaveCount(1);
    await expect(page.locator('.export-panel').getByRole('status').first()).toHaveText(
      'This linkage cannot be assembled at any input angle',
    );
    const html = await page.locator('main').innerHTML();
    expect(html).not.toContain('NaN');
    const right = await page.locator('.rightbar').innerText();
    expect(right).not.toContain('NaN');
  });
});
