import { readFileSync, writeFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import { artifact, waitReady } from './helpers';

/** What the browser's own XML parser finds in an SVG file: a parse error, the root's name and every <text>'s content. */
interface SvgFacts {
  parseError: string | null;
  root: string;
  texts: string[];
  width: string | null;
  height: string | null;
}

async function downloadSvg(page: Page, button: string): Promise<{ name: string; text: string }> {
  const [d] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: button, exact: true }).click(),
  ]);
  return { name: d.suggestedFilename(), text: readFileSync(await d.path(), 'utf8') };
}

/** Parses the file with DOMParser as image/svg+xml (strict XML: a bad escape is a parse error). */
async function svgFacts(page: Page, text: string): Promise<SvgFacts> {
  return page.evaluate((src) => {
    const doc = new DOMParser().parseFromString(src, 'image/svg+xml');
    const err = doc.querySelector('parsererror');
    const root = doc.documentElement;
    return {
      parseError: err ? (err.textContent ?? 'parse error') : null,
      root: `${root.namespaceURI} ${root.localName}`,
      texts: [...doc.querySelectorAll('text')].map((t) => t.textContent ?? ''),
      width: root.getAttribute('width'),
      height: root.getAttribute('height'),
    };
  }, text);
}

/** Shows the SVG as an image in the page and saves a screenshot of it as an artefact to look at. */
async function lookAt(page: Page, text: string, name: string): Promise<void> {
  writeFileSync(artifact(name.replace(/\.png$/, '.svg')), text);
  const handle = await page.evaluateHandle(async (src) => {
    const img = document.createElement('img');
    img.src = `data:image/svg+xml;charset=utf-8,${encodeURIComponent(src)}`;
    img.style.cssText = 'position:fixed;left:0;top:0;z-index:99999;background:#fff';
    document.body.appendChild(img);
    await img.decode();
    return img;
  }, text);
  await handle.asElement()?.screenshot({ path: artifact(name) });
  await handle.evaluate((img) => (img as HTMLImageElement).remove());
}

const SVG_NS = 'http://www.w3.org/2000/svg svg';

test.describe('SVG export', () => {
  test('the linkage SVG is the canvas picture with the joint labels as text', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const box = await page.locator('canvas.linkage-canvas').boundingBox();
    if (!box) throw new Error('no canvas');
    const file = await downloadSvg(page, 'Export linkage SVG');
    expect(file.name).toBe('fourbar_6-2-5-5_open_theta2-45_linkage.svg');
    const svg = await svgFacts(page, file.text);
    expect(svg.parseError).toBeNull();
    expect(svg.root).toBe(SVG_NS);
    expect(Math.abs(Number(svg.width) - box.width)).toBeLessThanOrEqual(1);
    for (const label of ['O2', 'O4', 'A', 'B', 'P']) expect(svg.texts).toContain(label);
    // The angle labels are text too (θ2 = 45.0° at the default state).
    expect(svg.texts.some((s) => s.includes('45.0°'))).toBe(true);
    await lookAt(page, file.text, 'svg-linkage.png');
  });

  test('the grid label and an off-screen instant centre carry the length unit', async ({ page }) => {
    // Zoomed in 4x on the default linkage: the instant centres fall outside the view and are marked at its edge.
    await page.goto('./?lu=mm&ic=1&z=4');
    await waitReady(page);
    const svg = await svgFacts(page, (await downloadSvg(page, 'Export linkage SVG')).text);
    expect(svg.parseError).toBeNull();
    expect(svg.texts.filter((s) => /^grid [\d.]+ mm$/.test(s)).length).toBeGreaterThan(0);
    expect(svg.texts.filter((s) => /^I(13|24) \(−?[\d.]+, −?[\d.]+\) mm$/.test(s)).length).toBeGreaterThan(0);
    await page.goto('./?lu=in&ic=1&z=4');
    await waitReady(page);
    const inches = await svgFacts(page, (await downloadSvg(page, 'Export linkage SVG')).text);
    expect(inches.texts.filter((s) => /^grid [\d.]+ in$/.test(s)).length).toBeGreaterThan(0);
  });

  test('each plot SVG parses and carries its title and axis label as text', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const plots: [string, string, string][] = [
      ['Export θ3 plot SVG', 'theta3-vs-theta2', 'θ3 against θ2'],
      ['Export θ4 plot SVG', 'theta4-vs-theta2', 'θ4 against θ2'],
      ['Export θ3 and θ4 plot SVG', 'theta3-theta4-vs-theta2', 'θ3 and θ4 against θ2'],
      ['Export ω3 and ω4 plot SVG', 'omega3-omega4-vs-theta2', 'ω3 and ω4 against θ2'],
      ['Export α3 and α4 plot SVG', 'alpha3-alpha4-vs-theta2', 'α3 and α4 against θ2'],
    ];
    for (const [button, stem, title] of plots) {
      const file = await downloadSvg(page, button);
      expect(file.name).toBe(`fourbar_6-2-5-5_open_${stem}.svg`);
      const svg = await svgFacts(page, file.text);
      expect(svg.parseError).toBeNull();
      expect(svg.root).toBe(SVG_NS);
      expect(svg.texts).toContain(title);
      expect(svg.texts).toContain('θ2 (°)');
      // Styling is attributes, so the file looks the same outside the page.
      expect(file.text).toMatch(/font-family="system-ui/);
    }
    const conv = await downloadSvg(page, 'Export NR convergence plot SVG');
    expect(conv.name).toBe('fourbar_6-2-5-5_open_theta2-45_nr-convergence.svg');
    const svg = await svgFacts(page, conv.text);
    expect(svg.parseError).toBeNull();
    expect(svg.texts.some((s) => s.startsWith('NR convergence at θ2 = 45'))).toBe(true);
    // Each exported plot carries its own marker at θ2 = 45° (the page draws its marker over the chart instead):
    // the line at 45/360 of the plot width and a dot of each quantity's colour on it.
    const markerOf = (text: string) =>
      page.evaluate((svgText) => {
        const doc = new DOMParser().parseFromString(svgText, 'image/svg+xml');
        const line = doc.querySelector('g.plot > g.marker > line.mline');
        const domain = doc.querySelector('g.axis-x path.domain')?.getAttribute('d') ?? '';
        const width = Number(/H([\d.]+)/.exec(domain)?.[1]) - 0.5;
        const circles = [...doc.querySelectorAll('g.plot > g.marker > circle')];
        return {
          x: Number(line?.getAttribute('x1')) / width,
          fills: circles.map((c) => c.getAttribute('fill')),
          cx: circles.map((c) => Number(c.getAttribute('cx')) / width),
        };
      }, text);
    const both = await downloadSvg(page, 'Export θ3 and θ4 plot SVG');
    for (const button of ['Export θ3 and θ4 plot SVG', 'Export ω3 and ω4 plot SVG', 'Export α3 and α4 plot SVG']) {
      const marker = await markerOf(
        button === 'Export θ3 and θ4 plot SVG' ? both.text : (await downloadSvg(page, button)).text,
      );
      expect(marker.x, button).toBeCloseTo(45 / 360, 3);
      expect(
        marker.cx.map((x) => Math.round(x * 3600)),
        button,
      ).toEqual([450, 450]);
      expect(new Set(marker.fills).size, button).toBe(2);
    }
    await lookAt(page, both.text, 'svg-angles.png');
  });

  test('the solver lab exports its diagram as SVG', async ({ page }) => {
    await page.goto('./?page=lab');
    await expect(page.getByTestId('solver-lab')).toHaveAttribute('data-ready', 'true', { timeout: 90_000 });
    const file = await downloadSvg(page, 'Export diagram SVG');
    expect(file.name).toBe('fourbar_6-2-5-5_open_work-precision_step1.svg');
    const svg = await svgFacts(page, file.text);
    expect(svg.parseError).toBeNull();
    expect(svg.texts).toContain('Work-precision diagram');
  });
});
