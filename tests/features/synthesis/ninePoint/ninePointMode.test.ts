import { csvParse } from 'd3-dsv';
import { describe, expect, it } from 'vitest';
import type { NineClassFacts } from '../../../../src/features/synthesis/ninePoint/nineClassFacts';
import { NO_FILTERS, filterClasses } from '../../../../src/features/synthesis/ninePoint/nineClassFacts';
import { NINE_CSV_COLUMNS, ninePointCsv } from '../../../../src/features/synthesis/ninePoint/nineCsv';
import { nineRefusalText } from '../../../../src/features/synthesis/ninePoint/nineInput';
import { WMS_PROBLEM_3 } from '../../../../src/features/synthesis/ninePoint/wmsProblem3';
import { ninePointMessagesEn } from '../../../../src/features/synthesis/ninePoint/ninePointMessagesEn';
import { nineResultOf, nineSlices } from '../../../../src/features/synthesis/ninePoint/useNinePointSynthesis';
import type { NinePointClass, NinePointLinkage, NinePointResult } from '../../../../src/synthesis';
import { NINE_POINT_PATHS } from '../../../../src/synthesis';

const nt = ninePointMessagesEn;

/** A linkage with given lengths (the list and CSV read only these fields). */
function linkage(r1: number, i: number): NinePointLinkage {
  return {
    links: { r1, r2: 0.5, r3: 1.25, r4: 1 },
    branch: 'open',
    O2: { x: i, y: -i },
    groundAngle: 0.25,
    pDist: 0.75,
    pAngle: 0.5,
    theta2: Array.from({ length: 9 }, (_, k) => 0.125 * k),
    branches: Array(9).fill(i % 2 === 0 ? 'open' : 'crossed'),
  };
}

function cls(grashof: boolean, defects: NinePointClass['defects'], i: number): NinePointClass {
  return { cognates: [linkage(1 + i, i), linkage(2 + i, i + 10), linkage(3 + i, i + 20)], grashof, defects };
}

function facts(size: number, crank: boolean, muMinDeg: number): NineClassFacts {
  return { cognates: [], sizes: [size], size, crank, muMinDeg };
}

describe('nineSlices', () => {
  it('deals every start path to exactly one slice, in order', () => {
    const s = nineSlices(NINE_POINT_PATHS, 32);
    expect(s[0].start).toBe(0);
    expect(s.at(-1)!.end).toBe(NINE_POINT_PATHS);
    s.forEach((x, i) => {
      expect(x.end - x.start).toBeGreaterThan(0);
      expect(x.end - x.start).toBeLessThanOrEqual(32);
      if (i > 0) expect(x.start).toBe(s[i - 1].end);
    });
  });
});

describe('nineResultOf', () => {
  it('counts every start path in total, so a cancelled run shows the untracked ones', () => {
    const a: NinePointResult = { classes: [cls(true, [], 0)], paths: { total: 32, finished: 31, failed: 1 } };
    const b: NinePointResult = { classes: [], paths: { total: 32, finished: 32, failed: 0 } };
    const r = nineResultOf([a, b], NINE_POINT_PATHS);
    expect(r.paths).toEqual({ total: NINE_POINT_PATHS, finished: 63, failed: 1, retracked: 0 });
    expect(r.classes.length).toBe(1);
  });
});

describe('filterClasses', () => {
  const classes = [
    cls(true, ['circuit'], 0),
    cls(false, [], 1),
    cls(true, ['branch'], 2),
    cls(true, ['order', 'branch'], 3),
  ];
  const f = [facts(3, true, 20), facts(1, false, 40), facts(2, true, NaN), facts(0.5, false, 10)];

  it('keeps every class in the order found without filters', () => {
    expect(filterClasses(classes, f, NO_FILTERS)).toEqual([0, 1, 2, 3]);
  });

  it('keeps Grashof, crank-driven, and circuit- and order-free classes (a branch defect alone is kept)', () => {
    expect(filterClasses(classes, f, { ...NO_FILTERS, grashof: true })).toEqual([0, 2, 3]);
    expect(filterClasses(classes, f, { ...NO_FILTERS, crank: true })).toEqual([0, 2]);
    expect(filterClasses(classes, f, { ...NO_FILTERS, noDefect: true })).toEqual([1, 2]);
    expect(filterClasses(classes, f, { ...NO_FILTERS, grashof: true, crank: true, noDefect: true })).toEqual([2]);
  });

  it('bounds the size (inclusive) and sorts by size or by transmission angle (unknown last)', () => {
    expect(filterClasses(classes, f, { ...NO_FILTERS, maxSize: 2 })).toEqual([1, 2, 3]);
    expect(filterClasses(classes, f, { ...NO_FILTERS, sort: 'size' })).toEqual([3, 1, 2, 0]);
    expect(filterClasses(classes, f, { ...NO_FILTERS, sort: 'transmission' })).toEqual([1, 0, 3, 2]);
  });
});

describe('nineRefusalText', () => {
  it('names the count, the coinciding points (1-based) and their place, a line and a circle', () => {
    expect(nineRefusalText(WMS_PROBLEM_3, nt)).toBeNull();
    expect(nineRefusalText(WMS_PROBLEM_3.slice(0, 8), nt)).toBe(
      'Nine points needs exactly 9 target points; there are 8.',
    );
    expect(nineRefusalText([...WMS_PROBLEM_3.slice(0, 8), { x: 0.8, y: 0.7 }], nt)).toBe(
      'Points 3 and 9 coincide at (0.8, 0.7): nine distinct points are needed.',
    );
    const line = Array.from({ length: 9 }, (_, k) => ({ x: k, y: 1 - k }));
    expect(nineRefusalText(line, nt)).toMatch(/one line/);
    const circle = Array.from({ length: 9 }, (_, k) => ({ x: 2 * Math.cos(k), y: 2 * Math.sin(k) }));
    expect(nineRefusalText(circle, nt)).toMatch(/one circle/);
  });
});

describe('ninePointCsv', () => {
  it('writes one row per linkage with the columns named, numbers reading back exactly', () => {
    const rows = csvParse(ninePointCsv([cls(true, ['order', 'branch'], 1), cls(false, [], 2)]));
    expect(rows.columns).toEqual([...NINE_CSV_COLUMNS]);
    expect(rows.length).toBe(6);
    expect(rows.map((r) => `${r.class}.${r.cognate}`)).toEqual(['1.1', '1.2', '1.3', '2.1', '2.2', '2.3']);
    expect(Number(rows[1].r1)).toBe(3);
    expect(rows[0].defects).toBe('order branch');
    expect(rows[0].branch).toBe('crossed');
    // θ2 in degrees: 0.125 rad × 8 at the ninth point.
    expect(Number(rows[0].theta2_9_deg)).toBeCloseTo((180 / Math.PI) * 1, 12);
  });
});
