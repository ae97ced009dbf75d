/**
 * Spurious overflow and underflow (issue 18): where the true rate is a finite double, the solver returns
 * it, however far the input rates and link ratios are from 1 (omega2^2 alone overflowing, r2 / r3 beyond
 * 1e308, omega2 / sin mu beyond 1e308); where the true rate itself overflows, +-Infinity is the answer.
 * The oracle is referenceRatesWide: Cramer's rule at 120 digits, with the tolerance of
 * rateToleranceAtPose (K eps per term / |sin mu|, tests/oracle/rates.ts) evaluated in the same precision.
 */
import Decimal from 'decimal.js';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Angles, Linkage } from '../../src/solver';
import { couplerPointMotion, linkRates, solveClosedForm, sweepRates } from '../../src/solver';
import type { InputRates } from '../oracle/rates';
import {
  pointTolerance,
  rateToleranceAtPose,
  referencePointAtPose,
  referenceRatesAtPose,
  referenceRatesWide,
} from '../oracle/rates';
import { expectNear } from './metricsHelpers';

const RATES = ['omega3', 'omega4', 'alpha3', 'alpha4'] as const;
/**
 * A result below the normal range is rounded once more when scaled into the subnormals (an absolute
 * 2^-1075), and terms below 2^-1074 of the largest vanish as in any double sum: two subnormal ulps.
 */
const SUBNORMAL_FLOOR = new Decimal(2).times(Number.MIN_VALUE);
const MAX = new Decimal(Number.MAX_VALUE);

/** Each rate of linkRates against the wide oracle: within tolerance, or +-Infinity where the truth is (nearly) beyond MAX_VALUE. */
function expectRates(l: Linkage, theta2: number, pose: Angles, input: InputRates, what: string): void {
  const got = linkRates(l, theta2, pose, input);
  const { ref, tol } = referenceRatesWide(l, theta2, pose, input);
  const arrays = sweepRates(l, [theta2], [pose.theta3], [pose.theta4], () => true, input);
  for (const k of RATES) {
    const ctx = `${what}: ${k} = ${ref[k].toSignificantDigits(6).toString()} (tol ${tol[k].toSignificantDigits(2).toString()}), got ${got[k]}`;
    expect(arrays[k][0], `${ctx}: sweepRates equals linkRates`).toBe(got[k]);
    if (!Number.isFinite(got[k])) {
      expect(Number.isNaN(got[k]), `${ctx}: NaN`).toBe(false);
      expect(ref[k].abs().plus(tol[k]).greaterThanOrEqualTo(MAX), `${ctx}: spurious overflow`).toBe(true);
      expect(Math.sign(got[k]), `${ctx}: sign of the overflow`).toBe(ref[k].isNegative() ? -1 : 1);
      continue;
    }
    const err = new Decimal(got[k]).minus(ref[k]).abs();
    expect(err.lessThanOrEqualTo(tol[k].plus(SUBNORMAL_FLOOR)), `${ctx}: error ${err.toExponential(2)}`).toBe(true);
  }
}

describe('linkRates and sweepRates without spurious overflow', () => {
  const tinyCrank: Linkage = { r1: 1, r2: 1e-20, r3: 1, r4: 1 };

  it('gives alpha near 1e300 for omega2 = 1e160 with r2 / r3 = 1e-20 (omega2^2 overflows)', () => {
    const pose = solveClosedForm(tinyCrank, 1, 'open')!;
    const got = linkRates(tinyCrank, 1, pose, { omega2: 1e160, alpha2: 0 });
    expect(Number.isFinite(got.alpha3) && Number.isFinite(got.alpha4)).toBe(true);
    for (const alpha2 of [0, 1e300, -3e299]) {
      expectRates(tinyCrank, 1, pose, { omega2: 1e160, alpha2 }, `omega2 1e160, alpha2 ${alpha2}`);
    }
  });

  it('gives finite rates for r2 / r3 beyond 1e308 (the ratio itself overflows)', () => {
    // O2 O4 = 2^1000, crank 2^999 along the ground: |A O4| = 2^999 = r4, closed by a 2^-40 coupler.
    const l: Linkage = { r1: 2 ** 1000, r2: 2 ** 999, r3: 2 ** -40, r4: 2 ** 999 };
    const pose = solveClosedForm(l, 0, 'open')!;
    expect(pose).not.toBeNull();
    for (const [omega2, alpha2] of [
      [1e-200, 0],
      [1e-200, 1e-250],
      [-1e-20, 3e-300],
      [1e-170, -1e-310],
    ]) {
      expectRates(l, 0, pose, { omega2, alpha2 }, `r2 / r3 = 2^1039, omega2 ${omega2}, alpha2 ${alpha2}`);
      expectRates(l, 0.3, { theta3: 2.1, theta4: -0.4 }, { omega2, alpha2 }, `r2 / r3 = 2^1039 at a given pose`);
    }
  });

  it('gives omega near 1e290 for omega2 = 1e300 at sin mu = 1e-10 (omega2 / sin mu overflows)', () => {
    const pose = { theta3: 0.5, theta4: 0.5 + 1e-10 };
    for (const theta2 of [1.3, -2.9]) {
      expectRates(tinyCrank, theta2, pose, { omega2: 1e300, alpha2: 0 }, `omega2 1e300 at ${theta2}`);
      expectRates(tinyCrank, theta2, pose, { omega2: -1e300, alpha2: 1e300 }, `omega2 -1e300 at ${theta2}`);
    }
  });

  it('matches the wide oracle for random extreme lengths, rates and poses (seeded)', () => {
    const decade = (lo: number, hi: number) => fc.double({ min: lo, max: hi, noNaN: true }).map((e) => 10 ** e);
    const signed = (lo: number, hi: number) => fc.tuple(decade(lo, hi), fc.boolean()).map(([v, neg]) => (neg ? -v : v));
    const angle = fc.double({ min: -Math.PI, max: Math.PI, noNaN: true });
    fc.assert(
      fc.property(
        decade(-300, 300),
        decade(-300, 300),
        decade(-300, 300),
        signed(-300, 300),
        signed(-300, 300),
        angle,
        angle,
        fc.oneof(angle, decade(-14, -1)),
        (r2, r3, r4, omega2, alpha2, theta2, theta3, mu) => {
          const l = { r1: 1, r2, r3, r4 };
          const pose = { theta3, theta4: theta3 + mu };
          if (Math.abs(Math.sin(mu)) < 1e-14) return;
          expectRates(
            l,
            theta2,
            pose,
            { omega2, alpha2 },
            `l ${JSON.stringify(l)} w2 ${omega2} a2 ${alpha2} pose ${JSON.stringify(pose)} t2 ${theta2}`,
          );
        },
      ),
      { seed: 18, numRuns: 300 },
    );
  });
});

describe('couplerPointMotion without spurious overflow', () => {
  it('gives the acceleration near 1e280 for omega2 = 1e160 with r2 = 1e-20 (omega2^2 overflows)', () => {
    const l: Linkage = { r1: 1, r2: 1e-20, r3: 1, r4: 1 };
    const pose = solveClosedForm(l, 1, 'open')!;
    const input = { omega2: 1e160, alpha2: 0 };
    const got = couplerPointMotion(l, 1, pose, input, 1e-20, 0.7);
    const ref = referencePointAtPose(l, 1, pose, input, 1e-20, 0.7);
    // Tolerances are homogeneous in time: velocity ~ omega2, acceleration ~ omega2^2. Evaluate them at
    // omega2 / 2^531 (near 1.4) and scale back by exact powers of two, so the bound itself cannot overflow.
    const k = 2 ** 531;
    const small = { omega2: input.omega2 / k, alpha2: 0 };
    const rates = referenceRatesAtPose(l, 1, pose, small);
    const tol = pointTolerance(l, rates, rateToleranceAtPose(l, rates, small), small, 1e-20, 0);
    expectNear(got.vx, ref.vx, tol.velocity * k, 'vx');
    expectNear(got.vy, ref.vy, tol.velocity * k, 'vy');
    expectNear(got.ax, ref.ax, tol.acceleration * k * k, 'ax');
    expectNear(got.ay, ref.ay, tol.acceleration * k * k, 'ay');
  });
});
