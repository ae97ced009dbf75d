import { describe, expect, it } from 'vitest';
import { degToRad } from '../../../src/solver/angles';
import { plotSeries } from '../../../src/shared/charts/plotSeries';
import { referenceAngles } from '../../oracle/reference';
import { referenceMotion } from '../../oracle/rates';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };
const NR = { method: 'newton' as const, tol: null };

/** The smallest difference of two angles in radians (2π-periodic). */
function angleGap(a: number, b: number): number {
  return Math.abs(Math.atan2(Math.sin(a - b), Math.cos(a - b)));
}

describe('plotSeries (the plots, solved on the main thread)', () => {
  it('samples a benign crank-rocker about once per pixel and solves the branch asked for as the oracle does', () => {
    const p = plotSeries(L, 600, ['open'], NR, null);
    expect(p.theta2Deg.length).toBeGreaterThanOrEqual(601);
    expect(p.theta2Deg.length).toBeLessThan(1200);
    expect(p.crossed).toBeNull();
    expect(p.open!.rates).toBeUndefined();
    for (let i = 0; i < p.theta2Deg.length; i += 41) {
      const ref = referenceAngles(L, degToRad(p.theta2Deg[i]), 1)!;
      expect(angleGap(p.open!.theta3[i], ref.theta3)).toBeLessThan(1e-12);
      expect(angleGap(p.open!.theta4[i], ref.theta4)).toBeLessThan(1e-12);
    }
  });

  it('puts the exact input limits of a triple rocker into its samples', () => {
    const p = plotSeries({ r1: 4, r2: 3, r3: 3.5, r4: 3 }, 400, ['open', 'crossed'], NR, null);
    const limitDeg = 135.9513743259; // hard case 10
    expect(Math.min(...Array.from(p.theta2Deg, (d) => Math.abs(d - limitDeg)))).toBeLessThan(1e-8);
  });

  it('adds the link rates for the input motion when asked, as the oracle gives them', () => {
    const input = { omega2: 2, alpha2: -1 };
    const p = plotSeries(L, 300, ['open', 'crossed'], NR, input);
    for (const [b, sigma] of [['open', 1] as const, ['crossed', -1] as const]) {
      const r = p[b]!.rates!;
      for (let i = 0; i < p.theta2Deg.length; i += 29) {
        const ref = referenceMotion(L, degToRad(p.theta2Deg[i]), sigma, input);
        expect(r.omega3[i]).toBeCloseTo(ref.omega3, 9);
        expect(r.omega4[i]).toBeCloseTo(ref.omega4, 9);
        expect(r.alpha3[i]).toBeCloseTo(ref.alpha3, 8);
        expect(r.alpha4[i]).toBeCloseTo(ref.alpha4, 8);
      }
    }
  });
});
