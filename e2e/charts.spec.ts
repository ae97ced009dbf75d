import type { Locator, Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { artifact, waitReady } from './helpers';

/** The marker line's colour (the theme's chart marker), as the screen shows it. */
const MARKER_COLOR = '#e2590c';

/** The number of marker dots a live chart shows (its marker box's data-dots). */
async function markerDots(chart: Locator): Promise<number> {
  return chart.evaluate((svg) => {
    const box = svg.parentElement?.querySelector<HTMLElement>('.chart-marker');
    return (JSON.parse(box?.dataset.dots ?? '[]') as unknown[]).length;
  });
}

/** What screenOf reads off the screen: each point's [r, g, b], and the x of every pixel on a row within 40 of a colour. */
interface ScreenRead {
  pixels: Array<[number, number, number]>;
  rowMatches: number[];
}

/**
 * The chart's box as the screen shows it: an element screenshot (what the compositor drew, marker layers included)
 * decoded in the page, read at CSS-pixel points of the box, and along one row (CSS-pixel y) for pixels near a colour.
 */
async function screenOf(
  chart: Locator,
  points: Array<[number, number]>,
  row: { y: number; rgb: [number, number, number] } | null = null,
): Promise<ScreenRead> {
  const png = await chart.locator('xpath=..').screenshot();
  return chart.evaluate(
    async (svg: SVGSVGElement, { b64, at, row }) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const canvas = document.createElement('canvas');
      canvas.width = img.naturalWidth;
      canvas.height = img.naturalHeight;
      const ctx = canvas.getContext('2d')!;
      ctx.drawImage(img, 0, 0);
      const k = img.naturalWidth / svg.parentElement!.getBoundingClientRect().width;
      const pixels = at.map(([x, y]) => {
        const [r, g, b] = ctx.getImageData(Math.floor(x * k), Math.floor(y * k), 1, 1).data;
        return [r, g, b] as [number, number, number];
      });
      const rowMatches: number[] = [];
      if (row) {
        const d = ctx.getImageData(0, Math.round(row.y * k), canvas.width, 1).data;
        for (let i = 0; i < canvas.width; i++) {
          const off =
            Math.abs(d[4 * i] - row.rgb[0]) + Math.abs(d[4 * i + 1] - row.rgb[1]) + Math.abs(d[4 * i + 2] - row.rgb[2]);
          if (off < 40) rowMatches.push((i + 0.5) / k);
        }
      }
      return { pixels, rowMatches };
    },
    { b64: png.toString('base64'), at: points, row },
  );
}

/** '#rrggbb' as [r, g, b]. */
function rgbOf(color: string): [number, number, number] {
  return [1, 3, 5].map((i) => parseInt(color.slice(i, i + 2), 16)) as [number, number, number];
}

/**
 * For each marker dot of a chart: its distance (px) to the solid path of its own colour at the dot's x, and to the
 * nearest other path, and whether the screen shows the dot's colour at its centre.
 */
async function markerOffsets(chart: Locator): Promise<Array<{ own: number; other: number; painted: boolean }>> {
  const placed = await chart.evaluate((svg: SVGSVGElement) => {
    const paths = [...svg.querySelectorAll<SVGPathElement>('g.lines path')];
    // y of a path at x: the path's own geometry, bisected along its length within each monotone-in-x piece.
    const yAt = (p: SVGPathElement, x: number): number[] => {
      const n = 2000;
      const len = p.getTotalLength();
      const ys: number[] = [];
      let prev = p.getPointAtLength(0);
      for (let i = 1; i <= n; i++) {
        const q = p.getPointAtLength((len * i) / n);
        if ((prev.x - x) * (q.x - x) <= 0 && q.x !== prev.x && Math.abs(q.x - prev.x) < 5) {
          ys.push(prev.y + ((x - prev.x) / (q.x - prev.x)) * (q.y - prev.y));
        }
        prev = q;
      }
      return ys;
    };
    // The live chart draws its marker over the SVG and states the dots' plot-pixel centres on its box.
    const box = svg.parentElement?.querySelector<HTMLElement>('.chart-marker');
    const dots = JSON.parse(box?.dataset.dots ?? '[]') as Array<{ cx: number; cy: number; color: string }>;
    const [left, top] = (
      /translate\(([-\d.]+),([-\d.]+)\)/.exec(svg.querySelector('g.plot')?.getAttribute('transform') ?? '') ?? []
    )
      .slice(1)
      .map(Number);
    return dots.map(({ cx, cy, color: fill }) => {
      const dist = (p: SVGPathElement) => Math.min(Infinity, ...yAt(p, cx).map((y) => Math.abs(y - cy)));
      const own = paths.filter((p) => p.getAttribute('stroke') === fill && !p.getAttribute('stroke-dasharray'));
      const others = paths.filter((p) => !own.includes(p));
      return {
        own: own.length === 1 ? dist(own[0]) : Infinity,
        other: Math.min(Infinity, ...others.map(dist)),
        at: [left + cx, top + cy] as [number, number],
        fill,
      };
    });
  });
  // The screen really shows each dot there: its pixel at the dot's centre is the dot's colour.
  const shown = (
    await screenOf(
      chart,
      placed.map((d) => d.at),
    )
  ).pixels;
  return placed.map((d, i) => {
    const want = rgbOf(d.fill);
    const got = shown[i];
    return {
      own: d.own,
      other: d.other,
      painted: Math.abs(got[0] - want[0]) + Math.abs(got[1] - want[1]) + Math.abs(got[2] - want[2]) < 30,
    };
  });
}

/** Mutation counts of one watched group: batches of changes, and batches that left its markup as it was (a redundant redraw). */
interface MutationCount {
  batches: number;
  redundant: number;
}

/** Starts counting DOM mutation batches inside each group selector of a chart; read them back with mutationCounts. */
async function watchMutations(chart: Locator, selectors: string[]): Promise<void> {
  await chart.evaluate((svg: SVGSVGElement, sels: string[]) => {
    const w = window as unknown as { __mut?: Map<Element, Record<string, MutationCount>> };
    w.__mut ??= new Map();
    const counts: Record<string, MutationCount> = {};
    w.__mut.set(svg, counts);
    for (const sel of sels) {
      const el = svg.querySelector(sel);
      if (!el) throw new Error(`no ${sel}`);
      const c = (counts[sel] = { batches: 0, redundant: 0 });
      let markup = el.innerHTML;
      new MutationObserver(() => {
        c.batches++;
        if (el.innerHTML === markup) c.redundant++;
        markup = el.innerHTML;
      }).observe(el, { subtree: true, childList: true, attributes: true, characterData: true });
    }
  }, selectors);
}

async function mutationCounts(chart: Locator): Promise<Record<string, MutationCount>> {
  return chart.evaluate((svg: SVGSVGElement) => {
    const w = window as unknown as { __mut: Map<Element, Record<string, MutationCount>> };
    return { ...w.__mut.get(svg)! };
  });
}

/** Tick label boxes of one axis group, in page pixels. */
async function tickBoxes(chart: Locator, axis: string): Promise<Array<{ left: number; right: number }>> {
  return chart.evaluate((svg: SVGSVGElement, sel: string) => {
    return [...svg.querySelectorAll<SVGTextElement>(`${sel} .tick text`)]
      .filter((t) => t.textContent)
      .map((t) => {
        const r = t.getBoundingClientRect();
        return { left: r.left, right: r.right };
      });
  }, axis);
}

async function stepSlider(page: Page, name: RegExp, key: string, times: number): Promise<void> {
  await page.getByRole('slider', { name }).focus();
  for (let i = 0; i < times; i++) await page.keyboard.press(key);
}

test.describe('the angle and convergence charts', () => {
  test('each marker dot lies on its own curve, in separate and combined plots', async ({ page }) => {
    await page.goto('./?ghost=1');
    await waitReady(page);
    const t3 = page.getByRole('img', { name: 'θ3 against θ2' });
    const t4 = page.getByRole('img', { name: 'θ4 against θ2' });
    for (const chart of [t3, t4]) {
      await expect.poll(() => markerDots(chart)).toBe(1);
      for (const d of await markerOffsets(chart)) {
        expect(d.own).toBeLessThan(1.5);
        expect(d.other).toBeGreaterThan(5);
        expect(d.painted).toBe(true);
      }
    }
    await page.getByRole('radio', { name: 'Together' }).check();
    const both = page.getByRole('img', { name: 'θ3 and θ4 against θ2' });
    await expect.poll(() => markerDots(both)).toBe(2);
    const offsets = await markerOffsets(both);
    expect(offsets).toHaveLength(2);
    for (const d of offsets) {
      expect(d.own).toBeLessThan(1.5);
      expect(d.other).toBeGreaterThan(5);
      expect(d.painted).toBe(true);
    }
  });

  for (const br of ['open', 'crossed'] as const) {
    test(`with the other branch hidden, the one curve drawn is the ${br} branch the marker lies on`, async ({
      page,
    }) => {
      await page.goto(`./?br=${br}&ghost=0`);
      await waitReady(page);
      for (const name of ['θ3 against θ2', 'θ4 against θ2']) {
        const chart = page.getByRole('img', { name });
        await expect(chart.locator('g.lines path')).toHaveCount(1);
        await expect.poll(() => markerDots(chart)).toBe(1);
        for (const d of await markerOffsets(chart)) expect(d.own, `${br} ${name}`).toBeLessThan(1.5);
      }
    });
  }

  test('r3 steps redraw the curves but not the theta2 axis', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const t4 = page.getByRole('img', { name: 'θ4 against θ2' });
    await watchMutations(t4, ['g.axis-x', 'g.grid-x', 'g.axis-y', 'g.lines']);
    const before = await t4.locator('g.lines path').first().getAttribute('d');
    await stepSlider(page, /^r3/, 'ArrowRight', 5);
    await expect(page.getByRole('textbox', { name: /^r3/ })).toHaveValue('5.05');
    await expect.poll(() => t4.locator('g.lines path').first().getAttribute('d')).not.toBe(before);
    const counts = await mutationCounts(t4);
    expect(counts['g.lines'].batches).toBeGreaterThan(0);
    expect(counts['g.axis-x'].batches).toBe(0);
    expect(counts['g.grid-x'].batches).toBe(0);
    expect(counts['g.axis-y'].redundant).toBe(0);
  });

  test('theta2 steps redraw the convergence runs, and its axes only when their domain changes', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const conv = page.getByRole('img', { name: /^NR convergence at θ2/ });
    await watchMutations(conv, ['g.axis-x', 'g.axis-y', 'g.lines']);
    const runBefore = await conv.locator('g.lines path').last().getAttribute('d');
    await stepSlider(page, /^θ2/, 'ArrowRight', 6);
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('51');
    await expect(conv).toHaveAttribute('aria-label', /51/);
    await expect.poll(() => conv.locator('g.lines path').last().getAttribute('d')).not.toBe(runBefore);
    const counts = await mutationCounts(conv);
    expect(counts['g.lines'].batches).toBeGreaterThan(0);
    // An axis may change with the residual range, but is never rewritten with what it already shows.
    expect(counts['g.axis-x'].redundant).toBe(0);
    expect(counts['g.axis-y'].redundant).toBe(0);
  });

  for (const [w, h] of [
    [1280, 800],
    [390, 844],
  ] as const) {
    test(`tick labels never run together at ${w}x${h}`, async ({ page }) => {
      await page.setViewportSize({ width: w, height: h });
      await page.goto('./');
      await waitReady(page);
      const charts = [
        page.getByRole('img', { name: 'θ3 against θ2' }),
        page.getByRole('img', { name: 'θ4 against θ2' }),
        page.getByRole('img', { name: /^NR convergence at θ2/ }),
      ];
      for (const chart of charts) {
        await chart.scrollIntoViewIfNeeded();
        const boxes = await tickBoxes(chart, 'g.axis-x');
        expect(boxes.length).toBeGreaterThanOrEqual(2);
        for (let i = 1; i < boxes.length; i++) expect(boxes[i].left - boxes[i - 1].right).toBeGreaterThan(4);
      }
      await page
        .locator('section.plots, .plots-panel')
        .first()
        .screenshot({ path: artifact(`plots-${w}x${h}.png`) });
    });
  }
});

test.describe('chart markers on a high-density screen', () => {
  test.use({ deviceScaleFactor: 2 });

  test('at device pixel ratio 2 each marker is painted where its θ2 and its curves are, on every θ2 chart', async ({
    page,
  }) => {
    for (const [query, name] of [
      ['t2=200', 'θ3 against θ2'],
      ['t2=200&plot=vel', 'ω4 against θ2'],
    ]) {
      await page.goto(`./?${query}`);
      await waitReady(page);
      const chart = page.getByRole('img', { name });
      await expect.poll(() => markerDots(chart)).toBeGreaterThan(0);
      for (const d of await markerOffsets(chart)) {
        expect(d.own).toBeLessThan(1.5);
        expect(d.painted).toBe(true);
      }
      // The marker line is painted at θ2 = 200° on the chart's x scale, not offset by the plot's left margin: the
      // screen's pixels of the marker's colour on a row just under the plot's top.
      const { left, top, x } = await chart.evaluate((svg: SVGSVGElement) => {
        const box = svg.parentElement?.querySelector<HTMLElement>('.chart-marker');
        const [l, t] = (
          /translate\(([-\d.]+),([-\d.]+)\)/.exec(svg.querySelector('g.plot')?.getAttribute('transform') ?? '') ?? []
        )
          .slice(1)
          .map(Number);
        return { left: l, top: t, x: Number(box?.dataset.x) };
      });
      const painted = (await screenOf(chart, [], { y: top + 4, rgb: rgbOf(MARKER_COLOR) })).rowMatches;
      const offset =
        painted.length === 0 ? Infinity : Math.abs((painted[0] + painted[painted.length - 1]) / 2 - (left + x));
      expect(offset).toBeLessThan(1.5);
    }
  });
});
