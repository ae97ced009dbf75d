import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import {
  createCycleChart,
  decadeLabels,
  detJDomain,
  iterationTicks,
  maxIterations,
  spacedTicks,
  toAxisDeg,
  unassembledRuns,
} from '../../../src/features/lab/cycleChart';
import type { CycleChartData } from '../../../src/features/lab/cycleChart';
import { fakeSvg, writesUnder } from '../../shared/charts/fakeSvgDom';

describe('toAxisDeg', () => {
  it('maps limits in (-180, 180] onto the 0..360 axis', () => {
    expect(toAxisDeg(135.95)).toBe(135.95);
    expect(toAxisDeg(-135.95)).toBeCloseTo(224.05, 12);
    expect(toAxisDeg(-90)).toBe(270);
    expect(toAxisDeg(180)).toBe(180);
    expect(toAxisDeg(0)).toBe(0);
  });
  it('keeps angles already on the axis, 360 included, and wraps the rest', () => {
    expect(toAxisDeg(360)).toBe(360);
    expect(toAxisDeg(400)).toBeCloseTo(40, 12);
  });
});

describe('detJDomain', () => {
  it('spans whole decades around the positive values, ignoring NaN and zeros', () => {
    expect(detJDomain(new Float64Array([2.4e-4, 5.6, NaN, 0]))).toEqual([1e-4, 10]);
  });
  it('is at least two decades wide for a nearly constant |det J|', () => {
    const [lo, hi] = detJDomain(new Float64Array([18.3, 25.1]));
    expect(hi).toBe(100);
    expect(lo).toBe(1);
  });
  it('handles an exact power of ten and falls back without data', () => {
    const [lo, hi] = detJDomain(new Float64Array([10]));
    expect(hi / lo).toBeGreaterThanOrEqual(100);
    expect(hi).toBeGreaterThanOrEqual(10);
    expect(detJDomain(new Float64Array([NaN, NaN]))).toEqual([1e-3, 10]);
  });
});

describe('iterationTicks', () => {
  it('counts every integer on a small axis', () => {
    expect(iterationTicks(3)).toEqual([0, 1, 2, 3]);
    expect(iterationTicks(0)).toEqual([0, 1]);
  });
  it('steps so the last tick covers the maximum', () => {
    expect(iterationTicks(13)).toEqual([0, 5, 10, 15]);
    expect(iterationTicks(7)).toEqual([0, 2, 4, 6, 8]);
  });
  it('uses 1-2-5 steps up to the maximum on a symlog axis', () => {
    expect(iterationTicks(100)).toEqual([0, 1, 2, 5, 10, 20, 50, 100]);
    expect(iterationTicks(37)).toEqual([0, 1, 2, 5, 10, 20, 37]);
  });
  it('only ever gives integers', () => {
    for (const m of [1, 4, 9, 19, 23, 250]) expect(iterationTicks(m).every((t) => Number.isInteger(t))).toBe(true);
  });
});

describe('spacedTicks', () => {
  it('drops ticks closer than the gap, keeping the top one', () => {
    const px = (v: number) => 100 - Math.log1p(v) * 20;
    const kept = spacedTicks([0, 1, 2, 5, 10, 20, 50, 100], px, 13);
    expect(kept[kept.length - 1]).toBe(100);
    for (let i = 1; i < kept.length; i++) expect(Math.abs(px(kept[i]) - px(kept[i - 1]))).toBeGreaterThanOrEqual(13);
  });
});

describe('unassembledRuns', () => {
  it('finds the stretches where |det J| is NaN', () => {
    const x = [0, 10, 20, 30, 40, 50];
    expect(unassembledRuns(x, [1, NaN, NaN, 1, 1, NaN])).toEqual([
      [10, 20],
      [50, 50],
    ]);
    expect(unassembledRuns(x, [1, 1, 1, 1, 1, 1])).toEqual([]);
  });
});

describe('maxIterations', () => {
  it('is the largest count over all methods', () => {
    expect(
      maxIterations([
        { method: 'newton', label: '', iterations: Int32Array.from([0, 2, 1]) },
        { method: 'seed', label: '', iterations: Int32Array.from([5, 100]) },
      ]),
    ).toBe(100);
    expect(maxIterations([])).toBe(0);
  });
});

describe('decadeLabels', () => {
  it('labels one axis in one style', () => {
    expect(decadeLabels([1, 10, 100])).toEqual(['1', '10', '100']);
    expect(decadeLabels([0.01, 0.1, 1])).toEqual(['0.01', '0.1', '1']);
    expect(decadeLabels([1e-3, 1e-1, 10])).toEqual(['1e\u22123', '1e\u22121', '1e1']);
  });
});

describe('createCycleChart', () => {
  const TEXT = { title: 'cycle', xLabel: 'θ2 (°)', iterationsLabel: 'iterations', detJLabel: '|det J|' };
  const theta2Deg = Float64Array.from({ length: 361 }, (_v, i) => i);
  /** |det J| of amplitude a with an unassembled stretch from 100 to 120 degrees; two methods' counts. */
  const data = (a: number, extra = 0): CycleChartData => ({
    theta2Deg,
    detJ: theta2Deg.map((t) => (t > 100 && t < 120 ? NaN : a * (1.5 + Math.sin((t * Math.PI) / 180)))),
    iterations: [
      { method: 'newton', label: 'NR', iterations: Int32Array.from(theta2Deg, (t) => 2 + (t % 90 === 0 ? extra : 0)) },
      { method: 'seed', label: 'seed', iterations: Int32Array.from(theta2Deg, () => 3) },
    ],
    limitsDeg: [-90],
  });
  const W = 560;
  const H = 400;
  // Margins left 58, right 14: the θ2 axis runs over 488 px.
  const IW = W - 58 - 14;
  const panel = (svg: SVGSVGElement, cls: string) => svg.querySelector(`svg.${cls}`);
  const parts = (svg: SVGSVGElement, sel: string) =>
    ['panel-top', 'panel-bottom'].map((cls) => writesUnder(panel(svg, cls)?.querySelector(sel) ?? null));
  const made = () => {
    const svg = fakeSvg();
    const chart = createCycleChart(svg, { ...TEXT, width: 0, height: 0 });
    chart.update(data(2));
    chart.setMarker(90);
    chart.resize(W, H);
    return { svg, chart };
  };

  it('stacks two panels of equal plot height, the bottom one under the top one, the marker at θ2 in both', () => {
    const { svg } = made();
    expect(svg.getAttribute('height')).toBe(String(H));
    const top = panel(svg, 'panel-top');
    const bottom = panel(svg, 'panel-bottom');
    const topH = Number(top?.getAttribute('height'));
    expect(Number(bottom?.getAttribute('y'))).toBe(topH);
    expect(topH + Number(bottom?.getAttribute('height'))).toBe(H);
    // Plot heights: the top panel's less its top margin (46) and foot (7); the bottom one's less 14 − 7 and 40.
    const ihTop = topH - 46 - 7;
    const ihBottom = H - topH - 7 - 40;
    expect(Math.abs(ihTop - ihBottom)).toBeLessThanOrEqual(1);
    for (const p of [top, bottom]) {
      expect(Number(p?.querySelector('g.marker line.mline')?.getAttribute('x1'))).toBeCloseTo((90 / 360) * IW, 9);
    }
    // The limit −90° lands at 270° on the axis, in both panels.
    const limits = [...(svg.querySelectorAll('line.limit') as unknown as Element[])];
    expect(limits).toHaveLength(2);
    for (const l of limits) expect(Number(l.getAttribute('x1'))).toBeCloseTo((270 / 360) * IW, 9);
  });

  it('moves only the marker on a θ2 step, and hides it when θ2 is not finite', () => {
    const { svg, chart } = made();
    const lines = parts(svg, 'g.lines');
    const axes = parts(svg, 'g.axis-y');
    chart.setMarker(200);
    expect(parts(svg, 'g.lines')).toEqual(lines);
    expect(parts(svg, 'g.axis-y')).toEqual(axes);
    const x1 = panel(svg, 'panel-bottom')?.querySelector('g.marker line.mline')?.getAttribute('x1');
    expect(Number(x1)).toBeCloseTo((200 / 360) * IW, 9);
    chart.setMarker(NaN);
    for (const cls of ['panel-top', 'panel-bottom']) {
      expect(panel(svg, cls)?.querySelector('g.marker')?.getAttribute('display')).toBe('none');
    }
  });

  it('redraws the curves on new data and the axes only when their domain changes', () => {
    const { svg, chart } = made();
    const lines = parts(svg, 'g.lines');
    const axes = parts(svg, 'g.axis-y');
    chart.update(data(2.1)); // same decades of |det J|, same counts
    expect(parts(svg, 'g.axis-y')).toEqual(axes);
    const lines1 = parts(svg, 'g.lines');
    expect(lines1[0]).toBeGreaterThan(lines[0]);
    expect(lines1[1]).toBeGreaterThan(lines[1]);
    chart.update(data(2000, 40)); // |det J| decades up, 42 iterations: a symlog top axis
    const axes2 = parts(svg, 'g.axis-y');
    expect(axes2[0]).toBeGreaterThan(axes[0]);
    expect(axes2[1]).toBeGreaterThan(axes[1]);
  });

  it('sets its texts through the handle', () => {
    const { svg, chart } = made();
    chart.setText({ ...TEXT, title: 'Zyklus', detJLabel: '|det J| (m²)' });
    expect(panel(svg, 'panel-top')?.querySelector('text.title')?.textContent).toBe('Zyklus');
    const yLabels = [...(svg.querySelectorAll('text') as unknown as Element[])].map((t) => t.textContent);
    expect(yLabels).toContain('|det J| (m²)');
  });
  it('paints its background first, under both panels', () => {
    const { svg } = made();
    const kids = [...(svg.children as unknown as Element[])];
    expect(kids[0].getAttribute('class')).toBe('bg');
    expect(kids.map((k) => k.getAttribute('class'))).toEqual(['bg', 'panel-top', 'panel-bottom']);
  });

  it('puts the iteration ticks on a symlog axis (linear within one iteration of 0) once a method needs dozens', () => {
    const svg = fakeSvg();
    const chart = createCycleChart(svg, { ...TEXT, width: W, height: H });
    chart.update(data(2, 40)); // 42 iterations at the quarter turns
    const top = panel(svg, 'panel-top');
    const topH = Number(top?.getAttribute('height'));
    const ih = topH - 46 - 7;
    const rows = [...(top?.querySelectorAll('g.grid-y line.gy') as unknown as Element[])].map((l) =>
      Number(l.getAttribute('y1')),
    );
    const ticks = [...(top?.querySelectorAll('g.axis-y .tick text') as unknown as Element[])].map((t) =>
      Number(t.textContent),
    );
    expect(ticks[ticks.length - 1]).toBe(42);
    expect(ticks).toContain(1);
    // The oracle: d3's symlog with constant 1 maps v to ln(1 + v) / ln(43) of the way from the foot (ih) to 4 px.
    const symlogPx = (v: number) =>
      new Decimal(ih).plus(new Decimal(4 - ih).times(new Decimal(1 + v).ln().div(new Decimal(43).ln()))).toNumber();
    expect(rows).toHaveLength(ticks.length);
    ticks.forEach((t, i) => expect(rows[i]).toBeCloseTo(symlogPx(t), 9));
  });

  it('draws zeros of |det J| on the floor of its log axis (a dashed line, ≤ at the foot), NaN as the only gaps', () => {
    const svg = fakeSvg();
    const chart = createCycleChart(svg, { ...TEXT, width: W, height: H });
    const d = data(2);
    const detJ = d.detJ.map((v, i) => (i === 30 || i === 200 ? 0 : v));
    chart.update({ ...d, detJ });
    const bottom = panel(svg, 'panel-bottom');
    expect(bottom?.querySelectorAll('g.grid-y line.floor')).toHaveLength(1);
    const labels = [...(bottom?.querySelectorAll('g.axis-y .tick text') as unknown as Element[])].map(
      (t) => t.textContent,
    );
    expect(labels[0]?.startsWith('≤')).toBe(true);
    const path = bottom?.querySelector('g.lines path')?.getAttribute('d') ?? '';
    // One gap, the unassembled stretch: the zeros sit on the floor instead of breaking the line.
    expect(path.match(/M/g)).toHaveLength(2);
    expect(path).not.toMatch(/NaN|Infinity/);
  });
});
