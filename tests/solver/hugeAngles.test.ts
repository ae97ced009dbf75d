/**
 * Huge angles (issue 18): every solver function that takes angles answers for the exact doubles given,
 * however large. A difference such as theta2 - theta3 at theta2 = 1e16 rounds by up to a radian, so the
 * solver reduces it exactly (angleDiff: Cody-Waite / Payne-Hanek) before taking sines and cosines.
 * The oracles (tests/oracle) evaluate cos and sin of the exact doubles at 60 digits (decimal.js reduces
 * with as many digits of pi as the argument needs), so they are the truth for the angles given.
 */
import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import type { Angles, Linkage } from '../../src/solver';
import { reduceDifference } from '../../src/solver/angles';
import {
  couplerPoint,
  couplerPointMotion,
  instantCenters,
  linkRates,
  solveClosedForm,
  sweep,
  sweepRates,
  transmissionAngle,
  velocityRatios,
} from '../../src/solver';
import { referenceInstantCenters } from '../oracle/metrics';
import { centerTol, sinDifferenceFloor } from '../oracle/metricsTolerance';
import { pointTolerance, rateToleranceAtPose, referencePointAtPose, referenceRatesAtPose } from '../oracle/rates';
import { reducedAngleDigits, referenceWrap } from '../oracle/reference';
import { EPS } from '../oracle/tolerance';
import { expectNear } from './metricsHelpers';

const REPORT: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };
const INPUT = { omega2: 3, alpha2: -2 };
const RATES = ['omega3', 'omega4', 'alpha3', 'alpha4'] as const;
/** Input angles from where the old first-order correction started to fail (1e10) to the largest double. */
const HUGE = [1e10, -3e12, 2 ** 52 + 1, 1e16, -1e16, 7.5e17, 1e20, -1e100, 1e300, Number.MAX_VALUE];

/** The closed-form pose at a huge theta2 (the closed form takes cos and sin of the double itself). */
function poseAt(l: Linkage, theta2: number): Angles {
  const p = solveClosedForm(l, theta2, 'open');
  expect(p, `assembles at ${theta2}`).not.toBeNull();
  return { theta3: p!.theta3, theta4: p!.theta4 };
}

describe('linkRates at huge input angles', () => {
  it('gives omega3 = 0.02116 for the report linkage at theta2 = 1e16 (was 0.0425)', () => {
    const pose = poseAt(REPORT, 1e16);
    const got = linkRates(REPORT, 1e16, pose, { omega2: 1, alpha2: 0 });
    const ref = referenceRatesAtPose(REPORT, 1e16, pose, { omega2: 1, alpha2: 0 });
    expect(ref.omega3).toBeCloseTo(0.02116, 5);
    // The rates at a pose are exact to rounding for its angles: rateToleranceAtPose (K eps per term / sin mu).
    const tol = rateToleranceAtPose(REPORT, ref, { omega2: 1, alpha2: 0 });
    for (const k of RATES) expectNear(got[k], ref[k], tol[k], `${k} at 1e16`);
  });

  it('matches the 60-digit oracle from 1e10 to the largest double, in linkRates, sweepRates and sweep', () => {
    const poses = HUGE.map((t2) => poseAt(REPORT, t2));
    const viaSweep = sweep(REPORT, HUGE, { branch: 'open', rates: INPUT });
    const viaArrays = sweepRates(
      REPORT,
      HUGE,
      poses.map((p) => p.theta3),
      poses.map((p) => p.theta4),
      () => true,
      INPUT,
    );
    HUGE.forEach((t2, i) => {
      const got = linkRates(REPORT, t2, poses[i], INPUT);
      const ref = referenceRatesAtPose(REPORT, t2, poses[i], INPUT);
      const tol = rateToleranceAtPose(REPORT, ref, INPUT);
      for (const k of RATES) {
        expectNear(got[k], ref[k], tol[k], `${k} at theta2 = ${t2}`);
        expect(viaArrays[k][i], `sweepRates ${k} at ${t2}`).toBe(got[k]);
        expect(viaSweep[k]![i], `sweep ${k} at ${t2}`).toBe(got[k]);
      }
    });
  });

  it('reduces huge coupler and rocker angles too (a pose given unwrapped)', () => {
    const t2 = 0.7;
    const base = poseAt(REPORT, t2);
    // theta3 + 2 pi k rounded to a double is another exact angle; the oracle takes it as given.
    for (const turns of [1e9, 3e15, 1e20]) {
      const pose = { theta3: base.theta3 + 2 * Math.PI * turns, theta4: base.theta4 - 2 * Math.PI * turns };
      const ref = referenceRatesAtPose(REPORT, t2, pose, INPUT);
      const got = linkRates(REPORT, t2, pose, INPUT);
      const tol = rateToleranceAtPose(REPORT, ref, INPUT);
      for (const k of RATES) expectNear(got[k], ref[k], tol[k], `${k} with theta3, theta4 ~ ${turns} turns`);
    }
  });
  it('keeps sin mu to full relative accuracy for huge pose angles next to a limit (mu within 1e-9 of pi)', () => {
    // theta3 + pi rounds at the ulp of theta3 (2e-9 at 1e7, 5e-7 at 3e9), so mu = theta4 - theta3 is
    // pi plus a tiny exact remainder: sin mu must come from the reduced difference and its low part.
    // An odd number of half turns past one turn (3 pi, -5 pi) also makes the reduction subtract whole turns.
    for (const [theta3, halfTurns] of [
      [1e7 + 0.3, 1],
      [-3e9 - 0.7, 1],
      [1e7 + 0.3, 3],
      [-3e9 - 0.7, -5],
    ]) {
      const pose = { theta3, theta4: theta3 + halfTurns * Math.PI };
      const ref = referenceRatesAtPose(REPORT, 0.7, pose, INPUT);
      expect(Math.abs(ref.sinMu)).toBeLessThan(1e-6);
      const got = linkRates(REPORT, 0.7, pose, INPUT);
      const tol = rateToleranceAtPose(REPORT, ref, INPUT);
      for (const k of RATES) expectNear(got[k], ref[k], tol[k], `${k} with sin mu = ${ref.sinMu}`);
    }
  });
});

describe('couplerPointMotion and couplerPoint at huge angles', () => {
  it('puts P where the oracle does for pAngle = 1e16 (x and y were wrong too)', () => {
    const t2 = 1.1;
    const pose = poseAt(REPORT, t2);
    for (const pAngle of [1e16, -1e16, 1e12, 1e300]) {
      const got = couplerPointMotion(REPORT, t2, pose, INPUT, 3, pAngle);
      const ref = referencePointAtPose(REPORT, t2, pose, INPUT, 3, pAngle);
      const rates = referenceRatesAtPose(REPORT, t2, pose, INPUT);
      // The pose and pAngle are exact inputs: the point tolerance without pose rounding.
      const tol = pointTolerance(REPORT, rates, rateToleranceAtPose(REPORT, rates, INPUT), INPUT, 3, 0);
      const what = `pAngle = ${pAngle}`;
      expectNear(got.x, ref.x, tol.position, `${what} x`);
      expectNear(got.y, ref.y, tol.position, `${what} y`);
      expectNear(got.vx, ref.vx, tol.velocity, `${what} vx`);
      expectNear(got.vy, ref.vy, tol.velocity, `${what} vy`);
      expectNear(got.ax, ref.ax, tol.acceleration, `${what} ax`);
      expectNear(got.ay, ref.ay, tol.acceleration, `${what} ay`);
      const p = couplerPoint(REPORT, t2, pose.theta3, 3, pAngle);
      expectNear(p.x, ref.x, tol.position, `couplerPoint ${what} x`);
      expectNear(p.y, ref.y, tol.position, `couplerPoint ${what} y`);
    }
  });

  it('puts P where the oracle does at theta2 = 1e16 with a huge theta3', () => {
    const t2 = 1e16;
    const pose = poseAt(REPORT, t2);
    const theta3 = pose.theta3 + 2 * Math.PI * 1e17;
    const ref = referencePointAtPose(REPORT, t2, { ...pose, theta3 }, INPUT, 3, 0.4);
    const p = couplerPoint(REPORT, t2, theta3, 3, 0.4);
    // Position: a few roundings of terms of size r2 + pDist.
    const tol = 10 * EPS * (REPORT.r2 + 3);
    expectNear(p.x, ref.x, tol, 'x');
    expectNear(p.y, ref.y, tol, 'y');
  });
});

describe('instantCenters at huge angles', () => {
  it('matches the oracle at theta2 from 1e10 to the largest double', () => {
    for (const t2 of HUGE) {
      const pose = poseAt(REPORT, t2);
      const got = instantCenters(REPORT, t2, pose);
      const ref = referenceInstantCenters(REPORT, t2, pose.theta3, pose.theta4);
      // Every factor is relatively accurate once the differences are reduced exactly (centerTol, 16 eps);
      // I24's floor is that of sin at an exactly kept difference of the reduced angles (metricsTolerance.ts).
      const floor24 = sinDifferenceFloor(REPORT.r2, referenceWrap(pose.theta3), referenceWrap(t2), ref.I24!.sinBetween);
      expectNear(got.I13!.x, ref.I13!.x, centerTol(ref.I13!.x), `I13.x at ${t2}`);
      expectNear(got.I13!.y, ref.I13!.y, centerTol(ref.I13!.y), `I13.y at ${t2}`);
      expectNear(got.I24!.x, ref.I24!.x, centerTol(ref.I24!.x, floor24), `I24.x at ${t2}`);
    }
  });
});

describe('transmissionAngle and velocityRatios at huge angles', () => {
  it('take the exact difference of huge pose angles', () => {
    for (const t2 of HUGE) {
      const pose = poseAt(REPORT, t2);
      const turned = { theta3: pose.theta3 + 2 * Math.PI * 1e16, theta4: pose.theta4 - 2 * Math.PI * 3e18 };
      // |angleDiff| of the exact difference, rounded once: within an ulp of mu (<= pi).
      const mu = Math.abs(referenceWrap(turned.theta4, turned.theta3));
      expectNear(transmissionAngle(turned), mu, 2 * EPS * mu, `mu at ${t2}`);
      const ref = referenceRatesAtPose(REPORT, t2, turned, { omega2: 1, alpha2: 0 });
      const tol = rateToleranceAtPose(REPORT, ref, { omega2: 1, alpha2: 0 });
      const v = velocityRatios(REPORT, t2, turned);
      expectNear(v.dTheta3, ref.omega3, tol.omega3, `dTheta3 at ${t2}`);
      expectNear(v.dTheta4, ref.omega4, tol.omega4, `dTheta4 at ${t2}`);
    }
  });
});

describe('reduceDifference', () => {
  it('gives sin and cos of the exact difference to full relative accuracy, also next to pi and 0', () => {
    const D = Decimal.clone({ precision: 60 });
    const parts = { hi: 0, lo: 0 };
    const pairs: Array<[number, number]> = [];
    for (const a of [...HUGE, 3, -2.5, 1e7, 2 ** 26 - 1, 2 ** 26 + 3]) {
      for (const b of [0.3, -3.1, Math.PI, 1e16, -7.5e17]) pairs.push([a, b]);
    }
    // Differences that reduce to within a few ulps of pi and of 0, where a rounded double loses the sine.
    pairs.push([-1e16, -1e16 + 2 ** 4], [1e16 + 2, 1e16], [355, 0], [710, 0], [Math.PI, -Math.PI]);
    for (const [a, b] of pairs) {
      reduceDifference(a, b, parts);
      const d = new D(reducedAngleDigits(a)).minus(reducedAngleDigits(b));
      for (const [got, ref] of [
        [Math.sin(parts.hi) + parts.lo * Math.cos(parts.hi), D.sin(d).toNumber()],
        [Math.cos(parts.hi) - parts.lo * Math.sin(parts.hi), D.cos(d).toNumber()],
      ]) {
        // Math.sin and Math.cos round once (an ulp), the first-order correction adds a couple of eps.
        expectNear(got, ref, 4 * EPS * Math.abs(ref), `sin/cos of ${a} - ${b}`);
      }
    }
  });
});
