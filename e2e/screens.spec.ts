import type { Frame, Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { ORIGIN, artifact, waitReady } from './helpers';

// Every screen a student meets: a phone, a tablet, a laptop, and the embed widget inside a course page's
// iframe at the snippet's own size and at 600x450. The checks are geometric (what is inside the viewport),
// the screenshots are artefacts to look at.

/** A box in CSS pixels relative to the viewport of the document that holds it. */
interface Box {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

/** Horizontal overflow facts of a document: its scrolling width, the viewport width and the scroll position. */
async function overflow(target: Page | Frame) {
  return target.evaluate(() => ({
    scrollWidth: document.scrollingElement!.scrollWidth,
    scrollHeight: document.scrollingElement!.scrollHeight,
    innerWidth: window.innerWidth,
    innerHeight: window.innerHeight,
    scrollX: window.scrollX,
    scrollY: window.scrollY,
  }));
}

/** The viewport-relative box of the first element matching selector in target. */
async function boxOf(target: Page | Frame, selector: string): Promise<Box> {
  return target
    .locator(selector)
    .first()
    .evaluate((el) => {
      const r = el.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    });
}

/** True when box lies inside a width x height viewport at scroll 0 (1 px slack for subpixel layout). */
function inside(b: Box, width: number, height: number): boolean {
  return b.left >= -1 && b.top >= -1 && b.right <= width + 1 && b.bottom <= height + 1 && b.right > b.left;
}

const PHONE = { width: 390, height: 844 };

for (const lang of ['en', 'zh-TW'] as const) {
  test(`a 390x844 phone (${lang}) gets one column, no horizontal scroll, a full-width canvas`, async ({ browser }) => {
    const context = await browser.newContext({ viewport: PHONE, locale: lang === 'en' ? 'en-US' : 'zh-TW' });
    const page = await context.newPage();
    await page.goto(`./?lang=${lang}`);
    await waitReady(page);
    const o = await overflow(page);
    expect(o.scrollWidth).toBeLessThanOrEqual(o.innerWidth);
    const canvas = await boxOf(page, 'canvas.linkage-canvas');
    // The canvas spans the viewport less the page padding and its card border (at most 16 px each side).
    expect(canvas.right - canvas.left).toBeGreaterThanOrEqual(o.innerWidth - 32);
    expect(canvas.right - canvas.left).toBeLessThanOrEqual(o.innerWidth);
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toBeVisible();
    await expect(page.getByRole('slider', { name: /^θ2/ })).toBeVisible();
    const play = page.getByRole('button', { name: lang === 'en' ? 'Play' : '播放' });
    await expect(play).toBeVisible();
    // The header: each tab name on one line, no header child wider than the viewport.
    const tabs = page.getByRole('tab');
    for (let i = 0; i < (await tabs.count()); i++) {
      const lines = await tabs.nth(i).evaluate((el) => {
        const cs = getComputedStyle(el);
        const lineHeight = parseFloat(cs.lineHeight) || parseFloat(cs.fontSize) * 1.4;
        const inner = el.clientHeight - parseFloat(cs.paddingTop) - parseFloat(cs.paddingBottom);
        return Math.round(inner / lineHeight);
      });
      expect(lines).toBe(1);
    }
    const header = await boxOf(page, 'header');
    expect(header.right).toBeLessThanOrEqual(o.innerWidth + 1);
    await page.screenshot({ path: artifact(`screen-phone-${lang}.png`), fullPage: true });
    await context.close();
  });
}

for (const size of [
  { width: 1280, height: 800, name: 'laptop' },
  { width: 820, height: 1180, name: 'tablet' },
]) {
  test(`a ${size.width}x${size.height} ${size.name} shows every label in full`, async ({ browser }) => {
    const context = await browser.newContext({ viewport: { width: size.width, height: size.height } });
    const page = await context.newPage();
    await page.goto('./');
    await waitReady(page);
    const o = await overflow(page);
    expect(o.scrollWidth).toBeLessThanOrEqual(o.innerWidth);
    // No control label is cut by an ellipsis: its text fits its box.
    const clipped = await page.evaluate(() =>
      [...document.querySelectorAll<HTMLElement>('label, .section-title, .segmented-item span, .btn, .page-tab')]
        .filter((el) => el.offsetParent !== null && el.scrollWidth > el.clientWidth + 1)
        .map((el) => el.textContent),
    );
    expect(clipped).toEqual([]);
    await page.screenshot({ path: artifact(`screen-${size.name}.png`), fullPage: true });
    await context.close();
  });
}

const HOST = `${ORIGIN}/e2e-course/screens.html`;
const EMBED_SRC = `${ORIGIN}/embed.html?r1=6&r2=2&r3=5&r4=5&t2=45&panels=controls,plots`;

for (const frame of [
  { width: 760, height: 520 },
  { width: 600, height: 450 },
]) {
  test(`the embed in a ${frame.width}x${frame.height} frame shows the linkage, θ2, Play and the branch unscrolled`, async ({
    page,
  }) => {
    await page.setViewportSize({ width: frame.width + 80, height: frame.height + 80 });
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
    const o = await overflow(f);
    expect(o.innerWidth).toBe(frame.width);
    expect(o.scrollX).toBe(0);
    expect(o.scrollY).toBe(0);
    expect(o.scrollWidth).toBeLessThanOrEqual(o.innerWidth);
    const need = {
      canvas: 'canvas.linkage-canvas',
      theta2Field: 'input.numctl-field[id$="-field"]',
      play: 'button.play-btn',
      branch: '.segmented',
    };
    const theta2 = f.getByRole('textbox', { name: /^θ2/ });
    const theta2Box = await theta2.evaluate((el) => {
      const r = el.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    });
    expect(inside(theta2Box, o.innerWidth, o.innerHeight), `θ2 field ${JSON.stringify(theta2Box)}`).toBe(true);
    const slider = await f.getByRole('slider', { name: /^θ2/ }).evaluate((el) => {
      const r = el.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    });
    expect(inside(slider, o.innerWidth, o.innerHeight), `θ2 slider ${JSON.stringify(slider)}`).toBe(true);
    for (const [name, sel] of Object.entries({ canvas: need.canvas, play: need.play })) {
      const b = await boxOf(f, sel);
      expect(inside(b, o.innerWidth, o.innerHeight), `${name} ${JSON.stringify(b)}`).toBe(true);
    }
    const branch = await f.getByRole('group', { name: 'Branch' }).evaluate((el) => {
      const r = el.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    });
    expect(inside(branch, o.innerWidth, o.innerHeight), `branch ${JSON.stringify(branch)}`).toBe(true);
    const canvas = await boxOf(f, need.canvas);
    // The linkage gets a real share of the frame, not a sliver.
    expect((canvas.right - canvas.left) * (canvas.bottom - canvas.top)).toBeGreaterThan(
      0.25 * o.innerWidth * o.innerHeight,
    );
    await page.screenshot({ path: artifact(`screen-embed-${frame.width}x${frame.height}.png`) });
  });
}
