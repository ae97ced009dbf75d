import { describe, expect, it } from 'vitest';
import { createAngleChart } from '../../../src/shared/charts/theta2Chart';
import type { AngleChartData } from '../../../src/shared/charts/theta2Chart';
import { createRateChart, clipMarks } from '../../../src/shared/charts/rateChart';
import { fakeSvg, writesUnder } from './fakeSvgDom';

const TEXT = { title: 'θ3 against θ2', xLabel: 'θ2 (°)', yLabel: 'θ3 (°)' };
const theta2Deg = Array.from({ length: 361 }, (_, i) => i);
/** A smooth angle curve with a gap from 100 to 120 degrees (NaN: the linkage does not assemble). */
const angleData = (amp: number): AngleChartData => ({
  theta2Deg,
  series: [
    {
      label: 'θ3',
      color: '#111',
      valuesDeg: theta2Deg.map((t) => (t > 100 && t < 120 ? Number.NaN : amp * Math.sin(rad(t)))),
    },
  ],
});
const rad = (d: number) => (d * Math.PI) / 180;
const num = (el: Element | null, name: string) => Number(el?.getAttribute(name));

describe('createChart (through the angle spec)', () => {
  it('draws nothing until it has a size, then the plot at the margins', () => {
    const svg = fakeSvg();
    const chart = createAngleChart(svg, { ...TEXT, width: 0, height: 0 });
    chart.update(angleData(40));
    expect(svg.querySelector('g.lines path')).toBeNull();
    chart.resize(500, 300);
    expect(svg.querySelector('g.plot')?.getAttribute('transform')).toBe('translate(50,46)');
    expect(svg.querySelectorAll('g.lines path')).toHaveLength(1);
    expect(svg.querySelector('text.title')?.textContent).toBe('θ3 against θ2');
  });

  it('leaves a gap where the data do and never writes NaN', () => {
    const svg = fakeSvg();
    createAngleChart(svg, { ...TEXT, width: 500, height: 300 }).update(angleData(40));
    const d = svg.querySelector('g.lines path')?.getAttribute('d') ?? '';
    expect(d).not.toContain('NaN');
    expect(d.match(/M/g)).toHaveLength(2);
  });

  it('keeps its axes when new data keep their domain, and redraws them when it changes', () => {
    const svg = fakeSvg();
    const chart = createAngleChart(svg, { ...TEXT, width: 500, height: 300 });
    chart.update(angleData(40));
    const axes = () => ['g.axis-x', 'g.grid-x', 'g.axis-y', 'g.grid-y'].map((s) => writesUnder(svg.querySelector(s)));
    const lines = () => writesUnder(svg.querySelector('g.lines'));
    const [a0, l0] = [axes(), lines()];
    chart.update(angleData(40.5)); // same nice y domain
    expect(axes()).toEqual(a0);
    expect(lines()).toBeGreaterThan(l0);
    chart.update(angleData(150));
    const a2 = axes();
    expect(a2[0]).toBe(a0[0]); // theta2 axis: fixed
    expect(a2[2]).toBeGreaterThan(a0[2]);
  });

  it('puts the marker line at x(θ2) and a dot on the curve, and moves only the marker', () => {
    const svg = fakeSvg();
    const chart = createAngleChart(svg, { ...TEXT, width: 410, height: 300 });
    chart.update(angleData(40));
    const before = writesUnder(svg.querySelector('g.lines'));
    chart.setMarker({ theta2Deg: 90, valuesDeg: [40] });
    expect(writesUnder(svg.querySelector('g.lines'))).toBe(before);
    // Plot width 410 - 50 - 14 = 346 px for 360 degrees.
    expect(num(svg.querySelector('g.marker line.mline'), 'x1')).toBeCloseTo(86.5, 9);
    const y = chart.scale('y');
    expect(num(svg.querySelector('g.marker circle'), 'cy')).toBeCloseTo(y(40), 9);
    chart.setMarker(null);
    expect(svg.querySelector('g.marker')?.getAttribute('display')).toBe('none');
  });

  it('draws the dead-centre rules inside the θ2 axis only', () => {
    const svg = fakeSvg();
    const chart = createAngleChart(svg, { ...TEXT, width: 410, height: 300, xMarks: [{ xDeg: 45, label: 'ext.' }] });
    chart.setXMarks([
      { xDeg: 45, label: 'ext.' },
      { xDeg: 400, label: 'off' },
    ]);
    const marks = svg.querySelectorAll('g.x-mark');
    expect([...marks].map((m) => m.textContent)).toEqual(['ext.']);
    expect(marks[0].getAttribute('transform')).toBe(`translate(${(45 * 346) / 360},0)`);
  });
});

describe('rate spec of the θ2 chart', () => {
  it('clips its curves to the plot and marks each place a solid curve leaves it', () => {
    const svg = fakeSvg();
    const chart = createRateChart(svg, { title: 'ω', xLabel: 'θ2 (°)', yLabel: 'ω (rad/s)', width: 500, height: 300 });
    // A limit position: two runaway samples the robust domain cuts off.
    const values = theta2Deg.map((t) => (t === 90 ? 1e6 : t === 200 ? -1e6 : Math.cos(rad(t))));
    chart.update({ theta2Deg, series: [{ label: 'ω3', color: '#123', values }] });
    const id = /^url\(#(theta2-clip-\d+)\)$/.exec(svg.querySelector('g.lines')?.getAttribute('clip-path') ?? '')?.[1];
    expect([...svg.querySelectorAll('clipPath')].some((c) => c.getAttribute('id') === id)).toBe(true);
    const expected = clipMarks(theta2Deg, values, chart.scale('y').domain() as [number, number]);
    expect(expected.map((m) => m.side)).toEqual(['above', 'below']);
    expect(svg.querySelectorAll('g.clip-marks path')).toHaveLength(2);
    expect(svg.getAttribute('data-clip-marks')).toBe('2');
    const [lo, hi] = chart.scale('y').domain();
    expect(hi).toBeLessThan(10);
    expect(lo).toBeGreaterThan(-10);
  });
});
