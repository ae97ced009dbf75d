import { describe, expect, it } from 'vitest';
import { MECHANISM_TEMPLATES, fourBarSpec, jansenSpec, pistonDrivenSpec, sliderCrankSpec } from '../../src/mechanism';
import type { MechanismSpec } from '../../src/mechanism';
import { sweepWith } from '../../src/mechanism/sweep';
import { solveClosedForm } from '../../src/solver';
import { dist, dpt, exact, grid, rotate } from './oracle';

const scaled = (s: MechanismSpec, k: number): MechanismSpec => ({
  ...s,
  joints: s.joints.map((j) => ({ ...j, x: j.x * k, y: j.y * k })),
  points: s.points?.map((p) => ({ ...p, x: p.x * k, y: p.y * k })),
});

describe('sweepMechanism: hard cases', () => {
  it('turns a near-toggle slider-crank (coupler = crank + offset + 1e-9) fully, on its branch', () => {
    const spec = sliderCrankSpec(2, 3 + 1e-9, 1);
    const inputs = grid(0, 2 * Math.acos(-1), 361);
    const r = sweepWith(spec, inputs, undefined, false);
    expect([...r.ok].every((v) => v === 1)).toBe(true);
    const a0 = dpt(spec.joints[1].x, spec.joints[1].y);
    const b0 = dpt(spec.joints[2].x, spec.joints[2].y);
    const l = dist(a0, b0);
    let worst = 0;
    inputs.forEach((t, i) => {
      const a = rotate(a0, dpt(0, 0), exact(t));
      const bx = a[0].plus(l.pow(2).minus(b0[1].minus(a[1]).pow(2)).sqrt()).toNumber();
      worst = Math.max(worst, Math.abs(r.joints.B.x[i] - bx));
      // Never the mirror assembly (B left of A).
      expect(r.joints.B.x[i]).toBeGreaterThanOrEqual(r.joints.A.x[i]);
    });
    // At the near-toggle B - A = sqrt(l^2 - 9) ~ 8e-5: rounding of l^2 - 9 (~eps 9) costs ~1e-11 there.
    expect(worst).toBeLessThan(1e-9);
  });

  for (const dyads of [true, false]) {
    it(`passes close to a change point (4, 1, 3, 2+1e-12) without jumping branch (${dyads ? 'dyads' : 'Newton'})`, () => {
      const l = { r1: 4, r2: 1, r3: 3, r4: 2 + 1e-12 };
      const spec = fourBarSpec(l.r1, l.r2, l.r3, l.r4);
      const inputs = grid(0, 2 * Math.acos(-1), 181);
      const r = sweepWith(spec, inputs, undefined, dyads);
      const b0 = spec.joints[2];
      const theta40 = Math.atan2(b0.y, b0.x - 4);
      expect([...r.ok].every((v) => v === 1)).toBe(true);
      inputs.forEach((t, i) => {
        const ref = solveClosedForm(l, t, 'open')!;
        // Near theta2 = pi the two branches are 6e-5 rad apart and the pose is sensitive to the lengths' rounding
        // (about 1e6 x 4e-16): 1e-8 rad separates the right branch from the wrong one by far.
        expect(Math.abs(Math.sin(theta40 + r.links.rocker.angle[i] - ref.theta4))).toBeLessThan(1e-8);
      });
    });
  }

  it('reports a locked linkage (6, 1, 2, 3: flat as drawn) as singular everywhere, with no pose', () => {
    const r = sweepWith(fourBarSpec(6, 1, 2, 3), [0, 0.1, -0.1], undefined, false);
    expect([...r.status]).toEqual([2, 2, 2]);
    expect([...r.ok]).toEqual([0, 0, 0]);
    expect(Number.isNaN(r.joints.B.x[0])).toBe(true);
  });

  for (const dyads of [true, false]) {
    it(`stops at a rocker's limit and comes back on the same branch (Chebyshev, ${dyads ? 'dyads' : 'Newton'})`, () => {
      const spec = MECHANISM_TEMPLATES.chebyshev.spec;
      const inputs = [0, 0.5, 0.8, 0.9, 1.2, 0.8, 0.5, 0];
      const r = sweepWith(spec, inputs, undefined, dyads);
      expect([...r.status]).toEqual([0, 0, 0, 1, 1, 0, 0, 0]);
      expect(Number.isNaN(r.points.M.x[3])).toBe(true);
      expect(Math.abs(r.points.M.x[6] - r.points.M.x[1])).toBeLessThan(1e-13);
      expect(Math.abs(r.points.M.y[7] - 2)).toBeLessThan(1e-13);
    });
  }

  for (const dyads of [true, false]) {
    it(`does not jump a gap in the input range (3, 2.5, 4.2, 1.5 from 180 deg; ${dyads ? 'dyads' : 'Newton'})`, () => {
      // Reachable where |theta2| >= 57.95 deg: from 180 deg, +4.3 rad (426 deg) lies past the gap (302..418 deg),
      // so the drawn circuit cannot get there by continuity; -1.5 rad (94 deg) can be reached.
      const spec = fourBarSpec(3, 2.5, 4.2, 1.5, Math.acos(-1));
      const r = sweepWith(spec, [0.5, 4.3, -1.5], undefined, dyads);
      expect([...r.status]).toEqual([0, 1, 0]);
    });
  }

  it('stops a piston-driven crank at its dead centres (input on a P joint)', () => {
    const r = sweepWith(pistonDrivenSpec(), [0, 1, 1.62, 1.7, 3, 1, -2.3, -2.4], undefined, false);
    expect([...r.status]).toEqual([0, 0, 0, 1, 1, 0, 0, 1]);
    expect(Math.abs(r.sliders.Bore.s[2] - 1.62)).toBeLessThan(1e-13);
  });

  const SCALES = [1e9, 1e200, 1e-12, 1e-200];
  for (const k of SCALES) {
    it(`gives the same shape at scale ${k} (slider-crank, Newton; Jansen, dyads)`, () => {
      const inputs = grid(0, 6.3, 61);
      for (const [spec, dyads, id] of [
        [sliderCrankSpec(2, 5, 1), false, 'B'],
        [jansenSpec(), true, 'G'],
      ] as const) {
        const unit = sweepWith(spec, inputs, { omega: 1, alpha: 0 }, dyads);
        const big = sweepWith(scaled(spec, k), inputs, { omega: 1, alpha: 0 }, dyads);
        const size = Math.max(...unit.joints[id].x.map(Math.abs));
        for (let i = 0; i < inputs.length; i++) {
          expect(big.ok[i]).toBe(1);
          // Scaling by a non-power of two rounds every coordinate once: a few eps of the size.
          expect(Math.abs(big.joints[id].x[i] / k - unit.joints[id].x[i])).toBeLessThan(1e-13 * size);
          expect(Math.abs(big.joints[id].vx![i] / k - unit.joints[id].vx![i])).toBeLessThan(1e-12 * size);
        }
      }
    });
  }
});
