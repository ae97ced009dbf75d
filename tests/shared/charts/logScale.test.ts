import Decimal from 'decimal.js';
import { scaleLinear, scaleLog } from 'd3-scale';
import { describe, expect, it } from 'vitest';
import type { ChartSpec } from '../../../src/shared/charts/chart';
import { createChart, logFloor, onFloor } from '../../../src/shared/charts/chart';
import { CHART_STYLE, minus } from '../../../src/shared/charts/chartFrame';
import { fakeSvg } from './fakeSvgDom';

/** The oracle: a log axis from lo to hi over h pixels, upwards, in 40-digit decimals: h (1 − (lg v − lg lo) / (lg hi − lg lo)). */
function logPx(v: number, lo: number, hi: number, h: number): number {
  const lg = (x: number) => new Decimal(x).log(10);
  const f = lg(v)
    .minus(lg(lo))
    .div(lg(hi).minus(lg(lo)));
  return new Decimal(h).times(new Decimal(1).minus(f)).toNumber();
}

/** Same on x, left to right. */
function logPxX(v: number, lo: number, hi: number, w: number): number {
  const lg = (x: number) => new Decimal(x).log(10);
  return new Decimal(w)
    .times(
      lg(v)
        .minus(lg(lo))
        .div(lg(hi).minus(lg(lo))),
    )
    .toNumber();
}

interface Data {
  x: number[];
  y: number[];
  logX?: boolean;
}

/** y on a log axis over [1e-6, 1e2] with its floor at the foot (or at `floor`), decade ticks 1e-6 … 1e2 by two. */
const spec = (floor = 1e-6, lo = 1e-6): ChartSpec<Data, never> => ({
  frame: (d, plot) => ({
    x: d.logX ? scaleLog().domain([1, 1000]).range([0, plot.iw]) : scaleLinear().domain([0, 10]).range([0, plot.iw]),
    y: scaleLog().domain([lo, 1e2]).range([plot.ih, 0]),
    xTicks: d.logX ? [1, 10, 100, 1000] : [0, 5, 10],
    yTicks: [1e-6, 1e-4, 1e-2, 1, 1e2].filter((t) => t >= lo),
    yFloor: logFloor(floor, [d.y]),
  }),
  curves: (d) => [{ label: 'r', color: '#123456', x: d.x, y: d.y, dots: true }],
  yTickFormat: () => (v) => minus(`1e${Math.round(Math.log10(v))}`),
});

/** The points of an SVG path (M or L), in order, and the number of pieces (M count). */
function pathPoints(d: string): { pts: [number, number][]; pieces: number } {
  const pts = [...d.matchAll(/[ML]([-\d.e]+),([-\d.e]+)/g)].map((m): [number, number] => [Number(m[1]), Number(m[2])]);
  return { pts, pieces: (d.match(/M/g) ?? []).length };
}

// 500 x 300 with the kit's margins { top: 46, right: 14, bottom: 40, left: 50 }: a 436 x 214 px plot.
const W = 500;
const H = 300;
const IW = 436;
const IH = 214;
/** Path coordinates are written in hundredths of a pixel. */
const PATH_TOL = 0.006;

describe('onFloor and logFloor', () => {
  it('puts finite values below the floor on it and keeps NaN a gap', () => {
    expect(onFloor(0, 1e-6)).toBe(1e-6);
    expect(onFloor(-3, 1e-6)).toBe(1e-6);
    expect(onFloor(1e-9, 1e-6)).toBe(1e-6);
    expect(onFloor(1e-3, 1e-6)).toBe(1e-3);
    expect(onFloor(Number.NaN, 1e-6)).toBeNaN();
    expect(onFloor(0, undefined)).toBe(0);
  });
  it('has a floor only when some value is below it', () => {
    expect(logFloor(1e-6, [[1, 1e-3], [Number.NaN]])).toBeUndefined();
    expect(logFloor(1e-6, [[1, 1e-3], [0]])).toBe(1e-6);
    expect(logFloor(1e-17, [Float64Array.from([1e-18])])).toBe(1e-17);
  });
});

describe('a log y in the chart kit', () => {
  it('places each decade tick and its grid line where the logarithm says, labelled, the floor with ≤', () => {
    const svg = fakeSvg();
    createChart(svg, { width: W, height: H }, { title: 't', xLabel: 'x', yLabel: 'y' }, spec(), {
      x: [0, 1],
      y: [1, 0],
    });
    const grid = [...svg.querySelectorAll('g.grid-y line.gy')].map((l) => Number(l.getAttribute('y1')));
    const ticks = [1e-6, 1e-4, 1e-2, 1, 1e2];
    expect(grid).toHaveLength(ticks.length);
    ticks.forEach((t, i) => expect(grid[i]).toBeCloseTo(logPx(t, 1e-6, 1e2, IH), 9));
    const labels = [...svg.querySelectorAll('g.axis-y .tick text')].map((t) => t.textContent);
    expect(labels).toEqual(['≤1e\u22126', '1e\u22124', '1e\u22122', '1e0', '1e2']);
    const floor = svg.querySelectorAll('g.grid-y line.floor');
    expect(floor).toHaveLength(1);
    expect(Number(floor[0].getAttribute('y1'))).toBeCloseTo(IH, 9);
  });

  it('draws zeros, negatives and values below the floor on it (hollow dots), NaN as a gap', () => {
    const svg = fakeSvg();
    const x = [0, 1, 2, 3, 4, 5, 6, 7];
    const y = [10, 1e-3, 0, 3e-2, Number.NaN, 1e-9, -3, 1];
    createChart(svg, { width: W, height: H }, { title: 't', xLabel: 'x', yLabel: 'y' }, spec(), { x, y });
    const { pts, pieces } = pathPoints(svg.querySelector('g.lines path')?.getAttribute('d') ?? '');
    expect(pieces).toBe(2);
    const shown = x.filter((_v, i) => !Number.isNaN(y[i]));
    expect(pts).toHaveLength(shown.length);
    const want = y.filter((v) => !Number.isNaN(v)).map((v) => logPx(v > 1e-6 ? v : 1e-6, 1e-6, 1e2, IH));
    pts.forEach(([px, py], i) => {
      expect(px).toBeCloseTo((shown[i] / 10) * IW, 2);
      expect(Math.abs(py - want[i])).toBeLessThan(PATH_TOL);
    });
    const dots = [...svg.querySelectorAll('g.dots circle')];
    expect(dots).toHaveLength(7);
    const hollow = dots.map((c) => c.getAttribute('fill') === CHART_STYLE.background);
    expect(hollow).toEqual([false, false, true, false, true, true, false]);
    expect(dots.filter((_c, i) => hollow[i]).every((c) => Number(c.getAttribute('cy')) === IH)).toBe(true);
  });

  it('draws a floor above the axis foot where the spec puts it, and no floor when nothing is below it', () => {
    const svg = fakeSvg();
    const chart = createChart(
      svg,
      { width: W, height: H },
      { title: 't', xLabel: 'x', yLabel: 'y' },
      spec(1e-4, 1e-6),
      {
        x: [0, 1, 2],
        y: [1, 0, 1e-5],
      },
    );
    const { pts } = pathPoints(svg.querySelector('g.lines path')?.getAttribute('d') ?? '');
    const atFloor = logPx(1e-4, 1e-6, 1e2, IH);
    expect(Math.abs(pts[1][1] - atFloor)).toBeLessThan(PATH_TOL);
    expect(Math.abs(pts[2][1] - atFloor)).toBeLessThan(PATH_TOL);
    expect(Number(svg.querySelector('g.grid-y line.floor')?.getAttribute('y1'))).toBeCloseTo(atFloor, 9);
    chart.update({ x: [0, 1], y: [1, 1e-3] });
    expect(svg.querySelectorAll('g.grid-y line.floor')).toHaveLength(0);
    expect([...svg.querySelectorAll('g.axis-y .tick text')].map((t) => t.textContent)).not.toContain('≤1e\u22124');
  });

  it('leaves a gap where a log x has no place for the value (0 or below)', () => {
    const svg = fakeSvg();
    const x = [1, 10, 0, 100, -5, 1000];
    const y = [1, 1, 1, 1, 1, 1];
    createChart(svg, { width: W, height: H }, { title: 't', xLabel: 'x', yLabel: 'y' }, spec(), { x, y, logX: true });
    const { pts, pieces } = pathPoints(svg.querySelector('g.lines path')?.getAttribute('d') ?? '');
    expect(pieces).toBe(3);
    const placed = x.filter((v) => v > 0);
    expect(pts).toHaveLength(placed.length);
    pts.forEach(([px], i) => expect(Math.abs(px - logPxX(placed[i], 1, 1000, IW))).toBeLessThan(PATH_TOL));
    expect(svg.querySelectorAll('g.dots circle')).toHaveLength(4);
    expect(svg.querySelector('g.lines path')?.getAttribute('d')).not.toMatch(/NaN|Infinity/);
  });
  it('writes ≤ on the floor tick itself when the floor stands above the axis foot, and on no other tick', () => {
    const svg = fakeSvg();
    createChart(svg, { width: W, height: H }, { title: 't', xLabel: 'x', yLabel: 'y' }, spec(1e-4, 1e-6), {
      x: [0, 1],
      y: [1, 0],
    });
    const labels = [...svg.querySelectorAll('g.axis-y .tick text')].map((t) => t.textContent);
    expect(labels).toEqual(['1e\u22126', '≤1e\u22124', '1e\u22122', '1e0', '1e2']);
  });
});
