import { describe, expect, it } from 'vitest';
import { computeCycle, computePoint, handleRequest } from '../../src/worker/compute';
import type { SolverRequest } from '../../src/worker/protocol';
import { decodeStatuses } from '../../src/worker/statusCodes';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };
const C = { distance: 2.5, angleRad: Math.PI / 6 };
const D = Math.PI / 180;
/** What a cycle request needs besides its linkage: the full app's defaults (both branches, curves, no plot samples). */
const NEEDS = {
  solver: { method: 'newton' as const, tol: null },
  branch: 'open' as const,
  otherBranch: true,
  curves: true,
  plotPixels: 0,
};
const POINT_NEEDS = { solver: { method: 'newton' as const, tol: null }, ghost: true, newton: true };

describe('computeCycle', () => {
  it('sweeps 361 points from 0 to 360 degrees on both branches of the report case', () => {
    const r = computeCycle({ type: 'cycle', id: 1, linkage: L, samples: 360, coupler: C, ...NEEDS }).response;
    if (r.type !== 'cycle') throw new Error(r.type);
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

  it('gives a closed rocking coupler curve per circuit for a triple rocker', () => {
    const r = computeCycle({
      type: 'cycle',
      id: 1,
      linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 },
      samples: 360,
      coupler: C,
      ...NEEDS,
    }).response;
    if (r.type !== 'cycle') throw new Error(r.type);
    expect(r.curves).toHaveLength(1);
    const c = r.curves[0];
    expect(c.rocking).toBe(true);
    expect(c.x[0]).toBe(c.x[c.x.length - 1]);
    expect(decodeStatuses(r.open.statusCodes)[180]).toBe('unreachable');
    expect(Number.isNaN(r.open.theta3[180])).toBe(true);
  });

  it('reports a linkage that cannot assemble anywhere without throwing', () => {
    const r = computeCycle({
      type: 'cycle',
      id: 1,
      linkage: { r1: 10, r2: 1, r3: 2, r4: 3 },
      samples: 36,
      coupler: C,
      ...NEEDS,
    }).response;
    if (r.type !== 'cycle') throw new Error(r.type);
    expect(r.open.okCount).toBe(0);
    expect(r.classification.type).toBe('cannot-assemble');
    expect(r.curves).toHaveLength(0);
  });
});

describe('computePoint', () => {
  it('solves the pose, the ghost and both NR runs', () => {
    const r = computePoint({
      type: 'point',
      id: 2,
      linkage: L,
      branch: 'open',
      theta2Rad: 90 * D,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
    }).response;
    if (r.type !== 'point') throw new Error(r.type);
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
      type: 'point',
      id: 3,
      linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 },
      branch: 'open',
      theta2Rad: Math.PI,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
    }).response;
    if (r.type !== 'point') throw new Error(r.type);
    expect(r.pose).toBeNull();
    expect(r.ghost).toBeNull();
    expect(r.continuation).toBeNull();
  });
});

describe('handleRequest', () => {
  it('answers a bad request with an error naming the value instead of throwing', () => {
    const r = handleRequest({
      type: 'cycle',
      id: 7,
      linkage: { r1: 0, r2: 2, r3: 5, r4: 5 },
      samples: 36,
      coupler: C,
      ...NEEDS,
    }).response;
    expect(r).toMatchObject({ type: 'error', id: 7, requestType: 'cycle' });
    if (r.type === 'error') expect(r.message).toMatch(/r1 .*got 0/);
    const u = handleRequest({ type: 'nope', id: 8 } as unknown as SolverRequest).response;
    expect(u.type).toBe('error');
  });
});

describe('computeCycle computes only what the view shows', () => {
  it('skips the other branch, the coupler curves and the plot samples when nothing shows them', () => {
    const lean = computeCycle({
      type: 'cycle',
      id: 1,
      linkage: L,
      samples: 360,
      coupler: C,
      ...NEEDS,
      otherBranch: false,
      curves: false,
    }).response;
    const full = computeCycle({
      type: 'cycle',
      id: 2,
      linkage: L,
      samples: 360,
      coupler: C,
      ...NEEDS,
      plotPixels: 600,
    }).response;
    if (lean.type !== 'cycle' || full.type !== 'cycle') throw new Error('not a cycle');
    expect(lean.crossed.skipped).toBe(true);
    expect(lean.crossed.okCount).toBe(0);
    expect(lean.curves).toEqual([]);
    expect(lean.plot).toBeNull();
    expect(full.plot).not.toBeNull();
    // About one plot sample per pixel for a benign crank-rocker.
    expect(full.plot!.theta2Deg.length).toBeGreaterThanOrEqual(601);
    expect(full.plot!.theta2Deg.length).toBeLessThan(1200);
    expect(lean.work.points).toBe(361);
    expect(full.work.points).toBeGreaterThan(2 * 361 + 2 * 600);
  });

  it('still sweeps both branches of a rocking input, which changes branch at its limits', () => {
    const r = computeCycle({
      type: 'cycle',
      id: 1,
      linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 },
      samples: 360,
      coupler: C,
      ...NEEDS,
      otherBranch: false,
    }).response;
    if (r.type !== 'cycle') throw new Error(r.type);
    expect(r.open.skipped).toBe(false);
    expect(r.crossed.skipped).toBe(false);
  });

  it('puts the exact input limits of a triple rocker into the plot samples', () => {
    const l = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
    const r = computeCycle({
      type: 'cycle',
      id: 1,
      linkage: l,
      samples: 360,
      coupler: C,
      ...NEEDS,
      plotPixels: 400,
    }).response;
    if (r.type !== 'cycle') throw new Error(r.type);
    const limitDeg = 135.9513743259; // hard case 10
    const nearest = Math.min(...Array.from(r.plot!.theta2Deg, (d) => Math.abs(d - limitDeg)));
    expect(nearest).toBeLessThan(1e-8);
  });

  it('sweeps with the chosen method: the report’s NR costs more iterations than the polished continuation', () => {
    const run = (method: 'seed' | 'newton' | 'closed-form') => {
      const r = computeCycle({
        type: 'cycle',
        id: 1,
        linkage: L,
        samples: 360,
        coupler: C,
        ...NEEDS,
        solver: { method, tol: null },
      }).response;
      if (r.type !== 'cycle') throw new Error(r.type);
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
      type: 'point',
      id: 1,
      linkage: L,
      branch: 'open',
      theta2Rad: 45 * D,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
      ghost: false,
      newton: false,
    }).response;
    if (r.type !== 'point') throw new Error(r.type);
    expect(r.pose).not.toBeNull();
    expect(r.ghost).toBeNull();
    expect(r.continuation).toBeNull();
    expect(r.cold).toBeNull();
    expect(r.work).toEqual({ points: 1, iterations: 0 });
  });

  it('runs NR with the chosen method and tolerance', () => {
    const seed = computePoint({
      type: 'point',
      id: 1,
      linkage: L,
      branch: 'open',
      theta2Rad: 45 * D,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
      solver: { method: 'seed', tol: null },
    }).response;
    const loose = computePoint({
      type: 'point',
      id: 2,
      linkage: L,
      branch: 'open',
      theta2Rad: 45 * D,
      stepRad: D,
      coupler: C,
      ...POINT_NEEDS,
      solver: { method: 'newton', tol: 1e-3 },
    }).response;
    if (seed.type !== 'point' || loose.type !== 'point') throw new Error('not a point');
    expect(seed.cold!.tolerance).toBe(1e-9);
    expect(loose.cold!.tolerance).toBeCloseTo(1e-3 * 18, 15);
    expect(loose.cold!.iterations).toBeLessThan(seed.cold!.iterations);
  });
});
