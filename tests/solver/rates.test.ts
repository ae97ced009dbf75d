/**
 * Velocity and acceleration analysis (src/solver/rates.ts) against two independent oracles
 * (tests/oracle/rates.ts):
 *
 * - "at the pose": the differentiated loop equations solved by Cramer's rule at 60 digits for the
 *   very double angles given. The tolerance is the rounding bound of rateToleranceAtPose: K eps
 *   q |omega2| / |sin mu| for velocities (q = r2 / r3 or r2 / r4), the sum of the terms of the
 *   acceleration balance times K eps / |sin mu| for accelerations. This is where toggles, 1e+-7 scales,
 *   tiny cranks and poses within 1e-15 rad of a limit are checked.
 * - "true": finite differences of the 80-digit positions (no velocity equations at all), which checks
 *   the formulas and the sign conventions themselves. The pose fed in is the oracle's, within 4 eps,
 *   and rateToleranceTrue adds what that rounding moves the rates by; used where |sin mu| >= 1e-7.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Angles, Branch, InputMotion, Linkage } from '../../src/solver';
import {
  LIMIT_SIN_MU,
  couplerPointMotion,
  linkRates,
  solveClosedForm,
  sweep,
  sweepRates,
  theta2Grid,
} from '../../src/solver';
import {
  POSE_ROUNDING,
  pointTolerance,
  rateToleranceAtPose,
  rateToleranceTrue,
  referenceMotion,
  referencePointAtPose,
  referenceRatesAtPose,
} from '../oracle/rates';
import type { ReferenceMotion } from '../oracle/rates';
import { referenceLimits } from '../oracle/reference';
import { BRANCHES, CASES, degGrid, oracleOutcome, scaled, sigmaOf, where } from './helpers';

const RATES = ['omega3', 'omega4', 'alpha3', 'alpha4'] as const;
/** The app's default input (10 rad/s) with an input acceleration, so every term of the balance is exercised. */
const INPUT: InputMotion = { omega2: 10, alpha2: -3 };
/** The true-rate oracle differentiates with h = 1e-26: valid where |sin mu| >= about 1e-8 (see the oracle). */
const TRUE_ORACLE_MIN_SIN = 1e-7;
/** A coupler point off the line AB, as most textbook coupler points are. */
const P_DIST_OF_R3 = 0.7;
const P_ANGLE = 0.6;

type Pose = Angles;

function solvedPose(l: Linkage, theta2: number, branch: Branch): Pose {
  const p = solveClosedForm(l, theta2, branch);
  if (!p) throw new Error(`no pose at ${where(l, theta2, branch)}`);
  return p;
}

/** linkRates at the given pose equals the 60-digit rates of that pose within rateToleranceAtPose. */
function expectRatesAtPose(l: Linkage, theta2: number, pose: Pose, input: InputMotion, label: string): void {
  const ref = referenceRatesAtPose(l, theta2, pose, input);
  const got = linkRates(l, theta2, pose, input);
  if (Math.abs(ref.sinMu) <= LIMIT_SIN_MU) {
    // A limit position to within the documented threshold: the rates are unbounded and reported as NaN.
    for (const k of RATES) expect(got[k], `${label} ${k} at a limit (sin mu ${ref.sinMu})`).toBeNaN();
    return;
  }
  const tol = rateToleranceAtPose(l, ref, input);
  for (const k of RATES) {
    const err = Math.abs(got[k] - ref[k]);
    expect(
      err,
      `${label} ${k} at ${where(l, theta2, '-')}, pose (${pose.theta3}, ${pose.theta4}), sin mu ${ref.sinMu}: ` +
        `expected ${ref[k]} got ${got[k]} (error ${err} > tol ${tol[k]})`,
    ).toBeLessThanOrEqual(tol[k]);
  }
}

/**
 * linkRates and couplerPointMotion at the oracle's pose equal the differentiated 80-digit positions
 * within rateToleranceTrue and pointTolerance. Returns the oracle answer, or null where the
 * oracle has no unique pose or is too close to a limit for finite differences.
 */
function expectTrueMotion(
  l: Linkage,
  theta2: number,
  branch: Branch,
  input: InputMotion,
  label: string,
): ReferenceMotion | null {
  const outcome = oracleOutcome(l, theta2, branch);
  if (outcome.kind !== 'unique' || Math.abs(outcome.pose.sinMu) < TRUE_ORACLE_MIN_SIN) return null;
  const pDist = P_DIST_OF_R3 * l.r3;
  const ref = referenceMotion(l, theta2, sigmaOf(branch), input, pDist, P_ANGLE);
  const pose = { theta3: ref.theta3, theta4: ref.theta4 };
  const ctx = `${label} at ${where(l, theta2, branch)}, sin mu ${ref.sinMu}`;
  const tol = rateToleranceTrue(l, ref, input);
  const got = linkRates(l, theta2, pose, input);
  for (const k of RATES) {
    const err = Math.abs(got[k] - ref[k]);
    expect(err, `${ctx}: ${k} expected ${ref[k]} got ${got[k]} (error ${err} > tol ${tol[k]})`).toBeLessThanOrEqual(
      tol[k],
    );
  }
  const pt = couplerPointMotion(l, theta2, pose, input, pDist, P_ANGLE);
  const ptol = pointTolerance(l, ref, tol, input, pDist, POSE_ROUNDING);
  const pairs = [
    ['x', 'position'],
    ['y', 'position'],
    ['vx', 'velocity'],
    ['vy', 'velocity'],
    ['ax', 'acceleration'],
    ['ay', 'acceleration'],
  ] as const;
  for (const [k, kind] of pairs) {
    const err = Math.abs(pt[k] - ref.point[k]);
    expect(
      err,
      `${ctx}: P.${k} expected ${ref.point[k]} got ${pt[k]} (error ${err} > tol ${ptol[kind]})`,
    ).toBeLessThanOrEqual(ptol[kind]);
  }
  return ref;
}

/** Input angles approaching each input limit of l from inside, at distances 1e-3 .. 1e-15 rad. */
function nearLimitAngles(l: Linkage): number[] {
  const lim = referenceLimits(l);
  if (lim.empty) return [];
  const out: number[] = [];
  for (const d of [1e-3, 1e-6, 1e-9, 1e-12, 1e-15]) {
    for (const sign of [1, -1]) {
      if (lim.hasLower && lim.lowerAbs > 0) out.push(sign * (lim.lowerAbs + d * Math.max(1, lim.lowerAbs)));
      if (lim.hasUpper) out.push(sign * (lim.upperAbs - d * lim.upperAbs));
    }
  }
  return out;
}

describe('linkRates', () => {
  it('equals the derivatives of the 80-digit positions on every hard case, both branches, around the circle', () => {
    let checked = 0;
    for (const [name, l] of Object.entries(CASES)) {
      for (const t2 of degGrid(-180, 135, 45)) {
        for (const branch of BRANCHES) {
          if (expectTrueMotion(l, t2, branch, INPUT, `case ${name}`)) checked++;
        }
      }
    }
    // Most of the 20 cases x 8 angles x 2 branches assemble; make sure the loop did not skip them all.
    expect(checked).toBeGreaterThan(200);
  });

  it('is exact to rounding at the solved pose on every hard case, both branches, around the circle', () => {
    let checked = 0;
    for (const l of Object.values(CASES)) {
      for (const t2 of degGrid(-180, 165, 15)) {
        for (const branch of BRANCHES) {
          const pose = solveClosedForm(l, t2, branch);
          if (!pose || pose.limit || pose.continuum) continue;
          expectRatesAtPose(l, t2, pose, INPUT, branch);
          checked++;
        }
      }
    }
    // 20 cases x 24 angles x 2 branches, less the unreachable points.
    expect(checked).toBeGreaterThan(600);
  });

  it('stays exact to rounding approaching every toggle, down to 1e-15 rad from the limit', () => {
    let checked = 0;
    for (const l of Object.values(CASES)) {
      for (const t2 of nearLimitAngles(l)) {
        for (const branch of BRANCHES) {
          const pose = solveClosedForm(l, t2, branch);
          if (!pose || pose.limit) continue;
          expectRatesAtPose(l, t2, pose, INPUT, `near limit ${branch}`);
          checked++;
        }
      }
    }
    // Seven of the cases have input limits (5 distances x 2 signs x 2 branches each, fewer where limits coincide).
    expect(checked).toBeGreaterThan(100);
  });

  it('grows like 1 / sin mu towards a toggle of the non-Grashof triple rocker (case 10), on both branches', () => {
    const l = CASES[10];
    const upper = referenceLimits(l).upperAbs;
    for (const branch of BRANCHES) {
      let previous = 0;
      for (const d of [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12]) {
        const t2 = upper - d;
        const pose = solvedPose(l, t2, branch);
        const r = linkRates(l, t2, pose, INPUT);
        const sinMu = Math.sin(pose.theta4 - pose.theta3);
        expect(Math.sign(sinMu)).toBe(sigmaOf(branch));
        // omega4 sin mu = omega2 (r2 / r4) sin(theta2 - theta3) stays finite and away from 0 here...
        const w4s = r.omega4 * sinMu;
        expect(Math.abs(w4s)).toBeGreaterThan(1);
        expect(Math.abs(w4s)).toBeLessThan(INPUT.omega2 * (l.r2 / l.r4));
        // ...so |omega4| grows without bound as the distance d to the limit shrinks (sin mu ~ sqrt(d)).
        expect(Math.abs(r.omega4)).toBeGreaterThan(previous);
        previous = Math.abs(r.omega4);
        expect(Number.isFinite(r.alpha3) && Number.isFinite(r.alpha4)).toBe(true);
        expectRatesAtPose(l, t2, pose, INPUT, `case 10 ${branch} ${d} from the limit`);
        if (d >= 1e-8) expectTrueMotion(l, t2, branch, INPUT, `case 10, ${d} from the limit`);
      }
      expect(previous).toBeGreaterThan(1e5);
    }
  });

  it('keeps alpha exact at a toggle where coupler and rocker are nearly equal (mu -> 0, r4 = r3 + 1e-3)', () => {
    // |r1 - r2| = 1e-3 < |r4 - r3| = 2e-3: the crank stops where A is 2e-3 from O4, coupler and rocker
    // folded onto each other (mu -> 0). There omega3 and omega4 grow like 1 / sin mu but omega3 - omega4
    // is a thousand times smaller, and the textbook form of the acceleration equations (r3 omega3^2 against
    // r4 omega4^2) would lose those three digits to cancellation.
    const l = { r1: 4, r2: 3.999, r3: 2, r4: 2.002 };
    const lim = referenceLimits(l);
    expect(lim.hasLower).toBe(true);
    let checked = 0;
    for (const d of [1e-3, 1e-5, 1e-7, 1e-9, 1e-11]) {
      for (const sign of [1, -1]) {
        const t2 = sign * (lim.lowerAbs + d);
        for (const branch of BRANCHES) {
          const pose = solvedPose(l, t2, branch);
          expect(Math.cos(pose.theta4 - pose.theta3)).toBeGreaterThan(0.9);
          expectRatesAtPose(l, t2, pose, INPUT, `nearly equal links ${branch}, ${d} from the toggle`);
          if (d >= 1e-5) expectTrueMotion(l, t2, branch, INPUT, 'nearly equal links');
          checked++;
        }
      }
    }
    expect(checked).toBe(20);
  });

  it('is exact to rounding through the change point of 2-2-4-4 (crank pin passing over O4)', () => {
    // r1 = r2 and r3 = r4: at theta2 = 0 the crank pin sits on O4 and sin mu -> 0 while the rates stay
    // bounded on the open branch (numerator and sin mu vanish together).
    const l = CASES[8];
    for (const t2 of [1e-3, -1e-5, 1e-7, -1e-9]) {
      for (const branch of BRANCHES) {
        const pose = solvedPose(l, t2, branch);
        expectRatesAtPose(l, t2, pose, INPUT, `case 8 ${branch}`);
        if (Math.abs(t2) >= 1e-5) expectTrueMotion(l, t2, branch, INPUT, 'case 8');
      }
      const open = linkRates(l, t2, solvedPose(l, t2, 'open'), INPUT);
      expect(Math.abs(open.omega3) + Math.abs(open.omega4)).toBeLessThan(2 * INPUT.omega2);
    }
  });

  it('is unchanged, up to rounding of the lengths, for links scaled by 1e7 and 1e-7', () => {
    for (const [name, base] of Object.entries(CASES)) {
      for (const k of [1e7, 1e-7]) {
        const l = scaled(base, k);
        for (const t2 of degGrid(-150, 150, 60)) {
          for (const branch of BRANCHES) {
            const pose = solveClosedForm(l, t2, branch);
            if (!pose || pose.limit || pose.continuum) continue;
            expectRatesAtPose(l, t2, pose, INPUT, `case ${name} x ${k}`);
          }
        }
      }
    }
    const l = scaled(CASES[1], 1e7);
    for (const branch of BRANCHES) expectTrueMotion(l, 1, branch, INPUT, 'case 1 x 1e7');
    const s = scaled(CASES[1], 1e-7);
    for (const branch of BRANCHES) expectTrueMotion(s, 1, branch, INPUT, 'case 1 x 1e-7');
  });

  it('gives rates of order r2 / r for a tiny crank (1e-6 and 1e-300)', () => {
    for (const l of [CASES[15], CASES[19]]) {
      for (const t2 of [0.3, 2, -2.5]) {
        for (const branch of BRANCHES) {
          const pose = solvedPose(l, t2, branch);
          const r = linkRates(l, t2, pose, INPUT);
          expect(Math.abs(r.omega3)).toBeLessThanOrEqual((10 * l.r2 * INPUT.omega2) / l.r3);
          expect(Math.abs(r.omega3)).toBeGreaterThan(0);
          expectRatesAtPose(l, t2, pose, INPUT, 'tiny crank');
          expectTrueMotion(l, t2, branch, INPUT, 'tiny crank');
        }
      }
    }
  });

  it('gives each branch its own rates (open and crossed differ and each matches its oracle)', () => {
    const l = CASES[1];
    const t2 = 1;
    const open = linkRates(l, t2, solvedPose(l, t2, 'open'), INPUT);
    const crossed = linkRates(l, t2, solvedPose(l, t2, 'crossed'), INPUT);
    expect(Math.abs(open.omega4 - crossed.omega4)).toBeGreaterThan(1);
    expect(expectTrueMotion(l, t2, 'open', INPUT, 'open')).not.toBeNull();
    expect(expectTrueMotion(l, t2, 'crossed', INPUT, 'crossed')).not.toBeNull();
  });

  it('returns NaN rates at a limit position (sin mu = 0 within the rounding of the pose)', () => {
    const exactlyFlat = linkRates(CASES[1], 1, { theta3: 0.3, theta4: 0.3 }, INPUT);
    const folded = linkRates(CASES[1], 1, { theta3: 0.3, theta4: 0.3 + Math.PI }, INPUT);
    // Change point 4-1-3-2 at theta2 = pi: crank, coupler and rocker flat; the closed form flags the limit.
    const cp = solveClosedForm(CASES[4], Math.PI, 'open')!;
    expect(cp.limit).toBe(true);
    const changePoint = linkRates(CASES[4], Math.PI, cp, INPUT);
    // 2-2-4-4 at theta2 = 0: the crank pin on O4, theta3 = theta4 (one member of the continuum).
    const pin = solveClosedForm(CASES[8], 0, 'open')!;
    expect(pin.continuum).toBe(true);
    const continuum = linkRates(CASES[8], 0, pin, INPUT);
    for (const r of [exactlyFlat, folded, changePoint, continuum]) {
      for (const k of RATES) expect(r[k], k).toBeNaN();
    }
  });

  it('answers finitely and exactly just outside the limit threshold', () => {
    // theta4 - theta3 = 8 eps exactly: sin mu = 8 eps > LIMIT_SIN_MU, the rates are huge but exact.
    const pose = { theta3: 0.25, theta4: 0.25 + 8 * Number.EPSILON };
    expect(Math.sin(pose.theta4 - pose.theta3)).toBeGreaterThan(LIMIT_SIN_MU);
    const r = linkRates(CASES[1], 1, pose, INPUT);
    for (const k of RATES) expect(Number.isFinite(r[k]), k).toBe(true);
    expectRatesAtPose(CASES[1], 1, pose, INPUT, 'just outside the threshold');
  });
});

describe('couplerPointMotion', () => {
  it('moves the crank pin A as a point of the crank when pDist = 0', () => {
    const l = CASES[1];
    const t2 = 0.8;
    const pose = solvedPose(l, t2, 'open');
    const m = couplerPointMotion(l, t2, pose, INPUT, 0, 1.2);
    const { omega2: w, alpha2: a } = INPUT;
    const [x, y] = [l.r2 * Math.cos(t2), l.r2 * Math.sin(t2)];
    expect(m).toEqual({ x, y, vx: -w * y, vy: w * x, ax: -a * y - w * w * x, ay: a * x - w * w * y });
  });

  it('moves the coupler pin B as a point of the rocker when pDist = r3, pAngle = 0', () => {
    for (const [name, l] of Object.entries(CASES)) {
      for (const t2 of degGrid(-170, 170, 40)) {
        for (const branch of BRANCHES) {
          const pose = solveClosedForm(l, t2, branch);
          if (!pose || pose.limit || pose.continuum) continue;
          const r = linkRates(l, t2, pose, INPUT);
          const m = couplerPointMotion(l, t2, pose, INPUT, l.r3, 0);
          // B = O4 + r4 e^{i theta4}: v_B = omega4 k x O4B, a_B = alpha4 k x O4B - omega4^2 O4B.
          const [ux, uy] = [l.r4 * Math.cos(pose.theta4), l.r4 * Math.sin(pose.theta4)];
          const ref = referenceRatesAtPose(l, t2, pose, INPUT);
          const rt = rateToleranceAtPose(l, ref, INPUT);
          // Both sides carry the error allowed for the rates, times the lever arm r3 or r4, plus the
          // closure error of the pose itself (each angle within 1e-9 here) times the rates.
          const closure = 1e-9 * Math.max(l.r3, l.r4);
          const w = Math.abs(r.omega3) + Math.abs(r.omega4) + Math.abs(INPUT.omega2);
          const vTol = (l.r3 + l.r4) * (rt.omega3 + rt.omega4) + closure * w + 1e-12 * l.r2 * INPUT.omega2;
          const aTol =
            (l.r3 + l.r4) * (rt.alpha3 + rt.alpha4 + 2 * w * (rt.omega3 + rt.omega4)) +
            closure * (w * w + Math.abs(r.alpha3) + Math.abs(r.alpha4) + Math.abs(INPUT.alpha2)) +
            1e-12 * l.r2 * (INPUT.omega2 ** 2 + Math.abs(INPUT.alpha2));
          const ctx = `case ${name} at ${where(l, t2, branch)}`;
          if (Math.abs(ref.sinMu) < 1e-6) continue; // the 1e-9 closure allowance assumes a well-conditioned pose
          expect(Math.abs(m.vx + r.omega4 * uy), `${ctx} vx`).toBeLessThanOrEqual(vTol);
          expect(Math.abs(m.vy - r.omega4 * ux), `${ctx} vy`).toBeLessThanOrEqual(vTol);
          expect(Math.abs(m.ax + r.alpha4 * uy + r.omega4 ** 2 * ux), `${ctx} ax`).toBeLessThanOrEqual(aTol);
          expect(Math.abs(m.ay - r.alpha4 * ux + r.omega4 ** 2 * uy), `${ctx} ay`).toBeLessThanOrEqual(aTol);
        }
      }
    }
  });

  it('is exact to rounding at the solved pose, for points on and off the coupler line', () => {
    for (const [name, l] of Object.entries(CASES)) {
      for (const t2 of degGrid(-160, 160, 80)) {
        for (const branch of BRANCHES) {
          const pose = solveClosedForm(l, t2, branch);
          if (!pose || pose.limit || pose.continuum) continue;
          const ref = referenceRatesAtPose(l, t2, pose, INPUT);
          if (Math.abs(ref.sinMu) <= LIMIT_SIN_MU) {
            // At a limit position P still has a place but no finite velocity or acceleration.
            const at = couplerPointMotion(l, t2, pose, INPUT, 0.5 * l.r3, 0);
            expect(Number.isFinite(at.x) && Number.isNaN(at.vx) && Number.isNaN(at.ay)).toBe(true);
            continue;
          }
          const rateTol = rateToleranceAtPose(l, ref, INPUT);
          for (const [pDist, pAngle] of [
            [0.5 * l.r3, 0],
            [1.3 * l.r3, -2.2],
            [-0.4 * l.r3, 0.9],
          ]) {
            const tol = pointTolerance(l, ref, rateTol, INPUT, pDist, 0);
            const want = referencePointAtPose(l, t2, pose, INPUT, pDist, pAngle);
            const got = couplerPointMotion(l, t2, pose, INPUT, pDist, pAngle);
            const ctx = `case ${name} P(${pDist}, ${pAngle}) at ${where(l, t2, branch)}`;
            const pairs = [
              ['x', tol.position],
              ['y', tol.position],
              ['vx', tol.velocity],
              ['vy', tol.velocity],
              ['ax', tol.acceleration],
              ['ay', tol.acceleration],
            ] as const;
            for (const [k, t] of pairs) {
              const err = Math.abs(got[k] - want[k]);
              expect(
                err,
                `${ctx} ${k}: expected ${want[k]} got ${got[k]} (error ${err} > tol ${t})`,
              ).toBeLessThanOrEqual(t);
            }
          }
        }
      }
    }
  });

  it('keeps the position finite and reports NaN velocity and acceleration at a limit position', () => {
    const cp = solveClosedForm(CASES[4], Math.PI, 'open')!;
    const m = couplerPointMotion(CASES[4], Math.PI, cp, INPUT, 1.5, 0.4);
    expect(Number.isFinite(m.x) && Number.isFinite(m.y)).toBe(true);
    for (const k of ['vx', 'vy', 'ax', 'ay'] as const) expect(m[k], k).toBeNaN();
  });
});

describe('sweepRates', () => {
  it('equals linkRates at every solved point and is NaN elsewhere', () => {
    for (const [l, branch] of [
      [CASES[1], 'open'],
      [CASES[10], 'crossed'],
      [CASES[12], 'open'],
    ] as const) {
      const grid = theta2Grid(0, 360, 1);
      const res = sweep(l, grid, { branch });
      const ok = (i: number) => res.status[i] === 'ok';
      const r = sweepRates(l, res.theta2, res.theta3, res.theta4, ok, INPUT);
      let solved = 0;
      for (let i = 0; i < grid.length; i++) {
        if (!ok(i)) {
          for (const k of RATES) expect(r[k][i], `${k}[${i}]`).toBeNaN();
          continue;
        }
        solved++;
        const one = linkRates(l, res.theta2[i], { theta3: res.theta3[i], theta4: res.theta4[i] }, INPUT);
        for (const k of RATES) expect(Object.is(r[k][i], one[k]), `${k}[${i}] ${r[k][i]} vs ${one[k]}`).toBe(true);
      }
      expect(solved).toBeGreaterThan(50);
      for (const k of RATES) expect(r[k]).toHaveLength(grid.length);
    }
  });

  it('leaves points that ok() rejects NaN even where their angles are finite', () => {
    const l = CASES[1];
    const res = sweep(l, theta2Grid(0, 360, 5), { branch: 'open' });
    const ok = (i: number) => i % 3 !== 0;
    const r = sweepRates(l, res.theta2, res.theta3, res.theta4, ok, INPUT);
    for (let i = 0; i < res.theta2.length; i++) {
      expect(Number.isFinite(res.theta3[i])).toBe(true);
      for (const k of RATES) expect(Number.isNaN(r[k][i]), `${k}[${i}]`).toBe(!ok(i));
    }
  });
});

describe('rate properties (fast-check, fixed seed)', () => {
  const RUNS = { seed: 42, numRuns: 200 } as const;
  const length = fc.double({ min: -2, max: 2, noNaN: true }).map((u) => 10 ** u);
  const linkageArb: fc.Arbitrary<Linkage> = fc.record({ r1: length, r2: length, r3: length, r4: length });
  const inputArb: fc.Arbitrary<InputMotion> = fc.record({
    omega2: fc.tuple(fc.double({ min: -2, max: 3, noNaN: true }), fc.constantFrom(1, -1)).map(([e, s]) => s * 10 ** e),
    alpha2: fc.double({ min: -1e4, max: 1e4, noNaN: true }),
  });
  const reachableArb = fc
    .record({
      l: linkageArb,
      u: fc.double({ min: 0.001, max: 0.999, noNaN: true }),
      sign: fc.constantFrom(1, -1),
      branch: fc.constantFrom<Branch>('open', 'crossed'),
    })
    .map(({ l, u, sign, branch }) => {
      const lim = referenceLimits(l);
      if (lim.empty) return null;
      return { l, theta2: sign * (lim.lowerAbs + u * (lim.upperAbs - lim.lowerAbs)), branch };
    })
    .filter((x): x is { l: Linkage; theta2: number; branch: Branch } => x !== null);

  it('is exact to rounding at the solved pose for random linkages, inputs and branches', () => {
    fc.assert(
      fc.property(reachableArb, inputArb, ({ l, theta2, branch }, input) => {
        const pose = solveClosedForm(l, theta2, branch);
        if (!pose || pose.limit || pose.continuum) return;
        expectRatesAtPose(l, theta2, pose, input, `random ${branch}`);
      }),
      RUNS,
    );
  });

  it('equals the derivatives of the true positions for random linkages, inputs and branches', () => {
    fc.assert(
      fc.property(reachableArb, inputArb, ({ l, theta2, branch }, input) => {
        expectTrueMotion(l, theta2, branch, input, `random`);
      }),
      { ...RUNS, numRuns: 60 },
    );
  });

  it('scales velocities by k and accelerations by k^2 when omega2 is scaled by k (alpha2 = 0), exactly', () => {
    fc.assert(
      fc.property(reachableArb, fc.constantFrom(2, -1, -0.5, 1024), ({ l, theta2, branch }, k) => {
        const pose = solveClosedForm(l, theta2, branch);
        if (!pose) return;
        const a = linkRates(l, theta2, pose, { omega2: 3, alpha2: 0 });
        const b = linkRates(l, theta2, pose, { omega2: 3 * k, alpha2: 0 });
        // Multiplying by a power of two (or -1) is exact, and every rate is a product with omega2 or omega2^2.
        expect(b.omega3).toBe(a.omega3 * k);
        expect(b.omega4).toBe(a.omega4 * k);
        expect(b.alpha3).toBe(a.alpha3 * k * k);
        expect(b.alpha4).toBe(a.alpha4 * k * k);
      }),
      RUNS,
    );
  });
});

describe('bad input', () => {
  const l = CASES[1];
  const pose = { theta3: 0.5, theta4: 1.5 };
  const cases: Array<[string, () => unknown, RegExp]> = [
    [
      'negative length',
      () => linkRates({ ...l, r3: -1 }, 1, pose, INPUT),
      /r3 must be a positive finite length, got -1/,
    ],
    [
      'NaN length',
      () => couplerPointMotion({ ...l, r1: NaN }, 1, pose, INPUT, 1, 0),
      /r1 must be a positive finite length, got NaN/,
    ],
    ['linkage null', () => linkRates(null as unknown as Linkage, 1, pose, INPUT), /linkage must be an object/],
    ['theta2 NaN', () => linkRates(l, NaN, pose, INPUT), /theta2 must be a finite angle in radians, got NaN/],
    [
      'theta2 Infinity',
      () => couplerPointMotion(l, Infinity, pose, INPUT, 1, 0),
      /theta2 must be a finite angle in radians, got Infinity/,
    ],
    [
      'pose null',
      () => linkRates(l, 1, null as unknown as Angles, INPUT),
      /pose must be an object with theta3 and theta4 \(radians\), got null/,
    ],
    [
      'pose a number',
      () => linkRates(l, 1, 3 as unknown as Angles, INPUT),
      /pose must be an object with theta3 and theta4 \(radians\), got 3/,
    ],
    [
      'pose.theta3 NaN',
      () => linkRates(l, 1, { theta3: NaN, theta4: 1 }, INPUT),
      /pose\.theta3 must be a finite angle in radians, got NaN/,
    ],
    [
      'pose.theta4 missing',
      () => linkRates(l, 1, { theta3: 1 } as Angles, INPUT),
      /pose\.theta4 must be a finite angle in radians, got undefined \(missing\)/,
    ],
    [
      'pose.theta4 a string',
      () => linkRates(l, 1, { theta3: 1, theta4: '2' } as unknown as Angles, INPUT),
      /pose\.theta4 must be a finite angle in radians, got "2"/,
    ],
    [
      'omega2 NaN',
      () => linkRates(l, 1, pose, { omega2: NaN, alpha2: 0 }),
      /input\.omega2 must be a finite angular velocity in rad\/s, got NaN/,
    ],
    [
      'omega2 Infinity',
      () => couplerPointMotion(l, 1, pose, { omega2: Infinity, alpha2: 0 }, 1, 0),
      /input\.omega2 must be a finite angular velocity in rad\/s, got Infinity/,
    ],
    [
      'alpha2 -Infinity',
      () => linkRates(l, 1, pose, { omega2: 1, alpha2: -Infinity }),
      /input\.alpha2 must be a finite angular acceleration in rad\/s², got -Infinity/,
    ],
    [
      'alpha2 missing',
      () => linkRates(l, 1, pose, { omega2: 1 } as InputMotion),
      /input\.alpha2 must be a finite angular acceleration in rad\/s², got undefined \(missing\)/,
    ],
    [
      'input null',
      () => linkRates(l, 1, pose, null as unknown as InputMotion),
      /input must be an object with omega2 \(rad\/s\) and alpha2 \(rad\/s²\), got null/,
    ],
    ['pDist NaN', () => couplerPointMotion(l, 1, pose, INPUT, NaN, 0), /pDist must be a finite length, got NaN/],
    [
      'pDist Infinity',
      () => couplerPointMotion(l, 1, pose, INPUT, Infinity, 0),
      /pDist must be a finite length, got Infinity/,
    ],
    [
      'pAngle NaN',
      () => couplerPointMotion(l, 1, pose, INPUT, 1, NaN),
      /pAngle must be a finite angle in radians, got NaN/,
    ],
    [
      'sweep omega2 NaN',
      () => sweepRates(l, [1], [0.5], [1.5], () => true, { omega2: NaN, alpha2: 0 }),
      /input\.omega2 must be a finite angular velocity in rad\/s, got NaN/,
    ],
    [
      'sweep bad length',
      () => sweepRates({ ...l, r2: 0 }, [1], [0.5], [1.5], () => true, INPUT),
      /r2 must be a positive finite length, got 0/,
    ],
    [
      'sweep theta3 too short',
      () => sweepRates(l, [1, 2, 3], [0.5, 0.5], [1, 1, 1], () => true, INPUT),
      /theta3 must have the length of theta2 \(3\), got 2/,
    ],
    [
      'sweep theta4 too long',
      () => sweepRates(l, [1], [0.5], [1, 1], () => true, INPUT),
      /theta4 must have the length of theta2 \(1\), got 2/,
    ],
  ];
  it.each(cases)('throws an Error naming the field: %s', (_label, call, message) => {
    expect(call).toThrow(message);
  });
});
