/**
 * sweep's result layout and its fused closed-form loop (issue 7, item 7): the default method runs
 * closedFormSweep, whose common path repeats closedFormAt's arithmetic inline, so the two must agree
 * bit for bit everywhere (near limits, past them, at continua, with tiny |A O4|); the status is one
 * byte a point, decoded to the string array only when read. Fixed seeds.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Linkage } from '../../src/solver';
import { sweep } from '../../src/solver';
import { Assembly, closedFormAt, newClosedFormPoint, planClosedForm } from '../../src/solver/closedForm';
import { POINT_STATUSES } from '../../src/solver/pointStatus';
import { scaleByPow2 } from '../../src/solver/validate';

const length = fc.double({ min: -3, max: 3, noNaN: true }).map((u) => 10 ** u);
const linkageArb: fc.Arbitrary<Linkage> = fc.oneof(
  fc.record({ r1: length, r2: length, r3: length, r4: length }),
  // Kites, parallelograms and r1 = r2 (the crank pin reaches O4), where the careful path runs.
  fc.record({ a: length, b: length }).map(({ a, b }) => ({ r1: a, r2: a, r3: b, r4: b })),
  fc.record({ a: length, b: length }).map(({ a, b }) => ({ r1: a, r2: b, r3: a, r4: b })),
);
const anglesArb = fc.array(
  fc.oneof(
    fc.double({ min: -20, max: 20, noNaN: true }),
    fc.constantFrom(0, Math.PI, -Math.PI, Math.PI / 2, 1e-300, -5e-324, 2 * Math.PI, 1e5),
  ),
  { minLength: 1, maxLength: 40 },
);

describe('sweep with the default closed form', () => {
  it('equals closedFormAt point by point, bit for bit, on both branches', () => {
    fc.assert(
      fc.property(linkageArb, anglesArb, fc.constantFrom<1 | -1>(1, -1), (l, t2s, sigma) => {
        const r = sweep(l, t2s, { branch: sigma > 0 ? 'open' : 'crossed' });
        const plan = planClosedForm(l);
        const p = newClosedFormPoint();
        t2s.forEach((t2, i) => {
          const a = closedFormAt(plan, t2, sigma, p);
          const code = a === Assembly.Unreachable ? 1 : a === Assembly.Continuum ? 2 : 0;
          expect(r.statusCodes[i], `status at ${t2}`).toBe(code);
          if (code !== 0) {
            expect(Number.isNaN(r.theta3[i]) && Number.isNaN(r.theta4[i]) && Number.isNaN(r.residual[i])).toBe(true);
            return;
          }
          expect(r.theta3[i]).toBe(p.theta3);
          expect(r.theta4[i]).toBe(p.theta4);
          expect(r.residual[i]).toBe(scaleByPow2(p.residual, plan.exponent));
          expect(r.theta2[i]).toBe(t2);
        });
      }),
      { seed: 7301, numRuns: 400 },
    );
  });

  it('keeps one status byte a point and decodes the string statuses from it on first read', () => {
    const l = { r1: 4, r2: 3, r3: 3.5, r4: 3 }; // a triple rocker: ok and unreachable points
    const grid = Array.from({ length: 361 }, (_, i) => (i * Math.PI) / 180);
    for (const method of ['closed-form', 'closed-form-polish', 'newton', 'newton-no-predictor', 'seed'] as const) {
      const r = sweep(l, grid, { branch: 'open', method });
      expect(r.statusCodes).toBeInstanceOf(Uint8Array);
      expect(r.statusCodes.length).toBe(361);
      expect(Array.isArray(r.status)).toBe(true);
      expect(r.status).toEqual(Array.from(r.statusCodes, (c) => POINT_STATUSES[c]));
      expect(r.status).toBe(r.status); // decoded once
      expect(new Set(r.status).size).toBeGreaterThan(1);
    }
  });
});
