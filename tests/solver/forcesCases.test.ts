/**
 * linkForces and sweepForces on cases a student can check by hand, at and near limit positions, and the
 * sweep form against the single-point form. Fij is the force of link i on link j (1 ground, 2 crank,
 * 3 coupler, 4 rocker), counter-clockwise torques positive, SI units (docs/forces.md).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { JointForces, LinkInertia } from '../../src/solver';
import { LIMIT_SIN_MU, classify, linkForces, solveClosedForm, sweepForces, wrapAngle } from '../../src/solver';
import { forceCaseArb } from './forcesOracle';

const STILL = { omega2: 0, alpha2: 0 };
const MASSLESS: LinkInertia = { mass: 0, inertia: 0, cg: { dist: 0, angle: 0 } };
/** A few eps of the largest force in the case (20 N): the hand values are exact, the solver rounds. */
const HAND_TOL = 1e-13;

function expectForces(got: JointForces, want: JointForces): void {
  for (const k of ['F12', 'F32', 'F43', 'F14', 'shakingForce'] as const) {
    expect(Math.abs(got[k].x - want[k].x), `${k}.x`).toBeLessThanOrEqual(HAND_TOL);
    expect(Math.abs(got[k].y - want[k].y), `${k}.y`).toBeLessThanOrEqual(HAND_TOL);
  }
  expect(Math.abs(got.torque - want.torque), 'torque').toBeLessThanOrEqual(HAND_TOL);
  expect(Math.abs(got.shakingMoment - want.shakingMoment), 'shakingMoment').toBeLessThanOrEqual(HAND_TOL);
}

function allNaN(f: JointForces): boolean {
  const values = [
    f.torque,
    f.shakingMoment,
    ...[f.F12, f.F32, f.F43, f.F14, f.shakingForce].flatMap((p) => [p.x, p.y]),
  ];
  return values.every(Number.isNaN);
}

describe('linkForces: worked cases', () => {
  // A 3-4-5 linkage: O2 = (0, 0), O4 = (0.6, 0); at theta2 = 0 the crank lies along the ground, A = (0.3, 0),
  // the coupler stands straight up to B = (0.3, 0.4) and the rocker O4B = (-0.3, 0.4) is 0.5 m long.
  const l = { r1: 0.6, r2: 0.3, r3: 0.4, r4: 0.5 };
  const pose = solveClosedForm(l, 0, 'open')!;

  it('holds a horizontal crank with a 2 kg weight against a 1.5 N·m load torque (statics)', () => {
    // The crank weighs W = 2 kg x 10 m/s² = 20 N at its middle (0.15, 0); the coupler and rocker are massless;
    // the machine driven by the rocker resists with -1.5 N·m (clockwise).
    // 1. The coupler carries no load of its own: a two-force member, so F43 lies along AB, F43 = (0, f).
    // 2. Rocker, moments about O4: the coupler pushes it with F34 = -F43 = (0, -f) at B, and O4B x F34 =
    //    (-0.3)(-f) - (0.4)(0) = 0.3 f. With the load torque: 0.3 f - 1.5 = 0, so f = 5 N: F43 = (0, 5).
    // 3. Rocker forces: F14 + F34 = 0, so F14 = (0, 5). Coupler: F23 = -F43, so F32 = -F23 = (0, 5).
    // 4. Crank forces: F12 + F32 + W = 0, so F12 = (0, 20) - (0, 5) = (0, 15).
    // 5. Crank, moments about O2: T12 + O2A x F32 + O2G x W = 0, O2A x F32 = 0.3 x 5 = 1.5,
    //    O2G x W = 0.15 x (-20) = -3, so T12 = 1.5 N·m: the motor holds the crank up counter-clockwise.
    // 6. The ground feels F21 + F41 = -(F12 + F14) = (0, -20), the crank's weight, and about O2 the motor's
    //    reaction -T12 plus O2O4 x F41 = 0.6 x (-5): -1.5 - 3 = -4.5 N·m. (The load torque comes from the
    //    driven machine, not the frame, so it is not part of the shaking moment.)
    const crank: LinkInertia = { mass: 2, inertia: 0.1, cg: { dist: 0.15, angle: 0 } };
    const loads = { gravity: { g: 10 }, outputTorque: -1.5 };
    const got = linkForces(l, 0, pose, STILL, { crank, coupler: MASSLESS, rocker: MASSLESS }, loads);
    expectForces(got, {
      status: 'ok',
      torque: 1.5,
      F12: { x: 0, y: 15 },
      F32: { x: 0, y: 5 },
      F43: { x: 0, y: 5 },
      F14: { x: 0, y: 5 },
      shakingForce: { x: 0, y: -20 },
      shakingMoment: -4.5,
    });
  });

  it('spins up an unbalanced crank: F12 = m a_G and T12 = (I_G + m d²) alpha2', () => {
    // Same pose, no gravity, the crank's 2 kg at 0.15 m with I_G = 0.02 kg·m², omega2 = 10 rad/s, alpha2 = 5 rad/s².
    // a_G = alpha2 k x O2G - omega2² O2G = (0, 0.75) + (-15, 0) m/s², so the bearing pushes the crank with
    // F12 = m a_G = (-30, 1.5) N (towards O2, and up to speed it up). Coupler and rocker carry nothing (F43
    // would have to lie along both AB and O4B), so T12 = I_G alpha2 + O2G x m a_G = 0.1 + 0.15 x 1.5 = 0.325 N·m,
    // which is (I_G + m d²) alpha2 = (0.02 + 0.045) x 5. The frame is pulled outward along the crank: (30, -1.5).
    const crank: LinkInertia = { mass: 2, inertia: 0.02, cg: { dist: 0.15, angle: 0 } };
    const got = linkForces(l, 0, pose, { omega2: 10, alpha2: 5 }, { crank, coupler: MASSLESS, rocker: MASSLESS }, {});
    expectForces(got, {
      status: 'ok',
      torque: 0.325,
      F12: { x: -30, y: 1.5 },
      F32: { x: 0, y: 0 },
      F43: { x: 0, y: 0 },
      F14: { x: 0, y: 0 },
      shakingForce: { x: 30, y: -1.5 },
      shakingMoment: -0.325,
    });
  });
});

describe('linkForces at and near limit positions', () => {
  const heavyCoupler = {
    crank: MASSLESS,
    coupler: { mass: 3, inertia: 0.05, cg: { dist: 0.2, angle: 0.1 } },
    rocker: MASSLESS,
  };
  const gravity = { gravity: { g: 9.81 } };

  it('returns NaN for every field where coupler and rocker are collinear (|sin mu| <= LIMIT_SIN_MU)', () => {
    const l = { r1: 0.4, r2: 0.3, r3: 0.35, r4: 0.3 };
    // A triple rocker at the end of its range: the closed form's limit pose, folded (mu = pi within rounding).
    const hi = classify(l).inputRange.intervals[0].hi;
    const limitPose = solveClosedForm(l, hi, 'open')!;
    expect(limitPose.limit).toBe(true);
    expect(allNaN(linkForces(l, hi, limitPose, STILL, heavyCoupler, gravity))).toBe(true);
    expect(linkForces(l, hi, limitPose, STILL, heavyCoupler, gravity).status).toBe('limit-position');
    // A parallelogram at its change point: all four pins on the ground line.
    const para = { r1: 2, r2: 1, r3: 2, r4: 1 };
    expect(allNaN(linkForces(para, 0, solveClosedForm(para, 0, 'open')!, STILL, heavyCoupler, gravity))).toBe(true);
    // Given poses either side of the threshold, mu = 0.9 and 1.1 LIMIT_SIN_MU; mu = pi as a double (sin mu =
    // 1.2e-16), and theta3 = -1, theta4 = pi - 1, whose exact difference is pi within an ulp of 2.1.
    for (const pose of [
      { theta3: 0, theta4: 0.9 * LIMIT_SIN_MU },
      { theta3: 0, theta4: Math.PI },
      { theta3: -1, theta4: Math.PI - 1 },
    ]) {
      expect(allNaN(linkForces(l, 1, pose, STILL, heavyCoupler, gravity)), JSON.stringify(pose)).toBe(true);
    }
    const justClear = linkForces(l, 1, { theta3: 0, theta4: 1.1 * LIMIT_SIN_MU }, STILL, heavyCoupler, gravity);
    expect(Number.isFinite(justClear.F43.x) && Number.isFinite(justClear.torque)).toBe(true);
  });

  it('gives pin forces that grow like 1 / |sin mu| towards a toggle (statics)', () => {
    // The same triple rocker approaching the end of its range. The rocker is massless and unloaded, a two-force
    // member: F43 lies along O4B, and the coupler's moments about A give r3 |F43| |sin mu| = |M3|, with M3 the
    // moment of the coupler's weight about A, m g d cos(theta3 + 0.1) (its CG 0.2 m out at 0.1 rad from AB).
    // M3 hardly changes as the pose settles, so |F43| grows like 1 / |sin mu| (and F12 = F43 - weight too).
    const l = { r1: 0.4, r2: 0.3, r3: 0.35, r4: 0.3 };
    const { mass, cg } = heavyCoupler.coupler;
    const hi = classify(l).inputRange.intervals[0].hi;
    for (const d of [1e-2, 1e-4, 1e-6, 1e-8, 1e-10]) {
      const pose = solveClosedForm(l, hi - d, 'open')!;
      const f = linkForces(l, hi - d, pose, STILL, heavyCoupler, gravity);
      const sinMu = Math.sin(pose.theta4 - pose.theta3);
      const m3 = mass * 9.81 * cg.dist * Math.cos(pose.theta3 + cg.angle);
      const f43 = Math.hypot(f.F43.x, f.F43.y);
      const want = Math.abs(m3) / (l.r3 * Math.abs(sinMu));
      // sin mu from 0.13 down to 1.3e-5 (it shrinks like the square root of d): F43 from 130 N to 1.3e6 N.
      // The test's own sin(theta4 - theta3) rounds the difference near pi: 4.4e-16 absolute, relative 1 / sin mu.
      const tol = 1e-13 + (4 * Number.EPSILON) / Math.abs(sinMu);
      expect(Math.abs(f43 - want) / want, `d ${d}, sin mu ${sinMu}`).toBeLessThanOrEqual(tol);
      expect(f43 * Math.abs(sinMu), `d ${d}`).toBeGreaterThan(16);
      expect(f43 * Math.abs(sinMu), `d ${d}`).toBeLessThan(17);
      // Along the line: F43 is parallel to the rocker.
      expect(Math.abs(f.F43.x * Math.sin(pose.theta4) - f.F43.y * Math.cos(pose.theta4)) / f43).toBeLessThan(1e-12);
    }
  });
});

describe('linkForces with huge angles', () => {
  it('answers for angles a whole number of turns away as for the same angles wrapped', () => {
    // theta4 = 6283185307179588 is an integer double 1e15 turns out; wrapAngle reduces it exactly (to an ulp).
    // A plain theta4 - theta3 would round it by up to half a radian before the sine.
    const l = { r1: 0.3, r2: 0.1, r3: 0.25, r4: 0.25 };
    const heavy: LinkInertia = { mass: 2, inertia: 0.03, cg: { dist: 0.1, angle: 0.2 } };
    const inertia = { crank: heavy, coupler: heavy, rocker: heavy };
    const loads = { gravity: { g: 9.81, angle: -1.2 }, couplerForce: { pDist: 0.1, pAngle: 1, fx: 5, fy: 7 } };
    const input = { omega2: 12, alpha2: -3 };
    for (const [theta2, theta3, theta4] of [
      [0.7, 0.3, 6283185307179588],
      [0.7 + 2 * Math.PI * 1e12, -2e16, 0.9],
    ]) {
      const far = linkForces(l, theta2, { theta3, theta4 }, input, inertia, loads);
      const near = linkForces(
        l,
        wrapAngle(theta2),
        { theta3: wrapAngle(theta3), theta4: wrapAngle(theta4) },
        input,
        inertia,
        loads,
      );
      const scale = Math.max(...[near.F12, near.F32, near.F43, near.F14].map((f) => Math.hypot(f.x, f.y)));
      for (const k of ['F12', 'F32', 'F43', 'F14', 'shakingForce'] as const) {
        // The two poses differ by the reduction's ulp and by how cos and sin round each form: a few eps.
        expect(Math.abs(far[k].x - near[k].x) / scale, `${k}.x at ${theta4}`).toBeLessThanOrEqual(1e-13);
        expect(Math.abs(far[k].y - near[k].y) / scale, `${k}.y at ${theta4}`).toBeLessThanOrEqual(1e-13);
      }
    }
  });
});

describe('sweepForces', () => {
  it('equals linkForces bit for bit at every point, and is NaN where the point is not ok (seeded)', () => {
    fc.assert(
      fc.property(forceCaseArb, (c) => {
        const pose = solveClosedForm(c.l, c.theta2, c.branch);
        if (!pose) return;
        const f = sweepForces(
          c.l,
          [c.theta2, c.theta2],
          [pose.theta3, NaN],
          [pose.theta4, NaN],
          (i) => i === 0,
          c.motion,
          c.inertia,
          c.loads,
        );
        const one = linkForces(c.l, c.theta2, pose, c.motion, c.inertia, c.loads);
        const pairs: Array<[Float64Array, number]> = [
          [f.torque, one.torque],
          [f.f12x, one.F12.x],
          [f.f12y, one.F12.y],
          [f.f32x, one.F32.x],
          [f.f32y, one.F32.y],
          [f.f43x, one.F43.x],
          [f.f43y, one.F43.y],
          [f.f14x, one.F14.x],
          [f.f14y, one.F14.y],
          [f.shakingX, one.shakingForce.x],
          [f.shakingY, one.shakingForce.y],
          [f.shakingMoment, one.shakingMoment],
        ];
        for (const [arr, v] of pairs) {
          expect(arr[0]).toBe(v);
          expect(arr[1]).toBeNaN();
        }
      }),
      { seed: 40, numRuns: 200 },
    );
  });
});
