import { describe, expect, it } from 'vitest';
import { nearestLimitDeg } from '../../src/study/limits';
import { referencePose } from '../../src/study/reference';
import {
  distanceToNearestLimitDeg,
  GROSS_ERROR_RAD,
  LAB_METHODS,
  runWorkPrecision,
  scoreSweep,
} from '../../src/study/workPrecision';
import { sweep, theta2Grid } from '../../src/solver';
import type { Linkage } from '../../src/solver';
import { referenceAngles } from '../oracle/reference';

const REPORT: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };
const DRAG_LINK: Linkage = { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 };
const now = () => performance.now();

function mulberry32(seed: number): () => number {
  let a = seed;
  return () => {
    a = (a + 0x6d2b79f5) | 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

describe('referencePose', () => {
  it('agrees with the tests’ independent 60-digit oracle to a few ulps on random linkages', () => {
    const rand = mulberry32(7);
    let compared = 0;
    for (let k = 0; k < 60; k++) {
      const l = { r1: 0.2 + 5 * rand(), r2: 0.2 + 5 * rand(), r3: 0.2 + 5 * rand(), r4: 0.2 + 5 * rand() };
      const t2 = (rand() * 2 - 1) * Math.PI;
      for (const sigma of [1, -1] as const) {
        const want = referenceAngles(l, t2, sigma);
        const got = referencePose(l, t2, sigma);
        expect(got === null, `assembly at ${JSON.stringify(l)} ${t2}`).toBe(want === null);
        if (!want || !got || Math.abs(want.sinMu) < 1e-6) continue;
        // Both are rounded once from 40+ digits: they may differ by one rounding of a value near pi.
        expect(Math.abs(got.theta3 - want.theta3)).toBeLessThanOrEqual(4.5e-16);
        expect(Math.abs(got.theta4 - want.theta4)).toBeLessThanOrEqual(4.5e-16);
        compared++;
      }
    }
    expect(compared).toBeGreaterThan(30);
  });
});

describe('scoreSweep', () => {
  it('counts failures, wrong-branch and falsely converged points separately from the error', () => {
    const grid = theta2Grid(0, 360, 30);
    const r = sweep(REPORT, grid, { branch: 'open' });
    const open = [...grid].map((t) => referencePose(REPORT, t, 1));
    const crossed = [...grid].map((t) => referencePose(REPORT, t, -1));
    expect(scoreSweep(r, open, crossed)).toMatchObject({ failures: 0, wrongBranch: 0, falseConvergence: 0 });
    expect(scoreSweep(r, open, crossed).maxError).toBeLessThanOrEqual(1e-15);
    // Scored against the crossed reference, every point is on the "wrong" branch.
    expect(scoreSweep(r, crossed, open).wrongBranch).toBe(grid.length);
    // A reference that says "cannot assemble" turns each ok point into a false convergence.
    expect(
      scoreSweep(
        r,
        open.map(() => null),
        crossed,
      ).falseConvergence,
    ).toBe(grid.length);
    const failed = { ...r, status: r.status.map(() => 'failed' as const) };
    expect(scoreSweep(failed, open, crossed).failures).toBe(grid.length);
  });
});

describe('runWorkPrecision', () => {
  it('traces every method on the report’s linkage; the defaults are full precision and loose tolerances are not', async () => {
    const stages: number[] = [];
    const res = await runWorkPrecision(REPORT, {
      branch: 'open',
      stepDeg: 5,
      now,
      minTimeMs: 1,
      reference: referencePose,
      onProgress: (f) => stages.push(f),
    });
    expect(res).not.toBeNull();
    const r = res!;
    expect(r.series.map((s) => s.method)).toEqual(LAB_METHODS.map((m) => m.method));
    expect(r.series.length).toBeGreaterThanOrEqual(4);
    expect(stages.at(-1)).toBe(1);
    expect(stages.every((f, i) => i === 0 || f >= stages[i - 1])).toBe(true);
    for (const s of r.series) {
      const def = s.points.find((p) => p.tol === null)!;
      expect(def.failures + def.wrongBranch + def.falseConvergence, s.label).toBe(0);
      for (const p of s.points) expect(p.nsPerPoint, `${s.label} ${p.tol}`).toBeGreaterThan(0);
      if (s.method !== 'seed') expect(def.maxError, s.label).toBeLessThanOrEqual(1e-14);
    }
    const seedLoose = r.series.find((s) => s.method === 'seed')!.points.find((p) => p.tol === 1e-3)!;
    expect(seedLoose.maxError).toBeGreaterThan(GROSS_ERROR_RAD);
    expect(r.limitsDeg).toEqual([]);
    expect(r.detJ.every((d) => d > 0)).toBe(true);
    // Smallest transmission-angle sine of 6-2-5-5: mu ranges over [47.16, 106.26] deg.
    expect(r.minSinMu.value).toBeCloseTo(Math.sin((47.16 * Math.PI) / 180), 3);
  });

  it('shows the report’s NR jumping branch on a drag link where every project method stays put', async () => {
    const r = (await runWorkPrecision(DRAG_LINK, {
      branch: 'open',
      stepDeg: 2,
      now,
      minTimeMs: 1,
      reference: referencePose,
    }))!;
    const seed = r.series.find((s) => s.method === 'seed')!.points.find((p) => p.tol === null)!;
    expect(seed.wrongBranch + seed.failures).toBeGreaterThan(0);
    for (const s of r.series.filter((x) => x.method !== 'seed')) {
      const def = s.points.find((p) => p.tol === null)!;
      expect(def.wrongBranch + def.failures + def.falseConvergence, s.label).toBe(0);
    }
  });

  it('reports the input limits of a triple rocker and never counts a point past them as converged', async () => {
    const l = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
    const r = (await runWorkPrecision(l, { branch: 'open', stepDeg: 5, now, minTimeMs: 1, reference: referencePose }))!;
    expect(r.limitsDeg.map((d) => Math.abs(d))).toEqual(
      [135.9513743259, 135.9513743259].map((x) => expect.closeTo(x, 8)),
    );
    for (const s of r.series.filter((x) => x.method !== 'seed')) {
      for (const p of s.points) expect(p.falseConvergence, `${s.label} ${p.tol}`).toBe(0);
    }
  });

  it('resolves to null when cancelled between stages', async () => {
    let calls = 0;
    const r = await runWorkPrecision(REPORT, {
      branch: 'open',
      now,
      reference: referencePose,
      pause: async () => {
        calls++;
      },
      isCancelled: () => calls >= 3,
    });
    expect(r).toBeNull();
    expect(calls).toBe(3);
  });
});

describe('distanceToNearestLimitDeg', () => {
  it('measures around the circle and is infinite without limits', () => {
    expect(distanceToNearestLimitDeg(10, [])).toBe(Infinity);
    expect(distanceToNearestLimitDeg(170, [-170])).toBeCloseTo(20, 12);
    expect(distanceToNearestLimitDeg(0, [135, -135])).toBeCloseTo(135, 12);
  });
});

describe('nearestLimitDeg', () => {
  it('names the nearest limit and its distance, or null without limits', () => {
    expect(nearestLimitDeg(10, [])).toBeNull();
    expect(nearestLimitDeg(130, [135.95, -135.95])).toEqual({
      distanceDeg: expect.closeTo(5.95, 12),
      limitDeg: 135.95,
    });
    expect(nearestLimitDeg(-170, [135.95, -135.95])).toEqual({
      distanceDeg: expect.closeTo(34.05, 12),
      limitDeg: -135.95,
    });
  });
});
