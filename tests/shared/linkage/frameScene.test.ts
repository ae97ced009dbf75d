import { describe, expect, it } from 'vitest';
import { sceneAtFrame, sceneWarning } from '../../../src/shared/linkage/frameScene';
import { classify } from '../../../src/solver';
import type { Branch, Linkage } from '../../../src/solver/types';
import { getMessages } from '../../../src/shared/i18n/i18n';
import type { CouplerCurve } from '../../../src/shared/solution';
import { angleDiff, referenceSolve } from '../../oracle/reference';
import { angleTolerance } from '../../oracle/tolerance';
import { rad, sweepScenes } from './fixtures';

const t = getMessages('en');
const REPORT: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };
const TRIPLE_ROCKER: Linkage = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
const COUPLER = { distance: 2.5, angleDeg: 30 };
const sigma = (b: Branch) => (b === 'open' ? 1 : -1);

function source(l: Linkage, curves: CouplerCurve[] = []) {
  const base = sweepScenes({ name: 'x', linkage: l, coupler: COUPLER }, 'open', 'en', 90)[0];
  return { base, coupler: COUPLER, curves, classification: classify(l), t };
}

describe('sceneAtFrame', () => {
  it('draws the oracle’s pose at each frame’s angle and branch, keeping the base bounds and toggles', () => {
    const src = source(REPORT);
    for (const branch of ['open', 'crossed'] as const) {
      for (let deg = 5; deg < 360; deg += 30) {
        const s = sceneAtFrame(src, rad(deg), branch);
        const ref = referenceSolve(REPORT, rad(deg), sigma(branch));
        if (ref.kind !== 'unique' || !s.pose) throw new Error(`no pose at ${deg}° ${branch}`);
        const tol = angleTolerance(REPORT, ref.pose);
        expect(Math.abs(angleDiff(s.pose.theta3, ref.pose.theta3))).toBeLessThanOrEqual(tol.theta3);
        expect(Math.abs(angleDiff(s.pose.theta4, ref.pose.theta4))).toBeLessThanOrEqual(tol.theta4);
        // The crank pin is where θ2 puts it (2 is the crank length; 1e-12 is rounding of cos/sin times 2).
        expect(Math.abs(s.pose.A.x - 2 * Math.cos(rad(deg)))).toBeLessThan(1e-12);
        expect(s.theta2).toBe(rad(deg));
        expect(s.bounds).toBe(src.base.bounds);
        expect(s.showGrid).toBe(src.base.showGrid);
        expect(s.ghost === null).toBe(!src.base.showGhost);
        expect(s.text.warning).toBeNull();
      }
    }
  });

  it('marks the circuit holding theta2 as current on a rocking input', () => {
    const curve = (loRad: number, hiRad: number): CouplerCurve =>
      ({ x: [0], y: [0], branch: 'open', rocking: true, loRad, hiRad }) as unknown as CouplerCurve;
    const src = source(TRIPLE_ROCKER, [curve(rad(-100), rad(100)), curve(rad(150), rad(200))]);
    expect(sceneAtFrame(src, rad(10), 'open').curves.map((c) => c.current)).toEqual([true, false]);
    expect(sceneAtFrame(src, rad(170), 'open').curves.map((c) => c.current)).toEqual([false, true]);
  });

  it('says the linkage cannot assemble at an unreachable angle, with the reachable range', () => {
    const s = sceneAtFrame(source(TRIPLE_ROCKER), rad(180), 'open');
    expect(s.pose).toBeNull();
    expect(s.text.warning).toBe(t.cannotAssembleAt('180.00'));
    expect(s.text.warningDetail).toMatch(/^Reachable/);
  });
});

describe('sceneWarning', () => {
  it('says nothing for an assembled pose and names a linkage that assembles nowhere', () => {
    expect(sceneWarning(true, null, 0, t)).toEqual({ warning: null, warningDetail: null });
    const never = classify({ r1: 10, r2: 1, r3: 1, r4: 1 });
    expect(sceneWarning(false, never, 0, t)).toEqual({ warning: t.cannotAssembleAny, warningDetail: null });
  });
});
