import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { exportChart, specDrawing } from '../../../src/shared/charts/exportChart';
import { angleSpec } from '../../../src/shared/charts/theta2Chart';
import { transmissionSpec } from '../../../src/shared/charts/transmissionChart';
import { FakeDocument, installFakeSvgDom } from './fakeSvgDom';

let uninstall = () => {};
beforeAll(() => {
  uninstall = installFakeSvgDom();
});
afterAll(() => uninstall());

const theta2Deg = Array.from({ length: 73 }, (_, i) => i * 5);
const data = { theta2Deg, series: [{ label: 'θ3', color: '#0a0', valuesDeg: theta2Deg.map((t) => 20 + t / 10) }] };
const TEXT = { title: 'θ3 against θ2', xLabel: 'θ2 (°)', yLabel: 'θ3 (°)' };

/** The attributes of the first element with this tag and class in SVG text. */
function attrsOf(svg: string, tag: string, cls: string): Record<string, string> {
  const m = new RegExp(`<${tag} class="${cls}"([^>]*)>`).exec(svg);
  if (!m) throw new Error(`no ${tag}.${cls} in the SVG`);
  return Object.fromEntries([...m[1].matchAll(/([\w-]+)="([^"]*)"/g)].map((a) => [a[1], a[2]]));
}

describe('exportChart', () => {
  it('writes a standalone SVG at the size asked, with the title and the marker at θ2 inside it', () => {
    const svg = exportChart(
      { width: 640, height: 360, draw: specDrawing(angleSpec, TEXT, data, { theta2Deg: 123.4, valuesDeg: [32.34] }) },
      'svg',
    );
    expect(svg.startsWith('<svg')).toBe(true);
    expect(svg).toContain('xmlns="http://www.w3.org/2000/svg"');
    const root = attrsOf(svg.replace('<svg', '<svg class="root"'), 'svg', 'root');
    expect([root.width, root.height, root.viewBox]).toEqual(['640', '360', '0 0 640 360']);
    expect(svg).toContain('>θ3 against θ2</text>');
    expect(svg).toContain('>θ2 (°)</text>');
    // Plot 640 - 50 - 14 = 576 px wide for 360 degrees: theta2 = 123.4 sits at 197.44 px.
    expect(Number(attrsOf(svg, 'line', 'mline').x1)).toBeCloseTo((123.4 * 576) / 360, 9);
    expect(attrsOf(svg, 'g', 'plot').transform).toBe('translate(50,46)');
  });

  it('draws any spec: the transmission chart with its band', () => {
    const band = { loDeg: 40, hiDeg: 140 };
    const text = { ...TEXT, title: 'Transmission angle', legendMu: 'μ', legendOutside: 'outside', legendBand: 'band' };
    const mu = { theta2Deg, muDeg: theta2Deg.map((t) => 90 + 70 * Math.cos((t * Math.PI) / 180)) };
    const svg = exportChart(
      {
        width: 600,
        height: 340,
        draw: specDrawing(
          transmissionSpec(() => band),
          text,
          mu,
          null,
        ),
      },
      'svg',
    );
    expect(svg).toContain('>Transmission angle</text>');
    expect(attrsOf(svg, 'rect', 'mu-band')['data-lo']).toBe('40');
    expect(svg).toContain('class="mu-outside"');
    expect(attrsOf(svg, 'g', 'marker').display).toBe('none');
  });

  it('draws into a fresh detached SVG each time', () => {
    const drawn: SVGSVGElement[] = [];
    const chart = { width: 10, height: 10, draw: (svg: SVGSVGElement) => void drawn.push(svg) };
    exportChart(chart, 'svg');
    exportChart(chart, 'svg');
    expect(drawn[0]).not.toBe(drawn[1]);
    expect((globalThis as { document?: unknown }).document).toBeInstanceOf(FakeDocument);
  });
});
