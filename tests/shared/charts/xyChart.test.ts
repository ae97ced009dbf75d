import { describe, expect, it } from 'vitest';
import { chartSize, plotArea } from '../../../src/shared/charts/chart';
import { createXYChart, equalAspectDomains, paddedExtent, xyFrame } from '../../../src/shared/charts/xyChart';
import type { XYChartData } from '../../../src/shared/charts/xyChart';
import { fakeSvg } from './fakeSvgDom';

/** Structural error of a three-precision-point design against x: zero at the precision points 1, 2.5 and 4. */
const xs = Array.from({ length: 61 }, (_, i) => 0.5 + i * 0.06);
const err = xs.map((x) => 0.01 * (x - 1) * (x - 2.5) * (x - 4));
const structural: XYChartData = {
  series: [
    { label: 'error', color: '#a00', x: xs, y: err },
    { label: 'precision points', color: '#00a', x: [1, 2.5, 4], y: [0, 0, 0], line: false, dots: true },
  ],
};
const TEXT = { title: 'Structural error', xLabel: 'x', yLabel: 'error' };

describe('xyFrame', () => {
  it('holds every data point inside both domains, on nice ends', () => {
    const area = plotArea(chartSize({ width: 500, height: 300 }));
    const f = xyFrame(structural, area);
    const [x0, x1] = f.x.domain();
    const [y0, y1] = f.y.domain();
    for (const s of structural.series) {
      for (let i = 0; i < s.x.length; i++) {
        expect(s.x[i]).toBeGreaterThanOrEqual(x0);
        expect(s.x[i]).toBeLessThanOrEqual(x1);
        expect(s.y[i]).toBeGreaterThanOrEqual(y0);
        expect(s.y[i]).toBeLessThanOrEqual(y1);
      }
    }
    // d3's nice: the ends are whole multiples of the tick step.
    const step = f.xTicks[1] - f.xTicks[0];
    expect(Math.abs(x0 / step - Math.round(x0 / step))).toBeLessThan(1e-9);
    expect(f.yTicks.every((t) => t >= y0 && t <= y1)).toBe(true);
  });

  it('gives both axes the same units per pixel with equalAspect, the data still inside and centred', () => {
    // A bearing load F12 round the origin: (F cos phi, F sin phi), F between 2 and 5 kN, wider than tall.
    const phi = Array.from({ length: 73 }, (_, i) => (i * 2 * Math.PI) / 72);
    const fx = phi.map((p) => 5 * Math.cos(p) + 3);
    const fy = phi.map((p) => 2 * Math.sin(p));
    const area = plotArea(chartSize({ width: 600, height: 300 }));
    const f = xyFrame({ series: [{ label: 'F12', color: '#000', x: fx, y: fy }] }, area, {
      equalAspect: true,
      includeOrigin: true,
    });
    const unitsX = (f.x.domain()[1] - f.x.domain()[0]) / area.iw;
    const unitsY = (f.y.domain()[1] - f.y.domain()[0]) / area.ih;
    expect(unitsY).toBeCloseTo(unitsX, 12);
    expect(f.x.domain()[0]).toBeLessThanOrEqual(-2);
    expect(f.x.domain()[1]).toBeGreaterThanOrEqual(8);
    expect(f.y.domain()[0]).toBeLessThanOrEqual(-2);
    expect(f.y.domain()[1]).toBeGreaterThanOrEqual(2);
    // A circle of radius 1 at the origin is as wide as it is tall in pixels.
    expect(f.x(1) - f.x(0)).toBeCloseTo(f.y(0) - f.y(1), 9);
  });
});

describe('paddedExtent and equalAspectDomains', () => {
  it('pads a range by 5 %, a single value by 10 %, and takes in the origin on request', () => {
    expect(paddedExtent([1, 3])).toEqual([0.9, 3.1]);
    expect(paddedExtent([2, 2])).toEqual([1.8, 2.2]);
    expect(paddedExtent([])).toEqual([-1, 1]);
    expect(paddedExtent([1, 3], true)[0]).toBeLessThan(0);
  });
  it('widens only the axis with fewer units per pixel, about its centre', () => {
    const d = equalAspectDomains([0, 10], [0, 1], 100, 100);
    expect(d.x).toEqual([0, 10]);
    expect(d.y).toEqual([-4.5, 5.5]);
  });
});

describe('createXYChart', () => {
  it('draws the error as a line with a gap, the precision points as dots on the scales, and its texts', () => {
    const svg = fakeSvg();
    const chart = createXYChart(svg, { ...TEXT, width: 500, height: 300 });
    const gapped = { ...structural.series[0], y: err.map((e, i) => (i === 30 ? Number.NaN : e)) };
    chart.update({ series: [gapped, structural.series[1]] });
    const paths = svg.querySelectorAll('g.lines path');
    expect(paths).toHaveLength(1); // the dots-only series has no line
    expect(paths[0].getAttribute('d')?.match(/M/g)).toHaveLength(2);
    const dots = [...svg.querySelectorAll('g.dots circle')];
    expect(dots).toHaveLength(3);
    const x = chart.scale('x');
    const y = chart.scale('y');
    dots.forEach((c, i) => {
      expect(Number(c.getAttribute('cx'))).toBeCloseTo(x([1, 2.5, 4][i]), 9);
      expect(Number(c.getAttribute('cy'))).toBeCloseTo(y(0), 9);
    });
    expect(svg.querySelector('text.title')?.textContent).toBe('Structural error');
    expect([...svg.querySelectorAll('g.legend text')].map((t) => t.textContent)).toEqual(['error', 'precision points']);
    // Typographic minus on negative ticks.
    const yTicks = [...svg.querySelectorAll('g.axis-y .tick text')].map((t) => t.textContent ?? '');
    expect(yTicks.some((t) => t.startsWith('\u2212'))).toBe(true);
  });
});
