import type { Browser, BrowserContext, Locator, Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { artifact, waitReady } from './helpers';

// The phone layout (issue 19): the canvas on top, the phone bar fixed at the bottom within a thumb's reach (Play,
// step, θ2, the branch), every other control in a sheet the bar opens, and a first-use hint that the joints can
// be dragged. Driven by touch (hasTouch, isMobile) at 390x844 and 360x740, in English and Traditional Chinese.

/** The words the specs look for, per language. */
const WORDS = {
  en: {
    play: 'Play',
    pause: 'Pause',
    stepForward: 'Step forward',
    stepBack: 'Step back',
    crossed: 'Crossed',
    bar: 'Play and input angle',
    allControls: 'All controls',
    controls: 'Controls',
    gotIt: 'Got it',
    hint: /drag joint A/,
    velocities: 'Velocities',
    anglePlots: 'Angle plots',
    velocityPlots: 'Velocity plots',
  },
  'zh-TW': {
    play: '播放',
    pause: '暫停',
    stepForward: '前進一步',
    stepBack: '後退一步',
    crossed: '交叉型',
    bar: '播放與輸入角',
    allControls: '全部控制項',
    controls: '控制項',
    gotIt: '知道了',
    hint: /拖曳 A 點/,
    velocities: '角速度',
    anglePlots: '角度圖',
    velocityPlots: '角速度圖',
  },
} as const;

type Lang = keyof typeof WORDS;

const PHONES = [
  { width: 390, height: 844 },
  { width: 360, height: 740 },
] as const;

/** A phone's browser context: touch, a mobile viewport, the language's locale. */
async function phoneContext(
  browser: Browser,
  size: { width: number; height: number },
  lang: Lang,
): Promise<BrowserContext> {
  return browser.newContext({
    viewport: size,
    hasTouch: true,
    isMobile: true,
    deviceScaleFactor: 2,
    locale: lang === 'en' ? 'en-US' : 'zh-TW',
  });
}

/** Opens the app in a language and waits until it has drawn. */
async function openApp(page: Page, lang: Lang, query = ''): Promise<void> {
  await page.goto(`./?lang=${lang}${query}`);
  await waitReady(page);
}

/** A box in viewport pixels. */
async function boxOf(locator: Locator) {
  return locator.evaluate((el) => {
    const r = el.getBoundingClientRect();
    return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
  });
}

/** One finger from `from` to `to` in steps (page pixels), through the Chrome DevTools protocol. */
async function touchDrag(page: Page, from: { x: number; y: number }, to: { x: number; y: number }): Promise<void> {
  const cdp = await page.context().newCDPSession(page);
  const at = (f: number) => [{ x: from.x + (to.x - from.x) * f, y: from.y + (to.y - from.y) * f, id: 1 }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
  for (let i = 1; i <= 12; i++)
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(i / 12) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await cdp.detach();
}

/** θ2 as the bar's field shows it. */
async function theta2(page: Page): Promise<number> {
  return Number(await page.getByRole('textbox', { name: /^θ2/ }).inputValue());
}

for (const lang of ['en', 'zh-TW'] as const) {
  const w = WORDS[lang];
  for (const size of PHONES) {
    test(`the phone bar at ${size.width}x${size.height} (${lang}): Play, Step, θ2 and the branch by touch, in reach while the page scrolls`, async ({
      browser,
    }) => {
      const context = await phoneContext(browser, size, lang);
      const page = await context.newPage();
      await openApp(page, lang);
      const bar = page.getByRole('region', { name: w.bar });
      await expect(bar).toBeVisible();
      const canvas = await boxOf(page.locator('canvas.linkage-canvas'));
      // The canvas on top, the bar at the bottom of the viewport, below the canvas.
      expect(canvas.top).toBeLessThan(size.height / 3);
      const b0 = await boxOf(bar);
      expect(b0.bottom).toBeLessThanOrEqual(size.height + 1);
      expect(b0.top).toBeGreaterThan(canvas.bottom - 1);
      expect(b0.left).toBeGreaterThanOrEqual(0);
      expect(b0.right).toBeLessThanOrEqual(size.width + 1);
      // One Play and one θ2 on the page: the bar's (the sheet leaves them out).
      await expect(page.getByRole('button', { name: w.play })).toHaveCount(1);
      await expect(page.getByRole('slider', { name: /^θ2/ })).toHaveCount(1);
      await page.screenshot({ path: artifact(`phone-${size.width}x${size.height}-${lang}.png`) });

      // Play and Pause by tapping.
      await bar.getByRole('button', { name: w.play }).tap();
      await expect(bar.getByRole('button', { name: w.pause })).toBeVisible();
      await bar.getByRole('button', { name: w.pause }).tap();
      await expect(bar.getByRole('button', { name: w.play })).toBeVisible();

      // Step forward and back move θ2 by one step (360 / 360 samples = 1°) from a round value.
      await openApp(page, lang, '&t2=45');
      await bar.getByRole('button', { name: w.stepForward }).tap();
      await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('46');
      await bar.getByRole('button', { name: w.stepBack }).tap();
      await bar.getByRole('button', { name: w.stepBack }).tap();
      await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('44');

      // The θ2 slider follows a finger: from its thumb at 44° to three quarters of its track.
      const slider = page.getByRole('slider', { name: /^θ2/ });
      const s = await slider.boundingBox();
      if (!s) throw new Error('no θ2 slider');
      // Chromium's thumb is 16 px wide: its centre runs from 8 px in to 8 px short of the track's ends.
      const thumbX = (deg: number) => s.x + 8 + ((s.width - 16) * deg) / 360;
      await touchDrag(page, { x: thumbX(44), y: s.y + s.height / 2 }, { x: thumbX(270), y: s.y + s.height / 2 });
      await expect.poll(() => theta2(page)).toBeGreaterThan(260);
      expect(Math.abs((await theta2(page)) - 270)).toBeLessThan(6);

      // The branch by tapping its other choice.
      await bar.getByRole('radio', { name: w.crossed }).tap();
      await expect(bar.getByRole('radio', { name: w.crossed })).toBeChecked();

      // Scrolled to the end, the bar is still in the viewport and still works, and nothing ends under it.
      await page.evaluate(() => window.scrollTo(0, document.documentElement.scrollHeight));
      await expect.poll(() => page.evaluate(() => window.scrollY)).toBeGreaterThan(400);
      const b1 = await boxOf(bar);
      expect(b1.top).toBeGreaterThanOrEqual(0);
      expect(b1.bottom).toBeLessThanOrEqual(size.height + 1);
      const lastCard = await boxOf(page.locator('.rightbar > *').last());
      expect(lastCard.bottom).toBeLessThanOrEqual(b1.top + 1);
      await bar.getByRole('button', { name: w.play }).tap();
      await expect(bar.getByRole('button', { name: w.pause })).toBeVisible();
      await bar.getByRole('button', { name: w.pause }).tap();
      await page.screenshot({ path: artifact(`phone-${size.width}x${size.height}-${lang}-scrolled.png`) });
      await context.close();
    });
  }

  test(`the phone's sheet holds every other control, by touch (${lang})`, async ({ browser }) => {
    const context = await phoneContext(browser, PHONES[1], lang);
    const page = await context.newPage();
    await openApp(page, lang);
    const toggle = page.getByRole('button', { name: w.allControls });
    await expect(toggle).toHaveAttribute('aria-expanded', 'false');
    // Closed, the sheet's controls are not rendered at all.
    await expect(page.getByRole('textbox', { name: /^r3/ })).toHaveCount(0);
    await toggle.tap();
    await expect(toggle).toHaveAttribute('aria-expanded', 'true');
    const sheet = page.getByRole('complementary', { name: w.controls, exact: true });
    await expect(sheet).toBeVisible();
    // Every control of the sidebar but the bar's own (θ2, branch, Play, step) is in the sheet and reachable.
    const reachable = [
      sheet.getByRole('combobox').first(),
      sheet.getByRole('textbox', { name: /^r1/ }),
      sheet.getByRole('textbox', { name: /^r4/ }),
      sheet.getByRole('slider', { name: /^r2/ }),
      sheet.getByRole('textbox', { name: /^ω2/ }),
      sheet.getByRole('textbox', { name: /^α2/ }),
      sheet.getByRole('checkbox').first(),
      sheet.getByRole('checkbox').last(),
    ];
    for (const control of reachable) {
      await control.scrollIntoViewIfNeeded();
      await expect(control).toBeInViewport();
    }
    await expect(sheet.getByRole('button', { name: w.play })).toHaveCount(0);
    await expect(sheet.getByRole('slider', { name: /^θ2/ })).toHaveCount(0);
    // A length typed in the sheet changes the linkage while the canvas stays in view above it.
    const r3 = sheet.getByRole('textbox', { name: /^r3/ });
    await r3.fill('5.5');
    await expect(page.locator('canvas.linkage-canvas')).toBeInViewport();
    await expect.poll(() => new URL(page.url()).searchParams.get('r3')).toBe('5.5');
    await page.screenshot({ path: artifact(`phone-sheet-${lang}.png`) });
    await toggle.tap();
    await expect(toggle).toHaveAttribute('aria-expanded', 'false');
    await expect(sheet).toHaveCount(0);
    await context.close();
  });

  test(`dragging joint A on the canvas by touch turns the crank (${lang})`, async ({ browser }) => {
    const context = await phoneContext(browser, PHONES[0], lang);
    const page = await context.newPage();
    await openApp(page, lang);
    const canvas = page.locator('canvas.linkage-canvas');
    const box = await canvas.boundingBox();
    if (!box) throw new Error('no canvas');
    const at = async (name: 'o2' | 'a') => {
      const [x, y] = (await canvas.getAttribute(`data-${name}`))!.split(',').map(Number);
      return { x: box.x + x, y: box.y + y };
    };
    const o2 = await at('o2');
    const a = await at('a');
    const r = Math.hypot(a.x - o2.x, a.y - o2.y);
    const to = { x: o2.x + r * Math.cos((120 * Math.PI) / 180), y: o2.y - r * Math.sin((120 * Math.PI) / 180) };
    await touchDrag(page, a, to);
    // A pixel at this radius is well under two degrees.
    await expect.poll(() => theta2(page)).toBeGreaterThan(110);
    expect(Math.abs((await theta2(page)) - 120)).toBeLessThan(2);
    await context.close();
  });

  test(`the drag hint shows on first use only, and never in the embed (${lang})`, async ({ browser }) => {
    const context = await phoneContext(browser, PHONES[0], lang);
    const page = await context.newPage();
    await openApp(page, lang);
    const hint = page.getByRole('note').filter({ hasText: w.hint });
    await expect(hint).toBeVisible();
    await page.screenshot({ path: artifact(`phone-hint-${lang}.png`) });
    await hint.getByRole('button', { name: w.gotIt }).tap();
    await expect(hint).toHaveCount(0);
    await page.reload();
    await waitReady(page);
    await expect(page.locator('canvas.linkage-canvas')).toBeVisible();
    await expect(page.getByRole('note').filter({ hasText: w.hint })).toHaveCount(0);
    // A fresh visitor of the embed (its own storage) sees no hint there.
    const embedContext = await phoneContext(browser, PHONES[0], lang);
    const embed = await embedContext.newPage();
    await embed.goto(`./embed.html?lang=${lang}`);
    await waitReady(embed);
    await expect(embed.locator('.drag-hint')).toHaveCount(0);
    await expect(embed.getByRole('region', { name: w.bar })).toHaveCount(0);
    await embedContext.close();
    await context.close();
  });

  test(`on a phone the dead-centre labels keep off the plot legends, and the layout toggle names its plots (${lang})`, async ({
    browser,
  }) => {
    for (const size of PHONES) {
      const context = await phoneContext(browser, size, lang);
      const page = await context.newPage();
      await openApp(page, lang);
      const charts = page.locator('section.plots svg.chart-svg');
      await expect(charts).toHaveCount(2);
      // The θ4 chart (below the fold) is drawn just after the first screen: wait for both legends, so the check
      // below cannot pass on an empty chart.
      await expect(charts.locator('g.legend')).toHaveCount(2);
      // Text boxes as Chromium lays them out with its own fonts.
      const faults = await charts.evaluateAll((svgs) => {
        const out: string[] = [];
        for (const svg of svgs) {
          const legend = [...svg.querySelectorAll('g.legend text')].map((t) => t.getBoundingClientRect());
          for (const mark of svg.querySelectorAll('g.x-mark text')) {
            const m = mark.getBoundingClientRect();
            for (const l of legend)
              if (m.left < l.right && l.left < m.right && m.top < l.bottom && l.top < m.bottom)
                out.push(`${mark.textContent} meets a legend entry`);
          }
        }
        return out;
      });
      expect(faults, `${size.width}x${size.height}`).toEqual([]);
      if (size === PHONES[0])
        await page.locator('section.plots').screenshot({ path: artifact(`phone-plots-${lang}.png`) });
      await context.close();
    }
    const context = await phoneContext(browser, PHONES[0], lang);
    const page = await context.newPage();
    await openApp(page, lang);
    await expect(page.getByRole('group', { name: w.anglePlots })).toBeVisible();
    await page.getByRole('radio', { name: w.velocities }).tap();
    await expect(page.getByRole('group', { name: w.velocityPlots })).toBeVisible();
    await expect(page.getByRole('group', { name: w.anglePlots })).toHaveCount(0);
    await context.close();
  });
}

test('the desktop keeps its sidebar: no phone bar at 1280x800', async ({ page }) => {
  await page.goto('./');
  await waitReady(page);
  await expect(page.getByRole('region', { name: WORDS.en.bar })).toHaveCount(0);
  await expect(page.getByRole('complementary', { name: 'Controls', exact: true })).toBeVisible();
  await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
  await expect(page.getByRole('note').filter({ hasText: WORDS.en.hint })).toHaveCount(0);
  await page.screenshot({ path: artifact('phone-spec-desktop-1280x800.png') });
});
