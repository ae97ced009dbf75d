import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { adaptiveGrid, adaptiveSweep, classify, solveClosedForm } from '../../src/solver';
import { referenceLimits } from '../oracle/reference';

const REPORT = { r1: 6, r2: 2, r3: 5, r4: 5 };
const TRIPLE_ROCKER = { r1: 4, r2: 3, r3: 3.5, r4: 3 }; // hard case 10: |t2| <= 135.9513743259 deg
const DOUBLE_ROCKER = { r1: 4, r2: 3, r3: 1, r4: 3.5 }; // hard case 12: two windows

describe('adaptiveGrid', () => {
  it('puts one sample per pixel on a benign crank-rocker and nothing more', () => {
    const g = adaptiveGrid(REPORT, { pixels: 500 });
    expect(g.length).toBe(501);
    expect(g[0]).toBe(0);
    expect(g[g.length - 1]).toBe(2 * Math.PI);
    for (let i = 1; i < g.length; i++) expect(g[i]).toBeGreaterThan(g[i - 1]);
  });

  it('contains the exact input limits of a triple rocker, as the oracle computes them', () => {
    const g = adaptiveGrid(TRIPLE_ROCKER, { pixels: 400 });
    const lim = referenceLimits(TRIPLE_ROCKER);
    const limits = classify(TRIPLE_ROCKER).inputRange.intervals.flatMap((iv) => [iv.hi, iv.lo + 2 * Math.PI]);
    for (const t of limits) {
      const nearest = Math.min(...Array.from(g, (x) => Math.abs(x - t)));
      expect(nearest).toBe(0);
    }
    // The limit the grid carries agrees with the 60-digit oracle's (acos conditioning: ~1e-15 rad here).
    expect(lim.hasUpper).toBe(true);
    expect(Math.abs(limits[0] - lim.upperAbs)).toBeLessThan(1e-13);
  });

  it('refines towards each limit, where the angles move like the square root of the distance', () => {
    const g = adaptiveGrid(TRIPLE_ROCKER, { pixels: 400 });
    const hi = classify(TRIPLE_ROCKER).inputRange.intervals[0].hi;
    const inside = Array.from(g).filter((t) => t < hi && t > hi - 0.01);
    // Uniform spacing would give one sample in the last 0.01 rad; the refinement gives many, down to ~1e-9.
    expect(inside.length).toBeGreaterThan(8);
    expect(hi - Math.max(...inside)).toBeLessThan(1e-8);
    for (const t of inside) expect(solveClosedForm(TRIPLE_ROCKER, t, 'open')).not.toBeNull();
  });

  it('keeps both windows of a Grashof double rocker and the gap between them', () => {
    const r = adaptiveSweep(DOUBLE_ROCKER, { branch: 'open', pixels: 360 });
    const ok = r.status.filter((s) => s === 'ok').length;
    expect(ok).toBeGreaterThan(40);
    expect(r.status.filter((s) => s === 'unreachable').length).toBeGreaterThan(200);
    expect(r.refinedCount).toBeGreaterThan(0);
    for (let i = 0; i < r.status.length; i++) {
      if (r.status[i] === 'ok') expect(Number.isFinite(r.theta3[i]) && Number.isFinite(r.theta4[i])).toBe(true);
      else expect(Number.isNaN(r.theta3[i])).toBe(true);
    }
  });

  it('bisects where a curve turns fast near a toggle and respects the point cap', () => {
    const nearToggle = { r1: 5, r2: 1, r3: 6, r4: 2 + 1e-9 }; // hard case 3: mu near 0 at t2 = 0
    const g = adaptiveGrid(nearToggle, { pixels: 100, maxJumpRad: 0.01, maxPoints: 300 });
    expect(g.length).toBeGreaterThan(101);
    expect(g.length).toBeLessThanOrEqual(300);
  });

  it('throws for a bad linkage or range, naming the value', () => {
    expect(() => adaptiveGrid({ r1: 6, r2: -2, r3: 5, r4: 5 }, { pixels: 10 })).toThrow(
      'r2 must be a positive finite length, got -2',
    );
    expect(() => adaptiveGrid(REPORT, { pixels: 10, startRad: 1, endRad: 1 })).toThrow(/endRad/);
  });

  it('never hangs: any options either throw an Error naming the option or give finite increasing samples in range', () => {
    const num = fc.oneof(
      fc.double({ noNaN: false }),
      fc.constantFrom(Infinity, -Infinity, 1.79e308, -1.79e308, 0, -1, 1e6, -1e6, 2 * Math.PI),
    );
    const linkage = fc.constantFrom(REPORT, TRIPLE_ROCKER, DOUBLE_ROCKER, { r1: 6, r2: 1, r3: 2, r4: 3 });
    const opts = fc.record(
      {
        startRad: num,
        endRad: num,
        pixels: fc.oneof(num, fc.integer({ min: 1, max: 2000 })),
        maxJumpRad: num,
        maxPoints: fc.oneof(num, fc.integer({ min: 1, max: 5000 })),
      },
      { requiredKeys: [] },
    );
    fc.assert(
      fc.property(linkage, opts, (l, o) => {
        let g: Float64Array;
        try {
          g = adaptiveGrid(l, o);
        } catch (e) {
          expect(e).toBeInstanceOf(Error);
          expect((e as Error).message).toMatch(/startRad|endRad|pixels|maxJumpRad|maxPoints/);
          return;
        }
        const start = o.startRad ?? 0;
        const end = o.endRad ?? 2 * Math.PI;
        expect(g[0]).toBe(start);
        expect(g[g.length - 1]).toBe(end);
        for (let i = 1; i < g.length; i++) expect(g[i]).toBeGreaterThan(g[i - 1]);
        for (const x of g) expect(Number.isFinite(x)).toBe(true);
        expect(g.length).toBeLessThanOrEqual(Math.max(o.maxPoints ?? 0, 8 * 100_001) + 200);
      }),
      { seed: 7201, numRuns: 150 },
    );
  });

  it('carries the limit angles of every turn of a long range (not only two turns either side)', () => {
    const g = adaptiveGrid(TRIPLE_ROCKER, { pixels: 2000, startRad: 1000, endRad: 1100 });
    const hi = classify(TRIPLE_ROCKER).inputRange.intervals[0].hi;
    const turns = Math.floor((1100 - hi) / (2 * Math.PI)) - Math.ceil((1000 - hi) / (2 * Math.PI)) + 1;
    const found = Array.from(g).filter(
      (x) => Math.abs(x - hi - 2 * Math.PI * Math.round((x - hi) / (2 * Math.PI))) === 0,
    );
    expect(turns).toBeGreaterThan(10);
    expect(found.length).toBeGreaterThanOrEqual(turns - 1);
  });
});
