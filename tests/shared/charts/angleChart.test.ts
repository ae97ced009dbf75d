import { describe, expect, it } from 'vitest';
import type { AngleChartData, AngleSeries } from '../../../src/shared/charts/theta2Chart';
import { angleSpec, angleYAxis } from '../../../src/shared/charts/theta2Chart';
import type { ChartSizeOptions } from '../../../src/shared/charts/chart';
import {
  chartFrame,
  chartSize,
  curvePath,
  markerPlacement,
  plotIndices,
  wrappedSegments,
} from '../../../src/shared/charts/chart';

/** The angle chart's frame for these series at this size. */
const angleFrame = (series: AngleSeries[], size: ChartSizeOptions) =>
  chartFrame(angleSpec, { theta2Deg: [], series }, chartSize(size));
/** The angle chart's marker placement for this marker over these series. */
const markerGeometry = (
  marker: { theta2Deg: number; valuesDeg: number[] },
  series: AngleSeries[],
  frame: ReturnType<typeof angleFrame>,
) => markerPlacement(angleSpec.marker!(marker, { theta2Deg: [], series } as AngleChartData), frame);
import { estimateTextWidth, minus } from '../../../src/shared/charts/chartFrame';
import { FONT_SIZES } from '../../../src/shared/theme/tokens';

describe('wrappedSegments', () => {
  it('turns NaN samples into gaps', () => {
    const pts = wrappedSegments([0, 1, 2], [10, Number.NaN, 12]);
    expect(pts.map((p) => Number.isNaN(p[1]))).toEqual([false, true, false]);
  });

  it('runs to the +-180 edge and breaks where the angle wraps, so no stroke crosses the plot', () => {
    const pts = wrappedSegments([0, 2], [179, -179]);
    expect(pts).toHaveLength(5);
    expect(pts[1]).toEqual([1, 180]);
    expect(Number.isNaN(pts[2][1])).toBe(true);
    expect(pts[3]).toEqual([1, -180]);
    expect(pts[4]).toEqual([2, -179]);
  });

  it('wraps the other way too', () => {
    const pts = wrappedSegments([0, 4], [-178, 178]);
    expect(pts[1][1]).toBe(-180);
    expect(pts[3][1]).toBe(180);
    expect(pts[1][0]).toBeCloseTo(2, 12);
  });
});

describe('angleYAxis', () => {
  it('holds the data with 5 degrees of padding and ends on nice angles within [-180, 180]', () => {
    const [a, b] = angleYAxis([{ label: '', color: '', valuesDeg: [31, 79] }]).domain;
    expect(a).toBeLessThanOrEqual(26);
    expect(b).toBeGreaterThanOrEqual(84);
    expect(b - a).toBeLessThanOrEqual(90);
    expect(a % 15).toBe(0);
    expect(b % 15).toBe(0);
    expect(angleYAxis([{ label: '', color: '', valuesDeg: [-179, 179] }]).domain).toEqual([-180, 180]);
  });
  it('shows the full range when there is no data', () => {
    expect(angleYAxis([{ label: '', color: '', valuesDeg: [Number.NaN] }]).domain).toEqual([-180, 180]);
  });
});

describe('angleFrame', () => {
  const full = [{ label: '', color: '', valuesDeg: [-179, 179] }];
  it('gives tick labels room at every width, phones included: no label runs into the next', () => {
    for (let width = 70; width <= 1600; width += 7) {
      const f = angleFrame(full, { width, height: 300 });
      const px = f.xTicks.map((t) => f.x(t));
      const w = f.xTicks.map((t) => estimateTextWidth(minus(`${t}`)));
      // Labels are centred on their ticks: the space between neighbours' edges must stay visible (4 px).
      for (let i = 1; i < px.length; i++) {
        expect(px[i] - px[i - 1] - (w[i] + w[i - 1]) / 2, `width ${width}`).toBeGreaterThan(4);
      }
      expect(f.xTicks.length, `width ${width}`).toBeGreaterThanOrEqual(width >= 160 ? 3 : 1);
    }
    for (let height = 120; height <= 900; height += 11) {
      const f = angleFrame(full, { width: 500, height });
      const py = f.yTicks.map((t) => f.y(t));
      for (let i = 1; i < py.length; i++)
        expect(py[i - 1] - py[i], `height ${height}`).toBeGreaterThan(FONT_SIZES.chart + 3);
    }
  });
  it('steps 60 degrees along theta2 from a phone-sized chart up to a wide export', () => {
    // Plot width = chart width - 64 px of margins: 60 degree steps from 160 px of plot width up.
    for (let width = 224; width <= 1600; width += 9) {
      expect(angleFrame(full, { width, height: 260 }).xTicks).toEqual([0, 60, 120, 180, 240, 300, 360]);
    }
  });
  it('keeps the y ticks inside the domain, at its ends', () => {
    const f = angleFrame([{ label: '', color: '', valuesDeg: [31, 79] }], { width: 500, height: 300 });
    expect(f.yTicks[0]).toBe(f.y.domain()[0]);
    expect(f.yTicks[f.yTicks.length - 1]).toBe(f.y.domain()[1]);
  });
});

describe('curvePath', () => {
  it('leaves a gap where the linkage cannot assemble and never writes NaN', () => {
    const f = angleFrame([{ label: '', color: '', valuesDeg: [-179, 179] }], { width: 400, height: 300 });
    const theta2 = [0, 60, 120, 180, 240, 300, 360];
    const d = curvePath({ x: theta2, y: [10, 20, Number.NaN, Number.NaN, 40, 50, 60], wrapped: true }, f);
    expect(d).not.toContain('NaN');
    expect(d.match(/M/g)).toHaveLength(2);
    // The path starts at the first sample on the chart's scales (the path keeps hundredths of a pixel: within 0.005 px).
    const [x0, y0] = d.slice(1).split(/[ML]/)[0].split(',').map(Number);
    expect(Math.abs(x0 - f.x(0))).toBeLessThanOrEqual(0.005 + 1e-9);
    expect(Math.abs(y0 - f.y(10))).toBeLessThanOrEqual(0.005 + 1e-9);
  });
});

describe('markerPlacement (angle spec)', () => {
  const series = [
    { label: 'a', color: 'faint', valuesDeg: [0], faint: true },
    { label: 'b', color: 'solid', valuesDeg: [0] },
  ];
  const f = angleFrame([{ label: '', color: '', valuesDeg: [-179, 179] }], { width: 400, height: 300 });
  it('puts a dot on each solid series at the scales of theta2 and its value', () => {
    const g = markerGeometry({ theta2Deg: 90, valuesDeg: [45] }, series, f);
    expect(g.x).toBe(f.x(90));
    expect(g.dots).toEqual([{ cx: f.x(90), cy: f.y(45), color: 'solid' }]);
  });
  it('hides the marker without theta2 and drops values that are gaps or outside the plot', () => {
    expect(markerGeometry({ theta2Deg: Number.NaN, valuesDeg: [1] }, series, f)).toEqual({ x: null, dots: [] });
    expect(markerPlacement(null, f).x).toBeNull();
    expect(markerGeometry({ theta2Deg: 10, valuesDeg: [Number.NaN] }, series, f).dots).toEqual([]);
    const narrow = angleFrame([series[1]], { width: 400, height: 300 });
    expect(markerGeometry({ theta2Deg: 10, valuesDeg: [170] }, series, narrow).dots).toEqual([]);
  });
});

describe('plotIndices', () => {
  it('keeps every sample when they fit', () => {
    expect(plotIndices([1, 2, 3], 10)).toEqual([0, 1, 2]);
  });
  it('thins long series but keeps run ends, gap starts, wraps and the last sample', () => {
    const y = Array.from({ length: 101 }, (_, i) =>
      i >= 40 && i <= 52 ? Number.NaN : i === 70 ? 179 : i === 71 ? -179 : i,
    );
    const idx = plotIndices(y, 10);
    expect(idx.length).toBeLessThan(30);
    for (const must of [0, 39, 40, 53, 70, 71, 100]) expect(idx).toContain(must);
  });
});
