import { describe, expect, it } from 'vitest';
import type { LabPoint, LabSeries } from '../../../src/study/workPrecision';
import {
  ERROR_FLOOR,
  METHOD_COLORS,
  formatErrorTick,
  formatTimeTick,
  formatTol,
  shownTol,
  hasTrouble,
  orderedCurvePoints,
  placePointLabels,
  plottedError,
  workPrecisionDomains,
  workPrecisionDrawing,
  workPrecisionFrame,
  WORK_PRECISION_SIZE,
  FAILURE_COLOR,
} from '../../../src/features/lab/workPrecisionChart';
import { fakeSvg } from '../../shared/charts/fakeSvgDom';
import { legendLayout } from '../../../src/shared/charts/chartFrame';
import { chartSize, plotArea } from '../../../src/shared/charts/chart';

function pt(tol: number | null, nsPerPoint: number, maxError: number, failures = 0): LabPoint {
  return {
    tol,
    nsPerPoint,
    maxError,
    p99Error: maxError,
    failures,
    wrongBranch: 0,
    falseConvergence: 0,
    itersPerPoint: 1,
  };
}

describe('formatTol', () => {
  it('writes the default as text and tolerances in short exponent form', () => {
    expect(formatTol(null)).toBe('default');
    expect(formatTol(null, 'Vorgabe')).toBe('Vorgabe');
    expect(formatTol(1e-6)).toBe('1e-6');
    expect(formatTol(1e-15)).toBe('1e-15');
    expect(formatTol(2.5e-9)).toBe('2.5e-9');
    expect(formatTol(1e3)).toBe('1e3');
  });
});

describe('shownTol', () => {
  it('writes a shown tolerance with U+2212 in its exponent, like the max errors beside it (formatSci)', () => {
    expect(shownTol(1e-6)).toBe('1e\u22126');
    expect(shownTol(2.5e-9)).toBe('2.5e\u22129');
    expect(shownTol(null, 'Vorgabe')).toBe('Vorgabe');
    expect(shownTol(1e-12)).not.toContain('-');
  });
});

describe('plottedError', () => {
  it('puts exact zeros and tiny errors on the floor and keeps NaN out', () => {
    expect(plottedError(0)).toBe(ERROR_FLOOR);
    expect(plottedError(1e-20)).toBe(ERROR_FLOOR);
    expect(plottedError(3e-10)).toBe(3e-10);
    expect(Number.isNaN(plottedError(NaN))).toBe(true);
  });
});

describe('hasTrouble', () => {
  it('flags failures, wrong branches and false convergence', () => {
    expect(hasTrouble(pt(1e-3, 100, 1e-3))).toBe(false);
    expect(hasTrouble(pt(1e-3, 100, 1e-3, 2))).toBe(true);
    expect(hasTrouble({ ...pt(1e-3, 100, 1e-3), wrongBranch: 1 })).toBe(true);
    expect(hasTrouble({ ...pt(1e-3, 100, 1e-3), falseConvergence: 1 })).toBe(true);
  });
});

describe('orderedCurvePoints', () => {
  it('traces tolerances loosest first and keeps the default apart', () => {
    const s: LabSeries = {
      method: 'newton',
      label: 'NR',
      points: [
        pt(null, 300, 1e-15),
        pt(1e-9, 200, 1e-9),
        pt(1e-3, 150, 1e-3),
        pt(1e-15, 250, 1e-15),
        pt(1e-6, 180, 1e-6),
      ],
    };
    const c = orderedCurvePoints(s);
    expect(c.traced.map((p) => p.tol)).toEqual([1e-3, 1e-6, 1e-9, 1e-15]);
    expect(c.defaultPoint?.nsPerPoint).toBe(300);
  });

  it('keeps NaN points in the trace (they become gaps) but drops a NaN default', () => {
    const s: LabSeries = {
      method: 'seed',
      label: 'seed',
      points: [pt(null, 100, NaN), pt(1e-6, 90, NaN), pt(1e-3, 80, 1e-3)],
    };
    const c = orderedCurvePoints(s);
    expect(c.traced).toHaveLength(2);
    expect(Number.isNaN(c.traced[1].maxError)).toBe(true);
    expect(c.defaultPoint).toBeNull();
  });

  it('gives a method with only its default a single marker and no curve', () => {
    const c = orderedCurvePoints({ method: 'closed-form', label: 'CF', points: [pt(null, 50, 4e-16)] });
    expect(c.traced).toEqual([]);
    expect(c.defaultPoint?.maxError).toBe(4e-16);
  });
});

describe('workPrecisionDomains', () => {
  it('pads errors to whole decades and times to 1-2-5 bounds', () => {
    const series: LabSeries[] = [
      { method: 'closed-form', label: '', points: [pt(null, 164, 4.4e-16)] },
      { method: 'newton', label: '', points: [pt(1e-3, 1029, 0.0508), pt(1e-9, 341, 2.5e-7)] },
    ];
    const d = workPrecisionDomains(series);
    expect(d.x).toEqual([100, 2000]);
    expect(d.y[0]).toBeCloseTo(1e-16, 30);
    expect(d.y[1]).toBeCloseTo(0.1, 15);
  });

  it('reaches below the floor when an error is exactly zero, and ignores NaN points', () => {
    const d = workPrecisionDomains([
      { method: 'newton', label: '', points: [pt(1e-3, 100, 0), pt(1e-6, 1e9, NaN), pt(1e-9, 300, 1e-3)] },
    ]);
    expect(d.y[0]).toBeLessThan(ERROR_FLOOR);
    expect(d.x[1]).toBeLessThan(1e4);
  });

  it('shows at least a decade of time when every method takes about the same', () => {
    const d = workPrecisionDomains([
      { method: 'newton', label: '', points: [pt(1e-3, 300, 1e-3), pt(1e-6, 320, 1e-6)] },
    ]);
    expect(d.x[1] / d.x[0]).toBeGreaterThanOrEqual(10);
    expect(d.x[0]).toBeLessThan(300);
    expect(d.x[1]).toBeGreaterThan(320);
  });

  it('falls back to fixed ranges without data', () => {
    expect(workPrecisionDomains([])).toEqual({ x: [10, 10000], y: [ERROR_FLOOR, 1] });
  });
});

describe('tick formats', () => {
  it('writes times as plain numbers and errors as powers with a typographic minus', () => {
    expect(formatTimeTick(500)).toBe('500');
    expect(formatTimeTick(2000)).toBe('2000');
    expect(formatTimeTick(1e6)).toBe('1e6');
    expect(formatErrorTick(1e-16)).toBe('1e\u221216');
    expect(formatErrorTick(0.01)).toBe('1e\u22122');
    expect(formatErrorTick(5e-3)).toBe('5e\u22123');
  });
});

describe('placePointLabels', () => {
  const inside = (b: { x: number; w: number }, W: number) => b.x >= 0 && b.x + b.w <= W;

  it('puts a label to the right of its point when there is room', () => {
    const [p] = placePointLabels([{ x: 50, y: 50, w: 20, h: 10 }], [], 200, 100);
    expect(p).toEqual({ x: 57, y: 53.75, anchor: 'start' });
  });

  it('moves to the left at the right edge and skips spots taken by earlier labels', () => {
    const [a] = placePointLabels([{ x: 195, y: 50, w: 20, h: 10 }], [], 200, 100);
    expect(a?.anchor).toBe('end');
    expect(inside({ x: (a?.x ?? 0) - 20, w: 20 }, 200)).toBe(true);
    const [b, c] = placePointLabels(
      [
        { x: 50, y: 50, w: 20, h: 10 },
        { x: 50, y: 50, w: 20, h: 10 },
      ],
      [],
      200,
      100,
    );
    expect(b?.anchor).toBe('start');
    expect(c?.anchor).toBe('end');
  });

  it('avoids obstacles and gives up when every spot is blocked', () => {
    const [p] = placePointLabels([{ x: 50, y: 50, w: 20, h: 10 }], [{ x0: 52, y0: 40, x1: 80, y1: 60 }], 200, 100);
    expect(p?.anchor).not.toBe('start');
    const [q] = placePointLabels([{ x: 50, y: 50, w: 20, h: 10 }], [{ x0: 0, y0: 0, x1: 200, y1: 100 }], 200, 100);
    expect(q).toBeNull();
  });
});

/**
 * The placement rule written out on its own, as the oracle: the eight spots in order, the first whose text lies
 * inside the plot and whose box (3 px of air across, 1 px up and down) overlaps no obstacle and no earlier box.
 */
function referencePlace(
  items: { x: number; y: number; w: number; h: number }[],
  obstacles: { x0: number; y0: number; x1: number; y1: number }[],
  width: number,
  height: number,
  gap = 7,
) {
  const taken = [...obstacles];
  return items.map(({ x, y, w, h }) => {
    const asc = 0.75 * h;
    const desc = 0.25 * h;
    const d = gap * 0.7;
    const spots = [
      [x + gap, y + asc / 2, 'start'],
      [x - gap, y + asc / 2, 'end'],
      [x, y - gap - desc, 'middle'],
      [x, y + gap + asc, 'middle'],
      [x + d, y - d, 'start'],
      [x + d, y + d + asc, 'start'],
      [x - d, y - d, 'end'],
      [x - d, y + d + asc, 'end'],
    ] as const;
    for (const [sx, sy, anchor] of spots) {
      const left = anchor === 'start' ? sx : anchor === 'end' ? sx - w : sx - w / 2;
      if (left < 0 || left + w > width || sy - asc < 0 || sy + desc > height) continue;
      const box = { x0: left - 3, y0: sy - asc - 1, x1: left + w + 3, y1: sy + desc + 1 };
      if (taken.some((t) => box.x0 < t.x1 && t.x0 < box.x1 && box.y0 < t.y1 && t.y0 < box.y1)) continue;
      taken.push(box);
      return { x: sx, y: sy, anchor };
    }
    return null;
  });
}

describe('placePointLabels against the rule written out (random crowds of labels and obstacles)', () => {
  it('places every label where the rule does, or drops it where the rule does', () => {
    let seed = 12345;
    const rand = () => (seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648;
    for (let trial = 0; trial < 300; trial++) {
      const W = 150 + 200 * rand();
      const H = 80 + 120 * rand();
      const items = Array.from({ length: 1 + Math.floor(12 * rand()) }, () => ({
        x: W * rand(),
        y: H * rand(),
        w: 10 + 40 * rand(),
        h: 8 + 6 * rand(),
      }));
      const obstacles = Array.from({ length: Math.floor(5 * rand()) }, () => {
        const x0 = W * rand();
        const y0 = H * rand();
        return { x0, y0, x1: x0 + 30 * rand(), y1: y0 + 20 * rand() };
      });
      const got = placePointLabels(items, obstacles, W, H);
      const want = referencePlace(items, obstacles, W, H);
      for (let i = 0; i < items.length; i++) {
        if (want[i] === null) expect(got[i]).toBeNull();
        else {
          expect(got[i]?.anchor).toBe(want[i]!.anchor);
          expect(got[i]!.x).toBeCloseTo(want[i]!.x, 9);
          expect(got[i]!.y).toBeCloseTo(want[i]!.y, 9);
        }
      }
    }
  });
});

describe('legendLayout', () => {
  it('wraps entries into rows no wider than the space', () => {
    const rows = legendLayout([100, 100, 100], 300).map((p) => p[1]);
    expect(rows).toEqual([0, 0, 1]);
    expect(legendLayout([500], 300)).toEqual([[0, 0]]);
  });
});

describe('METHOD_COLORS', () => {
  it('gives the five lab methods five different colours', () => {
    const ids = ['closed-form', 'closed-form-polish', 'newton', 'newton-no-predictor', 'seed'] as const;
    expect(new Set(ids.map((id) => METHOD_COLORS[id])).size).toBe(5);
  });
});

describe('workPrecisionDrawing', () => {
  const series: LabSeries[] = [
    { method: 'newton', label: 'NR', points: [pt(1e-3, 200, 1e-4), pt(1e-9, 400, 1e-10), pt(null, 300, 1e-12, 1)] },
    { method: 'closed-form', label: 'closed form', points: [pt(null, 50, 0)] },
  ];
  const options = { title: 'Work-precision diagram', xLabel: 'ns', yLabel: 'rad' };

  it('traces a method over its tolerances, marks defaults and trouble, rings the chosen point and labels tolerances', () => {
    const svg = fakeSvg();
    workPrecisionDrawing(series, { ...options, highlight: { method: 'newton', tol: 1e-9 } })(svg, 640, 400);
    expect(svg.querySelectorAll('g.lines path')).toHaveLength(1);
    const marks = [...svg.querySelectorAll('g.markers path')];
    expect(marks).toHaveLength(4);
    // Defaults (diamonds) are drawn first, so traced dots stay on top.
    expect(marks.map((m) => m.getAttribute('data-tol'))).toEqual(['default', 'default', '1e-3', '1e-9']);
    expect(marks.filter((m) => m.getAttribute('stroke') === FAILURE_COLOR)).toHaveLength(1);
    expect(svg.querySelectorAll('g.highlight circle')).toHaveLength(1);
    expect([...svg.querySelectorAll('g.tol-labels text')].map((t) => t.textContent)).toContain('1e\u22129');
    // The exact zero of the closed form sits on the dashed floor.
    expect(svg.querySelectorAll('g.grid-y line.floor')).toHaveLength(1);
    expect(svg.querySelector('text.title')?.textContent).toBe('Work-precision diagram');
  });

  it('leaves the tolerance labels out when asked, and shows the empty text without data', () => {
    const svg = fakeSvg();
    workPrecisionDrawing(series, { ...options, tolLabels: false })(svg, 640, 400);
    expect(svg.querySelectorAll('g.tol-labels text')).toHaveLength(0);
    const empty = fakeSvg();
    workPrecisionDrawing([], { ...options, emptyText: 'Run…' })(empty, 640, 400);
    expect(empty.querySelector('text.empty')?.textContent).toBe('Run…');
    expect(empty.querySelector('g.plot')?.getAttribute('display')).toBe('none');
  });
});

describe('workPrecisionFrame', () => {
  const series: LabSeries[] = [
    { method: 'newton', label: 'NR', points: [pt(1e-3, 200, 1e-4), pt(1e-9, 400, 1e-10)] },
    { method: 'closed-form', label: 'closed form', points: [pt(null, 50, 0)] },
  ];
  it('ticks the error floor at every height, so its ≤ label is always shown', () => {
    for (const height of [160, 200, 240, 300, 400, 600]) {
      const plot = plotArea(chartSize({ ...WORK_PRECISION_SIZE, width: 640, height }));
      const f = workPrecisionFrame({ series }, plot);
      expect(f.yFloor).toBe(ERROR_FLOOR);
      expect(f.yTicks).toContain(ERROR_FLOOR);
    }
    const svg = fakeSvg();
    workPrecisionDrawing(series, { title: 't', xLabel: 'x', yLabel: 'y' })(svg, 640, 240);
    const labels = [...svg.querySelectorAll('g.axis-y .tick text')].map((t) => t.textContent);
    expect(labels).toContain('≤1e\u221217');
  });
});
