/**
 * Cycle quantities: torqueCycleStats on torque curves with known integrals, and forceCycle on a real
 * crank-rocker against an independent fine-grid integration of the torque the energy balance requires
 * (no Newton–Euler equation on the test's side).
 */
import { describe, expect, it } from 'vitest';
import type { LinkInertia, LinkInertias, Loads } from '../../src/solver';
import { forceCycle, linkRates, solveClosedForm, torqueCycleStats } from '../../src/solver';
import { gravityVector, linkMotions } from './forcesOracle';

/** n + 1 angles from 0 to 2 pi inclusive. */
function turn(n: number): Float64Array {
  return Float64Array.from({ length: n + 1 }, (_, i) => (2 * Math.PI * i) / n);
}

describe('torqueCycleStats', () => {
  it('gives the mean, RMS, extremes and ΔE = 2A of T = T0 + A sin(theta2), ΔE to O(h²)', () => {
    const [T0, A] = [2, 5];
    const err = (n: number) => {
      const theta = turn(n);
      const s = torqueCycleStats(
        theta,
        theta.map((t) => T0 + A * Math.sin(t)),
        10,
        0.05,
      );
      expect(s.status).toBe('ok');
      // The trapezoid rule on a whole period of a trigonometric polynomial is exact to rounding.
      expect(Math.abs(s.mean - T0)).toBeLessThanOrEqual(1e-13);
      expect(Math.abs(s.rms - Math.sqrt(T0 * T0 + (A * A) / 2))).toBeLessThanOrEqual(1e-13);
      // Grids of 4k points hold 90 and 270 degrees, where the extremes are.
      expect(Math.abs(s.max - (T0 + A))).toBeLessThanOrEqual(1e-13);
      expect(Math.abs(s.min - (T0 - A))).toBeLessThanOrEqual(1e-13);
      expect(s.peak).toBe(s.max);
      expect(s.flywheelInertia).toBe(s.energyFluctuation / 0.05 / 10 / 10);
      // E = A (1 - cos theta2) swings from 0 to 2A. Linear interpolation of T is off by at most
      // (h² / 12) ∫ |T''| = (h² / 12) 4A over the turn, twice that for the swing.
      const h = (2 * Math.PI) / n;
      const e = Math.abs(s.energyFluctuation - 2 * A);
      expect(e).toBeLessThanOrEqual(((h * h) / 6) * 4 * A);
      return e;
    };
    const [e360, e720] = [err(360), err(720)];
    expect(e360).toBeGreaterThan(0);
    // Second order: halving the step divides the error by 4.
    expect(e360 / e720).toBeGreaterThan(3.9);
    expect(e360 / e720).toBeLessThan(4.1);
  });

  it('is exact for a piecewise-linear torque, including extremes of the energy between samples', () => {
    // T = 1, -1, 1, -1, 1 at every quarter turn: the mean is 0 and the energy is 0 at every sample, but the
    // interpolant crosses zero mid-interval, where E peaks at ±(1/2)(1)(pi/4) = ±pi/8: ΔE = pi/4.
    const theta = [0, Math.PI / 2, Math.PI, (3 * Math.PI) / 2, 2 * Math.PI];
    const s = torqueCycleStats(theta, [1, -1, 1, -1, 1], 2, 0.1);
    expect(s.mean).toBe(0);
    expect(s.rms).toBe(1);
    expect(s.energyFluctuation).toBeCloseTo(Math.PI / 4, 15);
    // The same samples in reverse (the crank turning clockwise through theta2) swing as far.
    const back = torqueCycleStats([...theta].reverse(), [1, -1, 1, -1, 1], -2, 0.1);
    expect(back.energyFluctuation).toBeCloseTo(Math.PI / 4, 15);
    expect(back.flywheelInertia).toBe(s.flywheelInertia);
  });

  it('says why when the samples are not one full turn or a torque is missing', () => {
    const theta = turn(8);
    const T = theta.map((t) => Math.cos(t));
    const half = theta.map((t) => t / 2);
    expect(torqueCycleStats(half, T, 1, 0.05).status).toBe('not-a-full-turn');
    const shuffled = Float64Array.from(theta);
    [shuffled[2], shuffled[3]] = [shuffled[3], shuffled[2]];
    expect(torqueCycleStats(shuffled, T, 1, 0.05).status).toBe('not-a-full-turn');
    const gap = Float64Array.from(T);
    gap[4] = NaN;
    const s = torqueCycleStats(theta, gap, 1, 0.05);
    expect(s.status).toBe('missing-points');
    expect([s.mean, s.rms, s.peak, s.energyFluctuation, s.flywheelInertia].every(Number.isNaN)).toBe(true);
    // A crank at rest has a torque curve (quasi-static) but no speed to steady: no flywheel.
    const still = torqueCycleStats(theta, T, 0, 0.05);
    expect(still.status).toBe('ok');
    expect(still.energyFluctuation).toBeGreaterThan(0);
    expect(still.flywheelInertia).toBeNaN();
  });
});

describe('forceCycle', () => {
  // The report's 6-2-5-5 crank-rocker at 5 cm a unit: uniform bars of 4 kg/m (m = rho L, I = m L² / 12, CG mid).
  const l = { r1: 0.3, r2: 0.1, r3: 0.25, r4: 0.25 };
  const bar = (L: number): LinkInertia => ({
    mass: 4 * L,
    inertia: (4 * L * L * L) / 12,
    cg: { dist: L / 2, angle: 0 },
  });
  const inertia: LinkInertias = { crank: bar(l.r2), coupler: bar(l.r3), rocker: bar(l.r4) };
  const loads: Loads = {
    gravity: { g: 9.81 },
    couplerForce: { pDist: 0.15, pAngle: 0.5, fx: 10, fy: -20 },
    outputTorque: -2,
  };
  const input = { omega2: 30, alpha2: 0 };

  /** T12 from the energy balance alone, T12 omega2 = d(KE)/dt - external power, at theta2. */
  function energyTorque(theta2: number): number {
    const pose = solveClosedForm(l, theta2, 'open')!;
    const rates = linkRates(l, theta2, pose, input);
    const { links, vP } = linkMotions(l, theta2, pose, input, rates, inertia, loads);
    const g = gravityVector(loads);
    const f = loads.couplerForce!;
    let power = f.fx * vP.x + f.fy * vP.y + loads.outputTorque! * rates.omega4;
    let dKE = 0;
    for (const k of links) {
      power += k.mass * (g.x * k.vG.x + g.y * k.vG.y);
      dKE += k.mass * (k.vG.x * k.aG.x + k.vG.y * k.aG.y) + k.inertia * k.omega * k.alpha;
    }
    return (dKE - power) / input.omega2;
  }

  /** ΔE, mean and RMS on a fine grid: trapezoid sums of the energy balance's torque. */
  function fineReference(n: number): { dE: number; mean: number; rms: number; peak: number } {
    const theta = turn(n);
    const T = theta.map(energyTorque);
    const h = (2 * Math.PI) / n;
    let sum = 0;
    let sumSq = 0;
    for (let i = 0; i < n; i++) {
      sum += (h * (T[i] + T[i + 1])) / 2;
      sumSq += (h * (T[i] * T[i] + T[i + 1] * T[i + 1])) / 2;
    }
    const mean = sum / (2 * Math.PI);
    let e = 0;
    let lo = 0;
    let hi = 0;
    for (let i = 0; i < n; i++) {
      e += (h * (T[i] + T[i + 1] - 2 * mean)) / 2;
      lo = Math.min(lo, e);
      hi = Math.max(hi, e);
    }
    const peak = Math.max(...T.map(Math.abs));
    return { dE: hi - lo, mean, rms: Math.sqrt(sum === 0 ? 0 : sumSq / (2 * Math.PI)), peak };
  }

  it('matches a fine-grid integration of the energy balance: ΔE to O(h²), the flywheel from it', () => {
    const ref = fineReference(40000);
    const coarse = forceCycle(l, 'open', input, inertia, loads, { points: 360 });
    const fine = forceCycle(l, 'open', input, inertia, loads, { points: 3600, k: 0.02 });
    expect(coarse.status).toBe('ok');
    expect(fine.status).toBe('ok');
    const rel = (x: number, y: number) => Math.abs(x - y) / Math.abs(y);
    // Loads that do no net work over a turn (gravity, a constant force on a closed path, a constant torque on
    // a rocker that swings back) and a steady speed: the motor's mean torque is zero, to rounding.
    expect(Math.abs(fine.stats.mean)).toBeLessThanOrEqual(1e-12 * fine.stats.peak);
    expect(Math.abs(ref.mean)).toBeLessThanOrEqual(1e-9 * ref.peak);
    // RMS: both spectrally accurate; the reference's own sampling of the peak is off by O(h²).
    expect(rel(fine.stats.rms, ref.rms)).toBeLessThanOrEqual(1e-12);
    expect(rel(coarse.stats.rms, ref.rms)).toBeLessThanOrEqual(1e-12);
    expect(rel(fine.stats.peak, ref.peak)).toBeLessThanOrEqual(1e-5);
    // ΔE: O(h²), measured 4.9e-5 at 360 points and 4.8e-7 at 3600 (ΔE = 8.07 J); the reference, its step 11x
    // smaller than 3600 points, is about 4e-9 off.
    const e360 = rel(coarse.stats.energyFluctuation, ref.dE);
    const e3600 = rel(fine.stats.energyFluctuation, ref.dE);
    expect(e360).toBeLessThanOrEqual(1e-4);
    expect(e3600).toBeLessThanOrEqual(1e-6);
    expect(e360 / e3600).toBeGreaterThan(50);
    expect(fine.stats.flywheelInertia).toBe(fine.stats.energyFluctuation / 0.02 / 30 / 30);
    expect(coarse.stats.flywheelInertia).toBe(coarse.stats.energyFluctuation / 0.05 / 30 / 30);
    expect(coarse.theta2.length).toBe(361);
    expect(coarse.forces.torque.length).toBe(361);
  });

  it('has no cycle for a crank that cannot turn, nor one that passes a limit position', () => {
    const tripleRocker = forceCycle({ r1: 0.4, r2: 0.3, r3: 0.35, r4: 0.3 }, 'open', input, inertia, loads);
    expect(tripleRocker.status).toBe('crank-does-not-turn');
    expect(tripleRocker.stats.energyFluctuation).toBeNaN();
    expect(tripleRocker.stats.status).toBe('missing-points');
    // The parallelogram's crank turns, through two change points where every force is undefined.
    const parallelogram = forceCycle({ r1: 0.2, r2: 0.1, r3: 0.2, r4: 0.1 }, 'open', input, inertia, loads);
    expect(parallelogram.status).toBe('limit-position');
    expect(parallelogram.stats.mean).toBeNaN();
    // Lengths a rounding away from a change point (0.11 + 0.35 against 0.29 + 0.17): at theta2 = 0 the pose is
    // not quite flat (sin mu = 9e-9), so every force is finite there, but some 1e8 times the loads.
    const nearlyFlat = { r1: 0.29, r2: 0.11, r3: 0.17, r4: 0.35 };
    const almost = forceCycle(nearlyFlat, 'open', input, inertia, loads);
    expect(almost.forces.torque.every(Number.isFinite)).toBe(true);
    expect(almost.status).toBe('limit-position');
    expect(almost.stats.energyFluctuation).toBeNaN();
    // A drag link (double crank) turns fully.
    const dragLink = forceCycle({ r1: 0.1, r2: 0.2, r3: 0.229, r4: 0.15 }, 'open', input, inertia, loads);
    expect(dragLink.status).toBe('ok');
    expect(dragLink.stats.energyFluctuation).toBeGreaterThan(0);
  });
});
