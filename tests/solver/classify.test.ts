/**
 * classify: Grashof test, linkage type, Barker class (as tabulated in Norton) and the input range,
 * whose limits are checked against the oracle's acos formulas (tests/oracle/reference.ts) with the
 * limit's own conditioning as tolerance (tests/oracle/tolerance.ts limitTolerance).
 */
import { describe, expect, it } from 'vitest';
import type { InputRange, Linkage, LinkageType } from '../../src/solver';
import { classify } from '../../src/solver';
import { angleDiff, deg, referenceLimits } from '../oracle/reference';
import { limitTolerance } from '../oracle/tolerance';
import { CASES } from './helpers';

interface Expected {
  name: string;
  l: Linkage;
  barker: string;
  /** The mapping: I-1 double-crank, I-2 crank-rocker, I-3 and I-4 double-rocker (the crank input cannot turn fully). */
  type: LinkageType;
  grashof?: boolean;
  crank?: boolean;
}

const table: Expected[] = [
  { name: 'case 1 (6, 2, 5, 5)', l: CASES[1], barker: 'I-2 GCRR', type: 'crank-rocker', grashof: true, crank: true },
  {
    name: 'case 2 (4, 1, 3, 2+1e-9)',
    l: CASES[2],
    barker: 'I-2 GCRR',
    type: 'crank-rocker',
    grashof: true,
    crank: true,
  },
  {
    name: 'case 3 (5, 1, 6, 2+1e-9)',
    l: CASES[3],
    barker: 'I-2 GCRR',
    type: 'crank-rocker',
    grashof: true,
    crank: true,
  },
  { name: 'case 4 (4, 1, 3, 2)', l: CASES[4], barker: 'III-2 SCRR', type: 'change-point' },
  {
    name: 'case 5 (4, 1, 3, 2+1e-12)',
    l: CASES[5],
    barker: 'I-2 GCRR',
    type: 'crank-rocker',
    grashof: true,
    crank: true,
  },
  {
    name: 'case 6 (4, 1, 3, 2-1e-12)',
    l: CASES[6],
    barker: 'II-1 RRR1',
    type: 'triple-rocker',
    grashof: false,
    crank: false,
  },
  { name: 'case 7 parallelogram (4, 2, 4, 2)', l: CASES[7], barker: 'III-5 S2X', type: 'change-point' },
  { name: 'case 8 kite (2, 2, 4, 4)', l: CASES[8], barker: 'III-5 S2X', type: 'change-point' },
  { name: 'case 9 kite (4, 2, 2, 4)', l: CASES[9], barker: 'III-5 S2X', type: 'change-point' },
  {
    name: 'case 10 (4, 3, 3.5, 3)',
    l: CASES[10],
    barker: 'II-1 RRR1',
    type: 'triple-rocker',
    grashof: false,
    crank: false,
  },
  {
    name: 'case 11 (3, 2.5, 4.2, 1.5)',
    l: CASES[11],
    barker: 'II-3 RRR3',
    type: 'triple-rocker',
    grashof: false,
    crank: false,
  },
  {
    name: 'case 12 (4, 3, 1, 3.5)',
    l: CASES[12],
    barker: 'I-3 GRCR',
    type: 'double-rocker',
    grashof: true,
    crank: false,
  },
  {
    name: 'case 13 (4, 3, 2.5, 2.5)',
    l: CASES[13],
    barker: 'II-1 RRR1',
    type: 'triple-rocker',
    grashof: false,
    crank: false,
  },
  {
    name: 'case 14 (1, 2, sqrt(5.25), 1.5)',
    l: CASES[14],
    barker: 'I-1 GCCC',
    type: 'double-crank',
    grashof: true,
    crank: true,
  },
  {
    name: 'case 15 (1, 1e-6, 1, 1)',
    l: CASES[15],
    barker: 'I-2 GCRR',
    type: 'crank-rocker',
    grashof: true,
    crank: true,
  },
  {
    name: 'case 16 (1e6, 1, 1e6+0.5, 2)',
    l: CASES[16],
    barker: 'I-2 GCRR',
    type: 'crank-rocker',
    grashof: true,
    crank: true,
  },
  {
    name: 'case 17 (case 1 x 1e200)',
    l: { r1: 6e200, r2: 2e200, r3: 5e200, r4: 5e200 },
    barker: 'I-2 GCRR',
    type: 'crank-rocker',
    crank: true,
  },
  {
    name: 'case 18 (case 1 x 1e-200)',
    l: { r1: 6e-200, r2: 2e-200, r3: 5e-200, r4: 5e-200 },
    barker: 'I-2 GCRR',
    type: 'crank-rocker',
    crank: true,
  },
  {
    name: 'case 19 (6, 1e-300, 5, 5)',
    l: CASES[19],
    barker: 'I-2 GCRR',
    type: 'crank-rocker',
    grashof: true,
    crank: true,
  },
  {
    name: 'case 20 (1, 1, 1e-9, 1)',
    l: CASES[20],
    barker: 'I-3 GRCR',
    type: 'double-rocker',
    grashof: true,
    crank: false,
  },
  { name: 'case 21 (10, 1, 2, 3)', l: CASES[21], barker: 'none', type: 'cannot-assemble', crank: false },
  // L = S + P + Q: a flat chain assembles at t2 = 0 only (docs/hard-cases.md case 22), so it is not
  // 'cannot-assemble' (classify, inputRange and sweep agree); S + L > P + Q makes it non-Grashof.
  { name: 'case 22 (6, 1, 2, 3)', l: CASES[22], barker: 'II-1 RRR1', type: 'triple-rocker', crank: false },
  // The Barker classes the table does not cover.
  {
    name: 'output shortest (6, 5, 5, 2)',
    l: { r1: 6, r2: 5, r3: 5, r4: 2 },
    barker: 'I-4 GRRC',
    type: 'double-rocker',
    grashof: true,
    crank: false,
  },
  {
    name: 'input longest (3, 4.2, 2.5, 1.5)',
    l: { r1: 3, r2: 4.2, r3: 2.5, r4: 1.5 },
    barker: 'II-2 RRR2',
    type: 'triple-rocker',
    grashof: false,
    crank: false,
  },
  {
    name: 'output longest (3, 2.5, 1.5, 4.2)',
    l: { r1: 3, r2: 2.5, r3: 1.5, r4: 4.2 },
    barker: 'II-4 RRR4',
    type: 'triple-rocker',
    grashof: false,
    crank: false,
  },
  {
    name: 'change point, ground shortest (1, 3, 2, 4)',
    l: { r1: 1, r2: 3, r3: 2, r4: 4 },
    barker: 'III-1 SCCC',
    type: 'change-point',
  },
  {
    name: 'change point, coupler shortest (3, 2, 1, 4)',
    l: { r1: 3, r2: 2, r3: 1, r4: 4 },
    barker: 'III-3 SRCR',
    type: 'change-point',
  },
  {
    name: 'change point, output shortest (3, 2, 4, 1)',
    l: { r1: 3, r2: 2, r3: 4, r4: 1 },
    barker: 'III-4 SRRC',
    type: 'change-point',
  },
  { name: 'all equal (2, 2, 2, 2)', l: { r1: 2, r2: 2, r3: 2, r4: 2 }, barker: 'III-6 S3X', type: 'change-point' },
  // S + L = 0.1 + 0.7 and P + Q = 0.2 + 0.6 differ only by rounding (3.5e-17 relative, exactly).
  {
    name: 'change point within rounding (0.1, 0.7, 0.2, 0.6)',
    l: { r1: 0.1, r2: 0.7, r3: 0.2, r4: 0.6 },
    barker: 'III-1 SCCC',
    type: 'change-point',
  },
];

/** Whether theta2 (rad, any turn) lies in the range; intervals may extend past pi. */
function inRange(range: InputRange, t2: number): boolean {
  if (range.full) return true;
  return range.intervals.some(({ lo, hi }) => lo + ((((t2 - lo) % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI)) <= hi);
}

/**
 * The range's boundary points (mod 2 pi) are exactly the oracle's limits +-lowerAbs, +-upperAbs
 * (each within the limit's conditioning), and points just inside / outside are classified correctly.
 */
function expectRangeMatchesOracle(l: Linkage): void {
  const lim = referenceLimits(l);
  const range = classify(l).inputRange;
  const expected: { at: number; tol: number }[] = [];
  if (lim.hasLower) {
    const tol = limitTolerance(l, lim.cosLower);
    expected.push({ at: lim.lowerAbs, tol }, { at: -lim.lowerAbs, tol });
  }
  if (lim.hasUpper && lim.upperAbs < Math.PI) {
    const tol = limitTolerance(l, lim.cosUpper);
    expected.push({ at: lim.upperAbs, tol }, { at: -lim.upperAbs, tol });
  }
  const ends = range.intervals.flatMap(({ lo, hi }) => [lo, hi]);
  for (const { lo, hi } of range.intervals) expect(lo).toBeLessThanOrEqual(hi);
  for (const e of expected) {
    const best = Math.min(...ends.map((x) => Math.abs(angleDiff(x, e.at))));
    expect(
      best,
      `limit ${e.at} rad (${(e.at * 180) / Math.PI} deg) of ${JSON.stringify(l)}; got ${JSON.stringify(range)}`,
    ).toBeLessThanOrEqual(e.tol);
  }
  for (const x of ends) {
    if (range.full) break;
    const best = Math.min(...expected.map((e) => Math.abs(angleDiff(x, e.at))));
    expect(best, `endpoint ${x} of ${JSON.stringify(range)} is not a limit`).toBeLessThanOrEqual(
      Math.max(...expected.map((e) => e.tol)),
    );
  }
  // Probe 1e-6 rad on either side of each limit (far beyond the limit tolerances used here).
  for (const e of expected) {
    const inside =
      Math.sign(e.at) * (Math.abs(e.at) + (Math.abs(e.at) === lim.lowerAbs && lim.hasLower ? 1e-6 : -1e-6));
    const outside =
      Math.sign(e.at) * (Math.abs(e.at) + (Math.abs(e.at) === lim.lowerAbs && lim.hasLower ? -1e-6 : 1e-6));
    if (Math.abs(inside) >= lim.lowerAbs && Math.abs(inside) <= lim.upperAbs)
      expect(inRange(range, inside), `inside ${inside}`).toBe(true);
    if (Math.abs(outside) < lim.lowerAbs || Math.abs(outside) > lim.upperAbs)
      expect(inRange(range, outside), `outside ${outside}`).toBe(false);
  }
}

describe('classify', () => {
  it.each(table)('puts $name in Barker class $barker ($type)', ({ l, barker, type, grashof, crank }) => {
    const c = classify(l);
    expect(c.barker).toBe(barker);
    expect(c.type).toBe(type);
    if (grashof !== undefined) expect(c.grashof).toBe(grashof);
    if (crank !== undefined) expect(c.inputIsCrank).toBe(crank);
  });

  it.each(table)('reports S, L, P, Q of $name', ({ l }) => {
    const c = classify(l);
    const sorted = [l.r1, l.r2, l.r3, l.r4].sort((a, b) => a - b);
    expect(c.S).toBe(sorted[0]);
    expect(c.L).toBe(sorted[3]);
    expect([c.P, c.Q].sort((a, b) => a - b)).toEqual([sorted[1], sorted[2]]);
  });

  it('gives a full turn to linkages whose input is a crank', () => {
    for (const k of [1, 2, 3, 5, 14, 15, 16, 19] as const) {
      const r = classify(CASES[k]).inputRange;
      expect(r.full, `case ${k}`).toBe(true);
      expect(r.intervals.length, `case ${k}`).toBe(1);
      expect(r.intervals[0].lo).toBeLessThanOrEqual(-Math.PI + 1e-15);
      expect(r.intervals[0].hi).toBeGreaterThanOrEqual(Math.PI - 1e-15);
    }
  });

  it('limits case 6 to |t2| <= 179.9999094034 deg (an ill-conditioned limit: 7e-9 rad tolerance)', () => {
    const range = classify(CASES[6]).inputRange;
    expect(range.full).toBe(false);
    expect(range.intervals.length).toBe(1);
    expectRangeMatchesOracle(CASES[6]);
    expect(Math.abs(range.intervals[0].hi - deg(179.9999094034))).toBeLessThan(1e-8);
    expect(inRange(range, Math.PI)).toBe(false);
  });

  it('limits case 10 to |t2| <= 135.9513743259 deg', () => {
    const range = classify(CASES[10]).inputRange;
    expect(range.intervals.length).toBe(1);
    expectRangeMatchesOracle(CASES[10]);
    expect(Math.abs(range.intervals[0].hi - deg(135.9513743259))).toBeLessThan(1e-11);
    expect(Math.abs(range.intervals[0].lo + deg(135.9513743259))).toBeLessThan(1e-11);
    expect(inRange(range, deg(136))).toBe(false);
    expect(inRange(range, 0)).toBe(true);
  });

  it('limits case 11 to |t2| >= 57.9494901188 deg, one interval through 180 deg', () => {
    const range = classify(CASES[11]).inputRange;
    expect(range.intervals.length).toBe(1);
    expectRangeMatchesOracle(CASES[11]);
    expect(inRange(range, Math.PI)).toBe(true);
    expect(inRange(range, -Math.PI)).toBe(true);
    expect(inRange(range, deg(57.9494901188 + 1e-6))).toBe(true);
    expect(inRange(range, deg(-57.9494901188 - 1e-6))).toBe(true);
    expect(inRange(range, deg(57.9))).toBe(false);
    expect(inRange(range, 0)).toBe(false);
  });

  it('limits case 12 to t2 in +-[38.6248328731, 78.5848422573] deg (two circuits)', () => {
    const range = classify(CASES[12]).inputRange;
    expect(range.intervals.length).toBe(2);
    expectRangeMatchesOracle(CASES[12]);
    for (const s of [1, -1]) {
      expect(inRange(range, s * deg(60))).toBe(true);
      expect(inRange(range, s * deg(38.6))).toBe(false);
      expect(inRange(range, s * deg(78.6))).toBe(false);
    }
    expect(inRange(range, 0)).toBe(false);
    expect(inRange(range, Math.PI)).toBe(false);
  });

  it('limits case 13 to |t2| <= 90 deg exactly (fl(pi/2) inside)', () => {
    const range = classify(CASES[13]).inputRange;
    expectRangeMatchesOracle(CASES[13]);
    expect(inRange(range, Math.PI / 2)).toBe(true);
    expect(inRange(range, -Math.PI / 2)).toBe(true);
  });

  it('limits case 20 to 60 +- 6.616e-8 deg and its mirror', () => {
    const range = classify(CASES[20]).inputRange;
    expect(range.intervals.length).toBe(2);
    expectRangeMatchesOracle(CASES[20]);
    expect(inRange(range, Math.PI / 3)).toBe(true);
    expect(inRange(range, -Math.PI / 3)).toBe(true);
    expect(inRange(range, Math.PI / 3 + 2e-9)).toBe(false);
    expect(inRange(range, Math.PI / 3 - 2e-9)).toBe(false);
  });

  it('limits the rocker-crank (6, 5, 5, 2) to two circuits', () => {
    const l = { r1: 6, r2: 5, r3: 5, r4: 2 };
    expect(classify(l).inputRange.intervals.length).toBe(2);
    expectRangeMatchesOracle(l);
  });

  it('gives case 21 an empty range', () => {
    const range = classify(CASES[21]).inputRange;
    expect(range.full).toBe(false);
    expect(range.intervals).toEqual([]);
  });

  it('gives case 22 exactly the single point t2 = 0', () => {
    const range = classify(CASES[22]).inputRange;
    expect(range.full).toBe(false);
    expect(range.intervals).toHaveLength(1);
    expect(range.intervals[0].lo).toBe(0);
    expect(range.intervals[0].hi).toBe(0);
  });

  it('matches the oracle limits of the other table cases', () => {
    for (const l of [
      CASES[1],
      CASES[14],
      CASES[15],
      CASES[16],
      CASES[19],
      { r1: 6e200, r2: 2e200, r3: 5e200, r4: 5e200 },
    ]) {
      expectRangeMatchesOracle(l);
    }
  });

  it('is independent of the unit', () => {
    for (const k of [1e-200, 1e-12, 2 ** -30, 1e9, 1e200]) {
      for (const n of [1, 6, 10, 11, 12, 13] as const) {
        const l = CASES[n];
        const a = classify(l);
        const b = classify({ r1: l.r1 * k, r2: l.r2 * k, r3: l.r3 * k, r4: l.r4 * k });
        expect(b.barker, `case ${n} x ${k}`).toBe(a.barker);
        expect(b.type).toBe(a.type);
        expect(b.inputRange.intervals.length).toBe(a.inputRange.intervals.length);
        a.inputRange.intervals.forEach((iv, i) => {
          // The scaled lengths are rounded once (relative 1e-16): limits move by that times their condition.
          expect(Math.abs(b.inputRange.intervals[i].lo - iv.lo)).toBeLessThanOrEqual(1e-8);
          expect(Math.abs(b.inputRange.intervals[i].hi - iv.hi)).toBeLessThanOrEqual(1e-8);
        });
      }
    }
  });

  it('rejects a linkage that is not four positive finite numbers, naming the field and the value', () => {
    expect(() => classify({ r1: 6, r2: 2, r3: -1, r4: 5 })).toThrow('r3 must be a positive finite length, got -1');
    const cases: [Record<string, unknown>, string, RegExp][] = [
      [{ r1: 0, r2: 2, r3: 5, r4: 5 }, 'r1', /\b0\b/],
      [{ r1: 6, r2: NaN, r3: 5, r4: 5 }, 'r2', /NaN/],
      [{ r1: 6, r2: 2, r3: 5, r4: Infinity }, 'r4', /Infinity/],
      [{ r1: 6, r2: 2, r3: 5, r4: -Infinity }, 'r4', /-Infinity/],
      [{ r1: 6, r2: '2', r3: 5, r4: 5 }, 'r2', /2/],
      [{ r1: 6, r2: 2, r3: 'five', r4: 5 }, 'r3', /five/],
      [{ r1: 6, r2: 2, r3: 5 }, 'r4', /undefined|missing/],
      [{ r1: null, r2: 2, r3: 5, r4: 5 }, 'r1', /null/],
      [{ r1: -1e-300, r2: 2, r3: 5, r4: 5 }, 'r1', /-1e-300/],
    ];
    for (const [l, field, value] of cases) {
      let message = '';
      try {
        classify(l as unknown as Linkage);
      } catch (e) {
        expect(e).toBeInstanceOf(Error);
        message = (e as Error).message;
      }
      expect(message, JSON.stringify(l)).toMatch(new RegExp(`\\b${field}\\b`));
      expect(message, JSON.stringify(l)).toMatch(value);
    }
    for (const notALinkage of [null, undefined, 42, 'linkage', []]) {
      expect(() => classify(notALinkage as unknown as Linkage)).toThrow(Error);
    }
  });
});
