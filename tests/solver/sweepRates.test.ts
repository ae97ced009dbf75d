import { describe, expect, it } from 'vitest';
import { linkRates, sweep, theta2Grid } from '../../src/solver';
import { referenceRatesAtPose } from '../oracle/rates';

describe('sweep with rates', () => {
  const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
  const input = { omega2: 10, alpha2: -3 };

  it('adds omega3, omega4, alpha3 and alpha4 that match the 60-digit oracle at every point', () => {
    const grid = theta2Grid(0, 360, 5);
    const r = sweep(l, grid, { branch: 'crossed', rates: input });
    expect(r.omega3).toBeInstanceOf(Float64Array);
    for (let i = 0; i < grid.length; i++) {
      const want = referenceRatesAtPose(l, grid[i], { theta3: r.theta3[i], theta4: r.theta4[i] }, input);
      // A benign crank-rocker (|sin mu| >= 0.67): relative 1e-12 is hundreds of ulps of room.
      for (const k of ['omega3', 'omega4', 'alpha3', 'alpha4'] as const) {
        expect(Math.abs(r[k]![i] - want[k])).toBeLessThanOrEqual(1e-12 * (1 + Math.abs(want[k])));
      }
    }
  });

  it('gives the same numbers as linkRates, and NaN where the loop does not close', () => {
    const tri = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
    const grid = theta2Grid(0, 360, 3);
    const r = sweep(tri, grid, { branch: 'open', rates: input });
    let gaps = 0;
    for (let i = 0; i < grid.length; i++) {
      if (r.status[i] !== 'ok') {
        gaps++;
        expect(r.omega4![i]).toBeNaN();
        continue;
      }
      const one = linkRates(tri, grid[i], { theta3: r.theta3[i], theta4: r.theta4[i] }, input);
      expect(r.alpha4![i]).toBe(one.alpha4);
    }
    expect(gaps).toBeGreaterThan(0);
  });

  it('computes nothing extra without rates', () => {
    const r = sweep(l, theta2Grid(0, 360, 10), { branch: 'open' });
    expect(r.omega3).toBeUndefined();
    expect(r.alpha4).toBeUndefined();
  });

  it('names a bad rate in its error', () => {
    expect(() => sweep(l, [0], { branch: 'open', rates: { omega2: Number.NaN, alpha2: 0 } })).toThrow(
      /rates\.omega2 .*NaN/,
    );
    expect(() => sweep(l, [0], { branch: 'open', rates: { omega2: 1, alpha2: Infinity } })).toThrow(/rates\.alpha2/);
  });
});
