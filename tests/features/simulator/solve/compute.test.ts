import { describe, expect, it } from 'vitest';
import {
  VIEW_SAMPLES_MAX,
  computeCycle,
  computePoint,
  computeTable,
} from '../../../../src/features/simulator/solve/compute';
import { decodeStatuses } from '../../../../src/shared/pointStatusCodes';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };
const C = { distance: 2.5, angleRad: Math.PI / 6 };
const D = Math.PI / 180;
/** What a cycle request needs besides its linkage: the full app's defaults (both branches, curves, no plot samples). */
const NEEDS = {
  solver: { method: 'newton' as const, tol: null },
  branch: 'open' as const,
  otherBranch: true,
  curves: true,
};
const POINT_NEEDS = { solver: { method: 'newton' as const, tol: null }, ghost: true, newton: true };

describe('computeCycle', () => {
  it('sweeps 361 points from 0 to 360 degrees on both branches of the report case', () => {
    const r = computeCycle({ linkage: L, samples: 360, coupler: C, ...NEEDS });
    expect(r.theta2Deg.length).toBe(361);
    expect(r.theta2Deg[0]).toBe(0);
    expect(r.theta2Deg[360]).toBe(360);
    expect(r.open.okCount).toBe(361);
    expect(r.crossed.okCount).toBe(361);
    // Hard case 1 at theta2 = 90 deg (60-digit reference; 1e-9 rad is far below what a plot shows).
    expect(r.open.theta3[90] / D).toBeCloseTo(32.3335306935, 7);
    expect(r.open.theta4[90] / D).toBeCloseTo(110.7965716607, 7);
    expect(r.crossed.theta3[90] / D).toBeCloseTo(-69.2034283393, 7);
    expect(r.classification.type).toBe('crank-rocker');
    expect(r.curves.map((c) => c.branch)).toEqual(['open', 'crossed']);
  });

  it('marks the unreachable inputs of a triple rocker with a status and NaN angles', () => {
    const r = computeCycle({ linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 }, samples: 360, coupler: C, ...NEEDS });
    expect(decodeStatuses(r.open.statusCodes)[180]).toBe('unreachable');
    expect(Number.isNaN(r.open.theta3[180])).toBe(true);
  });

  it('reports a linkage that cannot assemble anywhere without throwing', () => {
    const r = computeCycle({
      linkage: { r1: 10, r2: 1, r3: 2, r4: 3 },
      samples: 36,
      coupler: C,
      ...NEEDS,
    });
    expect(r.open.okCount).toBe(0);
    expect(r.classification.type).toBe('cannot-assemble');
    expect(r.curves).toHaveLength(0);
  });
});

describe('computePoint', () => {
  it('solves the pose, the ghost and both NR runs', () => {
    const r = computePoint({
      linkage: L,
      branch: 'open',
      theta2Rad: 90 * D,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
    });
    expect(r.pose?.theta3).toBeCloseTo(32.3335306935 * D, 9);
    expect(r.ghost?.theta4).toBeCloseTo(-147.6664693065 * D, 9);
    expect(r.continuation?.status).toBe('converged');
    expect(r.continuation?.onBranch).toBe(true);
    expect(r.cold?.log.length).toBeGreaterThan(1);
    expect(r.continuation!.iterations).toBeLessThan(r.cold!.iterations);
    expect(r.linkage).toEqual(L);
  });

  it('says when the linkage cannot assemble at theta2 (no pose, no NR)', () => {
    const r = computePoint({
      linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 },
      branch: 'open',
      theta2Rad: Math.PI,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
    });
    expect(r.pose).toBeNull();
    expect(r.ghost).toBeNull();
    expect(r.continuation).toBeNull();
  });
});

describe('bad params', () => {
  it('throws an error naming the field and value (expose turns it into an error answer)', () => {
    expect(() => computeCycle({ linkage: { r1: 0, r2: 2, r3: 5, r4: 5 }, samples: 36, coupler: C, ...NEEDS })).toThrow(
      /r1 .*got 0/,
    );
    expect(() => computeCycle({ linkage: L, samples: 2.5, coupler: C, ...NEEDS })).toThrow(/samples .*got 2\.5/);
    expect(() => computeTable({ linkage: L, samples: 0, branch: 'open', solver: NEEDS.solver })).toThrow(
      /samples .*got 0/,
    );
    expect(() =>
      computePoint({ linkage: L, branch: 'open', theta2Rad: NaN, stepRad: D, coupler: C, ...POINT_NEEDS }),
    ).toThrow(/theta2Rad .*got NaN/);
  });
});

describe('computeCycle at view resolution', () => {
  it('solves at most VIEW_SAMPLES_MAX intervals whatever the samples, and says how many were asked', () => {
    const r = computeCycle({ linkage: L, samples: 3600, coupler: C, ...NEEDS });
    expect(VIEW_SAMPLES_MAX).toBe(720);
    expect(r.samples).toBe(3600);
    expect(r.theta2Deg.length).toBe(721);
    expect(r.open.theta3.length).toBe(721);
    expect(r.theta2Deg[720]).toBe(360);
    // Hard case 1 at theta2 = 90 deg (60-digit reference), grid index 180 of 720.
    expect(r.open.theta3[180] / D).toBeCloseTo(32.3335306935, 7);
    // Both branches on the view grid, and the two coupler curves at VIEW_SAMPLES_MAX per turn.
    expect(r.work.points).toBe(2 * 721 + 2 * 721);
  });

  it('keeps the samples grid itself when it is coarser than the view cap', () => {
    const r = computeCycle({ linkage: L, samples: 180, coupler: C, ...NEEDS });
    expect(r.theta2Deg.length).toBe(181);
    expect(r.theta2Deg[1]).toBe(2);
  });
});

describe('computeTable', () => {
  it('gives the CSV columns of all samples + 1 rows of one branch, agreeing with the view grid', () => {
    const solver = { method: 'newton' as const, tol: null };
    const t = computeTable({ linkage: L, samples: 3600, branch: 'crossed', solver });
    const view = computeCycle({ linkage: L, samples: 3600, coupler: C, ...NEEDS });
    for (const a of [t.theta2Deg, t.theta3Rad, t.theta4Rad, t.statusCodes, t.iterations, t.residual]) {
      expect(a.length).toBe(3601);
    }
    expect(t.theta2Deg[900]).toBe(90);
    // Hard case 1, crossed branch at 90 deg (60-digit reference).
    expect(t.theta3Rad[900] / D).toBeCloseTo(-69.2034283393, 7);
    expect(t.okCount).toBe(3601);
    expect(decodeStatuses(t.statusCodes).every((s) => s === 'ok')).toBe(true);
    expect(t.totalIterations).toBe(Array.from(t.iterations).reduce((a, b) => a + b, 0));
    // Polished NR on a benign crank-rocker is at full precision on both grids: 1e-12 rad is far above its error.
    for (let k = 0; k <= 720; k++) {
      expect(view.theta2Deg[k]).toBe(t.theta2Deg[5 * k]);
      expect(Math.abs(view.crossed.theta3[k] - t.theta3Rad[5 * k])).toBeLessThan(1e-12);
    }
    expect(t.residual[900]).toBeLessThan(1e-12);
    expect([t.linkage, t.branch, t.samples]).toEqual([L, 'crossed', 3600]);
  });

  it('counts the assembled rows of a triple rocker', () => {
    const t = computeTable({
      linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 },
      samples: 360,
      branch: 'open',
      solver: { method: 'closed-form', tol: null },
    });
    // Hard case 10: reachable for |theta2| <= 135.9513743259 deg, so 136 + 1 + 135 whole degrees.
    expect(t.okCount).toBe(272);
    expect(decodeStatuses(t.statusCodes)[180]).toBe('unreachable');
  });
});

describe('computeCycle computes only what the view shows', () => {
  it('skips the other branch and the coupler curves when nothing shows them', () => {
    const lean = computeCycle({
      linkage: L,
      samples: 360,
      coupler: C,
      ...NEEDS,
      otherBranch: false,
      curves: false,
    });
    const full = computeCycle({ linkage: L, samples: 360, coupler: C, ...NEEDS });
    expect(lean.crossed.skipped).toBe(true);
    expect(lean.crossed.okCount).toBe(0);
    expect(lean.curves).toEqual([]);
    expect(full.crossed.skipped).toBe(false);
    expect(full.curves.length).toBeGreaterThan(0);
    expect(lean.work.points).toBe(361);
    expect(full.work.points).toBeGreaterThan(2 * 361);
  });

  it('still sweeps both branches of a rocking input, which changes branch at its limits', () => {
    const r = computeCycle({
      linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 },
      samples: 360,
      coupler: C,
      ...NEEDS,
      otherBranch: false,
    });
    expect(r.open.skipped).toBe(false);
    expect(r.crossed.skipped).toBe(false);
  });

  it('sweeps with the chosen method: the report’s NR costs more iterations than the polished continuation', () => {
    const run = (method: 'seed' | 'newton' | 'closed-form') => {
      const r = computeCycle({
        linkage: L,
        samples: 360,
        coupler: C,
        ...NEEDS,
        solver: { method, tol: null },
      });
      return r.open.totalIterations;
    };
    expect(run('closed-form')).toBe(0);
    expect(run('newton')).toBeLessThan(2 * 361);
    expect(run('seed')).toBeGreaterThan(run('newton'));
  });
});

describe('computePoint computes only what the view shows', () => {
  it('skips the ghost and the NR runs when no panel shows them', () => {
    const r = computePoint({
      linkage: L,
      branch: 'open',
      theta2Rad: 45 * D,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
      ghost: false,
      newton: false,
    });
    expect(r.pose).not.toBeNull();
    expect(r.ghost).toBeNull();
    expect(r.continuation).toBeNull();
    expect(r.cold).toBeNull();
    expect(r.work).toEqual({ points: 1, iterations: 0 });
  });

  it('runs NR with the chosen method and tolerance', () => {
    const seed = computePoint({
      linkage: L,
      branch: 'open',
      theta2Rad: 45 * D,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
      solver: { method: 'seed', tol: null },
    });
    const loose = computePoint({
      linkage: L,
      branch: 'open',
      theta2Rad: 45 * D,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
      solver: { method: 'newton', tol: 1e-3 },
    });
    expect(seed.cold!.tolerance).toBe(1e-9);
    expect(loose.cold!.tolerance).toBeCloseTo(1e-3 * 18, 15);
    expect(loose.cold!.iterations).toBeLessThan(seed.cold!.iterations);
  });
});
