import { describe, expect, it } from 'vitest';
import { localPose, poseAsPoint } from '../../../src/shared/linkage/localPose';
import type { Branch, Linkage } from '../../../src/solver/types';
import { angleDiff, referenceSolve } from '../../oracle/reference';
import { angleTolerance } from '../../oracle/tolerance';

const REPORT: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };
const TRIPLE_ROCKER: Linkage = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
const DRAG_LINK: Linkage = { r1: 2, r2: 4, r3: 5, r4: 4.5 };
const COUPLER = { distance: 2.5, angleDeg: 30 };
const sigma = (b: Branch) => (b === 'open' ? 1 : -1);

describe('localPose', () => {
  it('draws the oracle’s pose on both branches every 15° of three linkages', () => {
    let checked = 0;
    for (const l of [REPORT, TRIPLE_ROCKER, DRAG_LINK]) {
      for (const branch of ['open', 'crossed'] as const) {
        for (let deg = 7.5; deg < 360; deg += 15) {
          const p = localPose(l, deg, branch, COUPLER, true);
          const ref = referenceSolve(l, p.theta2Rad, sigma(branch));
          const other = referenceSolve(l, p.theta2Rad, branch === 'open' ? -1 : 1);
          if (ref.kind !== 'unique' || other.kind !== 'unique') {
            // Unreachable here (or a limit within rounding): never a torn pose.
            if (ref.kind === 'unreachable') expect(p.pose).toBeNull();
            continue;
          }
          const tol = angleTolerance(l, ref.pose);
          if (!p.pose || !p.ghost) throw new Error(`no pose at ${deg}° on ${branch}`);
          expect(Math.abs(angleDiff(p.pose.theta3, ref.pose.theta3))).toBeLessThanOrEqual(tol.theta3);
          expect(Math.abs(angleDiff(p.pose.theta4, ref.pose.theta4))).toBeLessThanOrEqual(tol.theta4);
          // The ghost is the other branch: the oracle's other assembly.
          const gTol = angleTolerance(l, other.pose);
          expect(Math.abs(angleDiff(p.ghost.theta3, other.pose.theta3))).toBeLessThanOrEqual(gTol.theta3);
          // mu in [0, pi] with |sin mu| the oracle's |sin(theta4 - theta3)|; 1e-12 covers the rounding of sin.
          expect(p.pose.mu).toBeGreaterThanOrEqual(0);
          expect(p.pose.mu).toBeLessThanOrEqual(Math.PI);
          expect(Math.abs(Math.sin(p.pose.mu) - Math.abs(ref.pose.sinMu))).toBeLessThan(1e-12);
          checked++;
        }
      }
    }
    // Most of the 144 poses assemble; the triple rocker's gaps are the rest.
    expect(checked).toBeGreaterThan(100);
  });

  it('gives no pose where the loop cannot close (the triple rocker at 180°)', () => {
    expect(referenceSolve(TRIPLE_ROCKER, Math.PI, 1).kind).toBe('unreachable');
    const p = localPose(TRIPLE_ROCKER, 180, 'open', COUPLER, true);
    expect(p.pose).toBeNull();
    expect(p.ghost).toBeNull();
  });

  it('solves the ghost only when it is drawn', () => {
    expect(localPose(REPORT, 45, 'open', COUPLER, false).ghost).toBeNull();
    expect(localPose(REPORT, 45, 'open', COUPLER, true).ghost).not.toBeNull();
  });

  it('gives no pose, rather than throwing, for lengths the solver refuses', () => {
    const bad = { r1: 6, r2: -1, r3: 5, r4: 5 };
    expect(() => localPose(bad, 45, 'open', COUPLER, true)).not.toThrow();
    expect(localPose(bad, 45, 'open', COUPLER, true).pose).toBeNull();
  });

  it('carries theta2 and the coupler angle in radians, and the inputs it was solved for', () => {
    const p = localPose(REPORT, 90, 'crossed', { distance: 1.5, angleDeg: -90 }, false);
    expect(p.theta2Rad).toBe(Math.PI / 2);
    expect(p.coupler).toEqual({ distance: 1.5, angleRad: -Math.PI / 2 });
    expect(p.branch).toBe('crossed');
    expect(p.linkage).toBe(REPORT);
  });
});

describe('poseAsPoint', () => {
  it('is the same pose as a point answer without NR runs', () => {
    const p = localPose(REPORT, 45, 'open', COUPLER, true);
    const m = poseAsPoint(p, { method: 'newton', tol: null });
    expect(m.theta2Rad).toBe(p.theta2Rad);
    expect(m.pose).toBe(p.pose);
    expect(m.ghost).toBe(p.ghost);
    expect(m.branch).toBe('open');
    expect(m.continuation).toBeNull();
    expect(m.cold).toBeNull();
  });
});
