import type { Frame, Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { canvasToolsRect } from '../src/shared/canvas/canvasTools';
import { ORIGIN, artifact, waitReady } from './helpers';

// Every screen a student meets: a phone, a tablet, a laptop, and the embed widget inside a course page's
// iframe at the snippet's own size (760x520) and at 600x450. The checks are geometric (what lies inside the
// viewport at scroll 0); the screenshots are artefacts to look at.

/** A box in CSS pixels relative to the viewport of the document that holds it. */
interface Box {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

/** Scroll facts of a document: its scrolling width, the viewport size and the scroll position. */
async function viewportOf(target: Page | Frame) {
  return target.evaluate(() => ({
    scrollWidth: document.scrollingElement!.scrollWidth,
    innerWidth: window.innerWidth,
    innerHeight: window.innerHeight,
    scrollX: window.scrollX,
    scrollY: window.scrollY,
  }));
}

/** The viewport-relative box of an element. */
async function boxOf(locator: ReturnType<Page['locator']>): Promise<Box> {
  return locator.evaluate((el) => {
    const r = el.getBoundingClientRect();
    return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
  });
}

/** True when a non-empty box lies inside a width x height viewport (1 px slack for subpixel layout). */
function inside(b: Box, width: number, height: number): boolean {
  return b.left >= -1 && b.top >= -1 && b.right <= width + 1 && b.bottom <= height + 1 && b.right > b.left;
}

/** The zoom buttons' box relative to the canvas, as laid out by the CSS. */
async function toolsOnCanvas(target: Page | Frame) {
  return target.locator('.canvas-wrap').evaluate((wrap) => {
    const c = wrap.querySelector('canvas')!.getBoundingClientRect();
    const t = wrap.querySelector('.canvas-tools')!.getBoundingClientRect();
    return { canvasWidth: c.width, x: t.left - c.left, y: t.top - c.top, width: t.width, height: t.height };
  });
}

/** The zoom buttons sit exactly where the renderer's label exclusion (canvasToolsRect, from the tokens) says. */
async function expectToolsWhereLabelsAvoid(target: Page | Frame): Promise<void> {
  const t = await toolsOnCanvas(target);
  const r = canvasToolsRect(t.canvasWidth);
  expect(t.x).toBeCloseTo(r.x, 0);
  expect(t.y).toBeCloseTo(r.y, 0);
  expect(t.width).toBeCloseTo(r.width, 0);
  expect(t.height).toBeCloseTo(r.height, 0);
}

/** Texts of visible labels, titles, tabs and buttons whose content does not fit their box (cut off). */
async function clippedLabels(target: Page | Frame): Promise<string[]> {
  return target.evaluate(() =>
    [
      ...document.querySelectorAll<HTMLElement>(
        'label, legend, .section-title, .segmented-item span, .btn, .page-tab, .fact dt, .fact dd',
      ),
    ]
      // A visually hidden legend (sr-only: the phone bar's "Branch") is a name for assistive technology, not cut-off text.
      .filter(
        (el) => el.offsetParent !== null && !el.classList.contains('sr-only') && el.scrollWidth > el.clientWidth + 1,
      )
      .map((el) => el.textContent ?? ''),
  );
}

const PHONE = { width: 390, height: 844 };

for (const lang of ['en', 'zh-TW'] as const) {
  test(`a 390x844 phone (${lang}): one column, no horizontal scroll, a full-width canvas, the header fits`, async ({
    browser,
  }) => {
    const context = await browser.newContext({ viewport: PHONE, locale: lang === 'en' ? 'en-US' : 'zh-TW' });
    const page = await context.newPage();
    await page.goto(`./?lang=${lang}`);
    await waitReady(page);
    const v = await viewportOf(page);
    expect(v.scrollWidth).toBeLessThanOrEqual(v.innerWidth);
    const canvas = await boxOf(page.locator('canvas.linkage-canvas'));
    // The canvas spans the viewport less the page padding and the card border (at most 10 px a side).
    expect(canvas.right - canvas.left).toBeGreaterThanOrEqual(v.innerWidth - 20);
    expect(canvas.left).toBeGreaterThanOrEqual(0);
    expect(canvas.right).toBeLessThanOrEqual(v.innerWidth);
    // Tall enough to show the linkage, not a strip: at least two thirds as tall as wide.
    expect(canvas.bottom - canvas.top).toBeGreaterThanOrEqual((2 / 3) * (canvas.right - canvas.left));
    // One column: the controls sit below the canvas, not beside it.
    const theta2 = page.getByRole('textbox', { name: /^θ2/ });
    expect((await boxOf(theta2)).top).toBeGreaterThan(canvas.bottom);
    await expect(theta2).toBeVisible();
    await expect(page.getByRole('slider', { name: /^θ2/ })).toBeVisible();
    await expect(page.getByRole('button', { name: lang === 'en' ? 'Play' : '播放' })).toBeVisible();
    // The header: every child inside the viewport, and each tab name on one line.
    const header = page.locator('header').first();
    for (const child of await header.locator(':scope > *').all()) {
      expect(inside(await boxOf(child), v.innerWidth, 10_000), await child.innerText()).toBe(true);
    }
    for (const tab of await page.getByRole('tab').all()) {
      const lines = await tab.evaluate((el) => {
        const range = document.createRange();
        range.selectNodeContents(el);
        // One line of text gives rects that all share a top.
        return new Set([...range.getClientRects()].map((r) => Math.round(r.top))).size;
      });
      expect(lines, await tab.innerText()).toBe(1);
    }
    expect(await clippedLabels(page)).toEqual([]);
    await expectToolsWhereLabelsAvoid(page);
    await page.screenshot({ path: artifact(`screen-phone-${lang}.png`) });
    await page.screenshot({ path: artifact(`screen-phone-${lang}-full.png`), fullPage: true });
    await context.close();
  });
}

for (const size of [
  { width: 1280, height: 800, name: 'laptop' },
  { width: 820, height: 1180, name: 'tablet' },
]) {
  test(`a ${size.width}x${size.height} ${size.name}: no horizontal scroll, no label cut off`, async ({ browser }) => {
    const context = await browser.newContext({ viewport: { width: size.width, height: size.height } });
    const page = await context.newPage();
    await page.goto('./');
    await waitReady(page);
    const v = await viewportOf(page);
    expect(v.scrollWidth).toBeLessThanOrEqual(v.innerWidth);
    // No visible label, title, tab or button text is clipped: its content fits its box.
    expect(await clippedLabels(page)).toEqual([]);
    await expectToolsWhereLabelsAvoid(page);
    await page.screenshot({ path: artifact(`screen-${size.name}.png`), fullPage: true });
    await context.close();
  });
}

test('a desktop from 1101 to 1440 px wide keeps the top bar in one row, in both languages, on every page', async ({
  browser,
}) => {
  // Two rows at a laptop's 1280 px took 31 px from the simulator's canvas (DesignBar.css, layout.css).
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const oneRow: string[] = [];
  for (const lang of ['en', 'zh-TW']) {
    for (const query of ['', 'page=lab&', 'page=syn&', 'page=mech&', 'page=3d&']) {
      await page.goto(`./?${query}lang=${lang}`);
      const bar = page.locator('.topbar');
      await expect(page.locator('.page-tab.active')).toBeVisible();
      for (const width of [1101, 1179, 1180, 1280, 1365, 1366, 1440]) {
        await page.setViewportSize({ width, height: 800 });
        // The bar's children share one row: none starts below the first's bottom.
        const rows = await bar.evaluate((b) => {
          const boxes = [...b.children]
            .filter((c) => !['absolute', 'fixed'].includes(getComputedStyle(c).position))
            .map((c) => c.getBoundingClientRect())
            .filter((r) => r.width > 0 && r.height > 0);
          const firstBottom = Math.min(...boxes.map((r) => r.bottom));
          return boxes.length > 0 && boxes.every((r) => r.top < firstBottom - 1) ? 1 : 2;
        });
        if (rows !== 1) oneRow.push(`${lang} ${query || 'simulator'} ${width}px`);
      }
    }
  }
  expect(oneRow).toEqual([]);
  await context.close();
});

const HOST = `${ORIGIN}/e2e-course/screens.html`;
// The default embed (controls and plots), as the app's "Copy embed code" makes it, with two lengths locked.
const EMBED_SRC = `${ORIGIN}/embed.html?r1=6&r2=2&r3=5&r4=5&t2=45&panels=controls,plots&lock=r1,r4`;

for (const frame of [
  { width: 760, height: 520 },
  { width: 600, height: 450 },
]) {
  test(`the embed in a ${frame.width}x${frame.height} frame shows the linkage, θ2, Play and the branch unscrolled`, async ({
    page,
  }) => {
    await page.setViewportSize({ width: frame.width + 40, height: frame.height + 40 });
    await page.route(HOST, (route) =>
      route.fulfill({
        contentType: 'text/html',
        body: `<!doctype html><html><head><title>Course page</title></head><body style="margin:20px">
<iframe id="sim" title="Four-bar linkage simulator" sandbox="allow-scripts allow-same-origin" src="${EMBED_SRC}"
 width="${frame.width}" height="${frame.height}" style="border:0"></iframe></body></html>`,
      }),
    );
    await page.goto(HOST);
    await waitReady(page.frameLocator('#sim'));
    const f = page.frame({ url: /embed\.html/ });
    if (!f) throw new Error('no embed frame');
    const v = await viewportOf(f);
    expect([v.innerWidth, v.innerHeight, v.scrollX, v.scrollY]).toEqual([frame.width, frame.height, 0, 0]);
    expect(v.scrollWidth).toBeLessThanOrEqual(v.innerWidth);
    const need = {
      canvas: f.locator('canvas.linkage-canvas'),
      'θ2 field': f.getByRole('textbox', { name: /^θ2/ }),
      'θ2 slider': f.getByRole('slider', { name: /^θ2/ }),
      Play: f.getByRole('button', { name: 'Play' }),
      branch: f.getByRole('group', { name: 'Branch' }),
    };
    for (const [name, locator] of Object.entries(need)) {
      const b = await boxOf(locator);
      expect(inside(b, v.innerWidth, v.innerHeight), `${name} at ${JSON.stringify(b)}`).toBe(true);
    }
    // The linkage gets a real share of the frame, not a sliver.
    const c = await boxOf(need.canvas);
    expect((c.right - c.left) * (c.bottom - c.top)).toBeGreaterThan(0.25 * v.innerWidth * v.innerHeight);
    // The controls' labels (including "(locked)") wrap rather than being cut off.
    expect(await clippedLabels(f)).toEqual([]);
    await expectToolsWhereLabelsAvoid(f);
    await page.screenshot({ path: artifact(`screen-embed-${frame.width}x${frame.height}.png`) });
  });
}
