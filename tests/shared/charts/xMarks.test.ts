import { describe, expect, it } from 'vitest';
import type { TextBox } from '../../../src/shared/charts/chartFrame';
import { estimateTextWidth, legendBoxes } from '../../../src/shared/charts/chartFrame';
import { createAngleChart } from '../../../src/shared/charts/theta2Chart';
import type { AngleChartData } from '../../../src/shared/charts/theta2Chart';
import { X_MARK_BASELINES, X_MARK_FONT_SIZE, xMarkBaselines } from '../../../src/shared/charts/xMarks';
import { fakeSvg } from './fakeSvgDom';

const meet = (a: TextBox, b: TextBox) => a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;

describe('xMarkBaselines', () => {
  it('keeps a label above the plot where nothing is in its way', () => {
    expect(xMarkBaselines([{ xPx: 200, label: 'fold.' }], [])).toEqual([X_MARK_BASELINES.above]);
  });

  it('moves a label that would meet the legend just inside the plot', () => {
    const legend: TextBox = { x0: 150, y0: -20, x1: 260, y1: -8 };
    expect(xMarkBaselines([{ xPx: 200, label: 'fold.' }], [legend])).toEqual([X_MARK_BASELINES.inside]);
  });

  it('moves the second of two labels that would meet each other', () => {
    const b = xMarkBaselines(
      [
        { xPx: 100, label: 'ext.' },
        { xPx: 108, label: 'fold.' },
      ],
      [],
    );
    expect(b).toEqual([X_MARK_BASELINES.above, X_MARK_BASELINES.inside]);
  });
});

// Issue 19: on a phone the dead-centre labels met the plot legends ("fold." over "(other branch)", 伸直 over
// "θ3 (另一分支)"). A 372 px chart is the phone's; the rules are at the report case's dead centres.
describe('the angle chart on a phone', () => {
  const theta2Deg = Array.from({ length: 361 }, (_, i) => i);
  const data = (other: string): AngleChartData => ({
    theta2Deg,
    series: [
      { label: `θ3 (${other})`, color: '#999', faint: true, valuesDeg: theta2Deg.map(() => -40) },
      { label: 'θ3', color: '#111', valuesDeg: theta2Deg.map(() => 40) },
    ],
  });
  for (const [lang, other, marks] of [
    ['en', 'other branch', ['ext.', 'fold.']],
    ['zh-TW', '另一分支', ['伸直', '摺疊']],
  ] as const) {
    it(`sets no dead-centre label over the legend (${lang})`, () => {
      for (const width of [300, 340, 372, 420]) {
        const svg = fakeSvg();
        const chart = createAngleChart(svg, {
          title: 'θ3',
          xLabel: 'θ2 (°)',
          yLabel: 'θ3 (°)',
          width,
          height: 260,
          xMarks: [
            { xDeg: 44.415, label: marks[0] },
            { xDeg: 236.251, label: marks[1] },
          ],
        });
        chart.update(data(other));
        const legend = legendBoxes(
          [...svg.querySelectorAll('g.legend g.item text')].map((t) => ({ label: t.textContent ?? '', color: '' })),
          14,
          33,
        );
        const plot = /translate\(([\d.]+),([\d.]+)\)/.exec(svg.querySelector('g.plot')!.getAttribute('transform')!)!;
        const [left, top] = [Number(plot[1]), Number(plot[2])];
        const labels = [...svg.querySelectorAll('g.x-mark')].map((g) => {
          const x = left + Number(/translate\(([-\d.]+),/.exec(g.getAttribute('transform')!)![1]);
          const text = g.querySelector('text')!;
          const y = top + Number(text.getAttribute('y'));
          const half = estimateTextWidth(text.textContent ?? '', X_MARK_FONT_SIZE) / 2;
          return { x0: x - half, y0: y - X_MARK_FONT_SIZE, x1: x + half, y1: y + X_MARK_FONT_SIZE / 4 };
        });
        expect(labels).toHaveLength(2);
        for (const l of labels) for (const b of legend) expect(meet(l, b), `${width} px`).toBe(false);
      }
    });
  }
});
