import { describe, expect, it } from 'vitest';
import { createTransmissionChart } from '../../../src/shared/charts/transmissionChart';
import { COLORS } from '../../../src/shared/theme/tokens';
import { fakeSvg } from './fakeSvgDom';

const deg = (r: number) => (r * 180) / Math.PI;
const rad = (d: number) => (d * Math.PI) / 180;
/** mu of the report's 6-2-5-5 from the law of cosines (s^2 = 40 - 24 cos theta2, cos mu = (50 - s^2) / 50). */
const muReport = (t2Deg: number) => deg(Math.acos((50 - (40 - 24 * Math.cos(rad(t2Deg)))) / 50));
/** theta2 in [0, 180] where the report's mu equals muDeg (the inverse of muReport). */
const theta2AtMu = (muDeg: number) => deg(Math.acos((40 - (50 - 50 * Math.cos(rad(muDeg)))) / 24));

const TEXT = {
  title: 'Transmission angle',
  xLabel: 'θ2 (°)',
  yLabel: 'μ (°)',
  legendMu: 'μ',
  legendOutside: 'out',
  legendBand: 'band',
};
const W = 614;
const H = 346;

/** The report's mu at 0.5 degree steps, drawn in a 614 x 346 chart (plot 550 x 260) with a 60-100 degree band. */
function drawn() {
  const svg = fakeSvg();
  const chart = createTransmissionChart(svg, { ...TEXT, width: W, height: H, band: { loDeg: 60, hiDeg: 100 } });
  const theta2Deg = Array.from({ length: 721 }, (_, i) => i / 2);
  chart.update({ theta2Deg, muDeg: theta2Deg.map(muReport) });
  return { svg, chart };
}

const attr = (el: Element | null, name: string) => Number(el?.getAttribute(name));

describe('transmission spec of the θ2 chart', () => {
  it('shades the stretches outside the band at the θ2 where the law of cosines leaves it', () => {
    const { svg } = drawn();
    const a = theta2AtMu(60);
    const b = theta2AtMu(100);
    const expected = [
      [0, a],
      [b, 360 - b],
      [360 - a, 360],
    ];
    const rects = svg.querySelectorAll('rect.mu-outside');
    expect(rects).toHaveLength(3);
    // Plot width 614 - 50 - 14 = 550 px for 360 degrees: the rect's pixels follow from its degrees, independently.
    const px = (d: number) => (d * 550) / 360;
    [...rects].forEach((r, i) => {
      // 0.5 degree samples: linear interpolation of the smooth mu errs by under 0.01 degree of theta2 here.
      expect(Math.abs(attr(r, 'data-x0') - expected[i][0])).toBeLessThan(0.01);
      expect(Math.abs(attr(r, 'data-x1') - expected[i][1])).toBeLessThan(0.01);
      expect(attr(r, 'x')).toBeCloseTo(px(attr(r, 'data-x0')), 9);
      expect(attr(r, 'width')).toBeCloseTo(px(attr(r, 'data-x1')) - px(attr(r, 'data-x0')), 9);
    });
  });

  it('shades the band between its edges on the fixed 0-180 degree axis and clips the warning curve outside it', () => {
    const { svg } = drawn();
    const band = svg.querySelector('rect.mu-band');
    // Plot height 346 - 46 - 40 = 260 px for 180 degrees, top down.
    const py = (mu: number) => 260 - (mu * 260) / 180;
    expect(band?.getAttribute('data-lo')).toBe('60');
    expect(attr(band, 'y')).toBeCloseTo(py(100), 9);
    expect(attr(band, 'height')).toBeCloseTo(py(60) - py(100), 9);
    const outside = svg.querySelector('g.lines path.mu-line-outside');
    const id = /^url\(#(.+)\)$/.exec(outside?.getAttribute('clip-path') ?? '')?.[1];
    const clip = [...svg.querySelectorAll('clipPath')].find((c) => c.getAttribute('id') === id);
    expect(clip).toBeDefined();
    const [above, below] = clip!.querySelectorAll('rect');
    expect(attr(above, 'y') + attr(above, 'height')).toBeCloseTo(py(100), 9);
    expect(attr(below, 'y')).toBeCloseTo(py(60), 9);
    expect(svg.querySelector('g.lines path.mu-line')?.getAttribute('clip-path')).toBeNull();
    expect([...svg.querySelectorAll('g.axis-y .tick text')].map((t) => t.textContent)).toEqual([
      '0',
      '30',
      '60',
      '90',
      '120',
      '150',
      '180',
    ]);
  });

  it('moves the shading with the band and colours the marker by it', () => {
    const { svg, chart } = drawn();
    chart.setMarker({ theta2Deg: 0, valuesDeg: [muReport(0)] });
    const dot = () => svg.querySelector('g.marker circle')?.getAttribute('fill');
    expect(dot()).toBe(COLORS.muOutside);
    chart.setBand({ loDeg: 40, hiDeg: 140 });
    expect(svg.querySelectorAll('rect.mu-outside')).toHaveLength(0);
    expect(svg.querySelector('rect.mu-band')?.getAttribute('data-hi')).toBe('140');
    expect(dot()).toBe(COLORS.angle);
  });

  it('names its legend from its texts: the curve, the warning colour and the band', () => {
    const { svg } = drawn();
    expect([...svg.querySelectorAll('g.legend text')].map((t) => t.textContent)).toEqual(['μ', 'out', 'band']);
    expect(svg.querySelector('text.title')?.textContent).toBe('Transmission angle');
  });
});
