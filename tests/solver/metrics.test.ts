/**
 * designMetrics and instantCenters as specifications: against the 60-digit oracle of
 * tests/oracle/metrics.ts with the tolerances of tests/oracle/metricsTolerance.ts (a few eps times the
 * value: the solver's triangle factors are exact sums, so needle-thin triangles keep every digit),
 * against the report's linkage and published crank-rocker designs, and on bad input.
 */
import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import type { Angles, Branch, Linkage } from '../../src/solver';
import { designMetrics, instantCenters, solveClosedForm, velocityRatios } from '../../src/solver';
import { referenceTransmission } from '../oracle/metrics';
import { angleTol } from '../oracle/metricsTolerance';
import { angleDiff, deg, referenceRockerSwing, toDeg } from '../oracle/reference';
import { EPS } from '../oracle/tolerance';
import { BRANCHES, CASES, sigmaOf } from './helpers';
import {
  describeLinkage,
  expectCentersMatchOracle,
  expectDeadCentrePoses,
  expectMatchesOracle,
  expectNear,
} from './metricsHelpers';

const REPORT: Linkage = CASES[1];

describe('designMetrics', () => {
  it("gives the report's 6-2-5-5 crank-rocker its printed transmission range and rocker swing on both branches", () => {
    // docs/hard-cases.md case 1: mu in [47.16, 106.26] deg; rocker swings 101.537..150.074 deg (open branch).
    for (const b of BRANCHES) {
      const m = expectMatchesOracle(REPORT, b);
      expectNear(toDeg(m.transmission.min), 47.16, 0.005, 'mu min (deg)');
      expectNear(toDeg(m.transmission.max), 106.26, 0.005, 'mu max (deg)');
      expect(m.transmission.theta2AtMin).toBe(0);
      expect(m.transmission.theta2AtMax).toBe(Math.PI);
      const s = sigmaOf(b);
      expectNear(toDeg(s * m.output!.extended.theta4), 101.537, 0.0005, `${b} extended theta4 (deg)`);
      expectNear(toDeg(s * m.output!.folded.theta4), 150.074, 0.0005, `${b} folded theta4 (deg)`);
      expectNear(toDeg(m.output!.swing), 150.074 - 101.537, 0.001, 'swing (deg)');
      expectDeadCentrePoses(REPORT, b, m);
    }
  });

  it("places the report linkage's rocker extremes where the acos-based reference puts them", () => {
    // A second, textbook derivation (reference.ts referenceRockerSwing: t4 = pi - acos(...)).
    const ext = referenceRockerSwing(REPORT);
    const m = designMetrics(REPORT, 'open');
    expectNear(m.output!.extended.theta4, ext.min, 1e-14, 'extended theta4 = rocker minimum');
    expectNear(m.output!.folded.theta4, ext.max, 1e-14, 'folded theta4 = rocker maximum');
  });

  it('is exact to rounding for a crank 1e-6 of the ground (swing and quick return of order 1e-6)', () => {
    const l = CASES[15]; // 1, 1e-6, 1, 1
    for (const b of BRANCHES) {
      const m = expectMatchesOracle(l, b);
      expectDeadCentrePoses(l, b, m);
      // Subtracting the two dead-centre angles would leave ~1e-10 relative error here.
      expect(m.output!.swing).toBeGreaterThan(1e-6);
      expect(m.output!.swing).toBeLessThan(1e-5);
      expect(m.timeRatio! - 1).toBeGreaterThan(1e-7);
    }
  });

  it('is exact to rounding with a rocker nearly at a toggle (mu within 1e-6 of 180 deg, dead centre on the ground)', () => {
    for (const l of [CASES[2], CASES[5]]) {
      for (const b of BRANCHES) {
        const m = expectMatchesOracle(l, b);
        expect(Math.PI - m.transmission.max).toBeGreaterThan(0);
        expect(Math.PI - m.transmission.max).toBeLessThan(1e-3);
        expectDeadCentrePoses(l, b, m);
      }
    }
  });

  it('is exact to rounding with both dead centres next to the ground line beyond a pivot', () => {
    // A tiny crank and a coupler of nearly r1 + r4 (or r4 - r1): B sits just beyond O4 (or behind O2) at
    // both dead centres, so the two angles at O4 (or O2) are both near 180 deg and their half-sum's sine
    // must come from the supplements.
    const r2 = 1e-6;
    const beyondO4: Linkage = { r1: 1, r2, r3: 2 - 2 * r2, r4: 1 };
    const behindO2: Linkage = { r1: 1, r2, r3: 2 + 2 * r2, r4: 3 };
    for (const l of [beyondO4, behindO2]) {
      for (const b of BRANCHES) {
        const m = expectMatchesOracle(l, b);
        expectDeadCentrePoses(l, b, m);
      }
    }
  });

  it('is exact to rounding with the coupler and rocker nearly folded at theta2 = 0 (mu near 0)', () => {
    const l = CASES[3]; // 5, 1, 6, 2 + 1e-9
    for (const b of BRANCHES) {
      const m = expectMatchesOracle(l, b);
      expect(m.transmission.min).toBeGreaterThan(0);
      expect(m.transmission.min).toBeLessThan(1e-3);
    }
  });

  it('is exact to rounding with a coupler almost equal to ground + crank', () => {
    // The transmission triangle at theta2 = pi has s = r1 + r2 within 2^-40 of r3: s^2 - r3^2 cancels.
    const rocking: Linkage = { r1: 1, r2: 0.1, r3: 1.1 - 2 ** -40, r4: 0.001 };
    // And a crank-rocker whose folded dead centre has r3 - r2 within 1e-12 of the ground.
    const crankRocker: Linkage = { r1: 1, r2: 0.25, r3: 1.25 - 1e-12, r4: 0.6 };
    for (const l of [rocking, crankRocker]) for (const b of BRANCHES) expectMatchesOracle(l, b);
    expect(designMetrics(crankRocker, 'open').output).not.toBeNull();
  });

  it('is exact to rounding for very unequal and extreme-scale links', () => {
    const k = 2 ** 600;
    const cases: Linkage[] = [
      CASES[16], // 1e6, 1, 1e6 + 0.5, 2
      CASES[19], // 6, 1e-300, 5, 5
      { r1: 6 * k, r2: 2 * k, r3: 5 * k, r4: 5 * k },
      { r1: 6 / k, r2: 2 / k, r3: 5 / k, r4: 5 / k },
      { r1: 6e200, r2: 2e200, r3: 5e200, r4: 5e200 },
      { r1: 6e-200, r2: 2e-200, r3: 5e-200, r4: 5e-200 },
    ];
    for (const l of cases) for (const b of BRANCHES) expectMatchesOracle(l, b);
    // A power-of-two scale changes nothing at all.
    expect(designMetrics(cases[2], 'open')).toEqual(designMetrics(REPORT, 'open'));
    expect(designMetrics(cases[3], 'crossed')).toEqual(designMetrics(REPORT, 'crossed'));
  });

  it('reproduces published crank-rocker designs (Goessner, crocker.js README examples)', () => {
    // S. Goessner, crocker.js (companion to "Getriebelehre - Vektorielle Analyse ebener Mechanismen"),
    // README "Simple Crank-Rocker" and "Optimal Crank-Rocker": frame d = 120, rocker range psi0 = 80 deg,
    // forth/back time ratio 10/9; crank a = 60 gives printed coupler b = 103, rocker c = 94, mu_min = 35 deg;
    // the optimal crank a = 46.7 gives printed b = 116, c = 73.9, mu_min = 37.7 deg. b and c are rebuilt
    // here from the library's closed-form relations in 60 digits (so swing and time ratio are exact
    // targets); the printed, rounded values bound them. mu_min there is folded to <= 90 deg.
    const D = Decimal.clone({ precision: 60 });
    const design = (a: number, d: number): Linkage => {
      const [A, F, pi] = [new D(a), new D(d), D.acos(-1)];
      const tfb = new D(10).div(9);
      const alpha = pi.times(tfb.minus(1)).div(tfb.plus(1));
      const h = pi.times(80).div(360); // psi0 / 2
      const g = h.minus(alpha.div(2));
      const b = F.pow(2)
        .times(D.sin(h).pow(2))
        .minus(A.pow(2).times(D.cos(g).pow(2)))
        .div(D.sin(g).pow(2))
        .sqrt();
      const c = A.pow(2)
        .times(D.sin(h.minus(alpha)))
        .div(D.sin(h))
        .plus(F.pow(2).times(D.sin(alpha.div(2)).pow(2)))
        .div(D.sin(g).pow(2))
        .sqrt();
      return { r1: d, r2: a, r3: b.toNumber(), r4: c.toNumber() };
    };
    const printed = [
      { a: 60, b: 103, c: 94, muMinDeg: 35, digits: 0.5 },
      { a: 46.7, b: 116, c: 73.9, muMinDeg: 37.7, digits: 0.05 },
    ];
    for (const p of printed) {
      const l = design(p.a, 120);
      expectNear(l.r3, p.b, 0.5, 'coupler length (printed to 3 digits)');
      expectNear(l.r4, p.c, p.digits, 'rocker length (printed)');
      for (const b of BRANCHES) {
        const m = expectMatchesOracle(l, b);
        expectNear(m.output!.swing, deg(80), 1e-13, 'rocker range psi0 = 80 deg');
        expectNear(m.timeRatio!, 10 / 9, 1e-13, 'time ratio 10/9');
        const muMin = Math.min(m.transmission.min, Math.PI - m.transmission.max);
        expectNear(toDeg(muMin), p.muMinDeg, p.digits, 'mu_min (printed, folded to <= 90 deg)');
      }
    }
  });

  it('gives a time ratio of exactly 1 when r1^2 + r2^2 = r3^2 + r4^2 and more than 1 next to it', () => {
    // Crank pivot on the line through the two rocker extremes: no quick return (e.g. Norton's
    // construction for a time ratio of 1). 49 + 1 = 25 + 25 and 64 + 1 = 16 + 49.
    for (const l of [
      { r1: 7, r2: 1, r3: 5, r4: 5 },
      { r1: 8, r2: 1, r3: 4, r4: 7 },
    ]) {
      for (const b of BRANCHES) {
        const m = expectMatchesOracle(l, b);
        expectNear(m.timeRatio!, 1, 2 * EPS, `${describeLinkage(l, b)} time ratio`);
        const near = { ...l, r1: l.r1 * (1 + 1e-9) };
        const q = expectMatchesOracle(near, b).timeRatio!;
        expect(q, `${describeLinkage(near, b)}: quick return appears`).toBeGreaterThan(1);
      }
    }
  });

  it('reports no dead centres for a double crank, a double rocker, triple rockers, a parallelogram and kites', () => {
    const cases = [CASES[14], CASES[12], CASES[10], CASES[11], CASES[13], CASES[7], CASES[8], CASES[9], CASES[20]];
    for (const l of cases) {
      for (const b of BRANCHES) {
        const m = expectMatchesOracle(l, b);
        expect(m.output).toBeNull();
        expect(m.timeRatio).toBeNull();
      }
    }
  });

  it('puts the transmission extremes of a rocking input at its limits (mu = 0 and 180 deg there)', () => {
    // Case 12 (I-3): t2 in +-[38.6248328731, 78.5848422573] deg, mu = 0 at the lower limit, 180 at the upper.
    const m12 = designMetrics(CASES[12], 'open');
    expect(m12.transmission.min).toBe(0);
    expect(m12.transmission.max).toBe(Math.PI);
    expectNear(toDeg(m12.transmission.theta2AtMin), 38.6248328731, 1e-9, 'lower limit (deg)');
    expectNear(toDeg(m12.transmission.theta2AtMax), 78.5848422573, 1e-9, 'upper limit (deg)');
    // Case 10 (II-1): |t2| <= 135.9513743259 deg; mu at t2 = 0 is t4 - t3 = 67.9756871630 - 52.6168015821.
    const m10 = designMetrics(CASES[10], 'crossed');
    expectNear(toDeg(m10.transmission.min), 67.975687163 - 52.6168015821, 2e-10, 'mu at t2 = 0 (deg)');
    expect(m10.transmission.theta2AtMin).toBe(0);
    expect(m10.transmission.max).toBe(Math.PI);
    expectNear(toDeg(m10.transmission.theta2AtMax), 135.9513743259, 1e-9, 'upper limit (deg)');
    // Case 11 (II-3): |t2| >= 57.9494901188 deg; mu at t2 = 180 is 154.2378459017 - 8.9299764871.
    const m11 = designMetrics(CASES[11], 'open');
    expect(m11.transmission.min).toBe(0);
    expectNear(toDeg(m11.transmission.theta2AtMin), 57.9494901188, 1e-9, 'lower limit (deg)');
    expectNear(toDeg(m11.transmission.max), 154.2378459017 - 8.9299764871, 2e-10, 'mu at t2 = 180 (deg)');
    expect(m11.transmission.theta2AtMax).toBe(Math.PI);
  });

  it('puts theta2AtMin and theta2AtMax on the exact limits, at input angles where the linkage assembles', () => {
    // A lower limit tMin gives the interval [tMin, 2 pi - tMin]; its mirror end, wrapped, is rounded at the
    // ulp of 2 pi (8.9e-16), which for l = (2, 1, 3, 1.999999999999) is 1e5 ulps of tMin = 1e-6 and lands
    // where the loop does not close. The limit is the half-angle form of triangle.ts (each factor an
    // exactly rounded sum of the lengths), so it has a triangle angle's accuracy: angleTol (16 eps of the
    // value) covers it and the one or two ulps inputRange moves it inward to where the closed form closes.
    const family: Linkage[] = [CASES[11], CASES[12], CASES[10]];
    for (let k = 1; k <= 13; k++) family.push({ r1: 2, r2: 1, r3: 3, r4: 2 - 10 ** -k });
    family.push({ r1: 2, r2: 1, r3: 3, r4: 1.999999999999 });
    for (const l of family) {
      const tr = referenceTransmission(l)!;
      const m = designMetrics(l, 'open').transmission;
      const ctx = describeLinkage(l, 'open');
      for (const [got, ref] of [
        [m.theta2AtMin, tr.theta2AtMin],
        [m.theta2AtMax, tr.theta2AtMax],
      ]) {
        expectNear(got, ref, angleTol(ref), `${ctx} theta2 of a transmission extreme`);
        for (const b of BRANCHES) {
          expect(solveClosedForm(l, got, b), `${ctx}: assembles at ${got} ${b}`).not.toBeNull();
        }
      }
    }
  });

  it('handles a chain that only assembles flat and one that never assembles', () => {
    // Case 22 (L = S + P + Q): only t2 = 0, pose (0, 180): mu = 180 deg is both extremes.
    for (const b of BRANCHES) {
      const m = expectMatchesOracle(CASES[22], b);
      expect(m.transmission).toEqual({ min: Math.PI, max: Math.PI, theta2AtMin: 0, theta2AtMax: 0 });
      // Case 21 cannot be assembled at all: NaN everywhere, no dead centres.
      expectMatchesOracle(CASES[21], b);
    }
  });

  it('treats the change-point crank-rocker (III-2) as a crank-rocker whose folded dead centre is the flat pose', () => {
    // Case 4 (4, 1, 3, 2): at t2 = 180 deg the pose is (0, 180) on both branches; the rocker turns back there.
    for (const b of BRANCHES) {
      const m = expectMatchesOracle(CASES[4], b);
      expect(m.output!.folded).toEqual({ theta2: Math.PI, theta4: Math.PI });
      expect(m.transmission.max).toBe(Math.PI);
      // theta4 stays on one side of pi on both sides of t2 = pi (below on the open branch, above on its
      // mirror image): pi is the rocker's extreme, reached at a corner of the branch rather than with w4 = 0.
      for (const t2 of [Math.PI - 1e-3, Math.PI + 1e-3]) {
        const pose = solveClosedForm(CASES[4], t2, b)!;
        expect(sigmaOf(b) * angleDiff(pose.theta4, Math.PI), `theta4 at ${t2} ${b}`).toBeLessThan(-1e-5);
      }
    }
  });

  it('mirrors between the branches: same transmission, swing and time ratio, negated dead-centre angles', () => {
    for (const l of [REPORT, CASES[15], CASES[16], { r1: 3.2, r2: 0.7, r3: 2.9, r4: 1.6 }]) {
      const open = designMetrics(l, 'open');
      const crossed = designMetrics(l, 'crossed');
      expect(crossed.transmission).toEqual(open.transmission);
      expect(crossed.timeRatio).toBe(open.timeRatio);
      expect(crossed.output!.swing).toBe(open.output!.swing);
      for (const k of ['extended', 'folded'] as const) {
        for (const f of ['theta2', 'theta4'] as const) {
          const a = open.output![k][f];
          const c = crossed.output![k][f];
          expect(Math.abs(a) === Math.PI ? Math.abs(c) : c, `${k}.${f}`).toBe(Math.abs(a) === Math.PI ? Math.PI : -a);
        }
      }
    }
  });

  it('throws an Error naming the field and value for a bad length or branch', () => {
    expect(() => designMetrics({ r1: 6, r2: 2, r3: -1, r4: 5 }, 'open')).toThrow(
      'r3 must be a positive finite length, got -1',
    );
    expect(() => designMetrics({ r1: NaN, r2: 2, r3: 5, r4: 5 }, 'open')).toThrow(
      'r1 must be a positive finite length',
    );
    expect(() => designMetrics({ r1: 6, r2: 0, r3: 5, r4: 5 }, 'open')).toThrow('r2 must be a positive finite length');
    expect(() => designMetrics({ r1: 6, r2: 2, r3: 5 } as unknown as Linkage, 'open')).toThrow('r4');
    expect(() => designMetrics(null as unknown as Linkage, 'open')).toThrow('linkage must be an object');
    expect(() => designMetrics(REPORT, 'up' as Branch)).toThrow(`branch must be 'open' or 'crossed', got "up"`);
    expect(() => designMetrics(REPORT, undefined as unknown as Branch)).toThrow('branch');
  });
});

describe('instantCenters', () => {
  it('matches the oracle over the cycle of the report linkage and of needle-like linkages, both branches', () => {
    const grid = Array.from({ length: 73 }, (_, i) => deg(-180 + 5 * i));
    for (const l of [REPORT, CASES[2], CASES[15], CASES[16], CASES[12], CASES[10]]) {
      for (const b of BRANCHES) {
        for (const t2 of grid) {
          const pose = solveClosedForm(l, t2, b);
          if (pose) expectCentersMatchOracle(l, t2, pose, b);
        }
      }
    }
  });

  it("agrees with Kennedy's theorem: I24 and I13 give the velocity ratios of the velocity analysis", () => {
    // I24 moves with both crank and rocker: w2 x = w4 (x - r1). I13 is the coupler's pole:
    // A = t (cos t2, sin t2) + (r2 - t) (cos t2, sin t2), so w2 r2 = w3 (r2 - t).
    for (const b of BRANCHES) {
      for (const t2 of [0.3, 1.2, 2.0, 2.9, -0.7, -2.2]) {
        const pose = solveClosedForm(REPORT, t2, b)!;
        const { I13, I24 } = instantCenters(REPORT, t2, pose);
        const v = velocityRatios(REPORT, t2, pose);
        const t = I13!.x * Math.cos(t2) + I13!.y * Math.sin(t2);
        expectNear(I24!.x / (I24!.x - REPORT.r1), v.dTheta4, 1e-12, `w4/w2 at ${t2} ${b}`);
        expectNear(REPORT.r2 / (REPORT.r2 - t), v.dTheta3, 1e-12, `w3/w2 at ${t2} ${b}`);
      }
    }
  });

  it('puts I24 on the crank pivot at a dead centre (the rocker stands still)', () => {
    for (const b of BRANCHES) {
      const { output } = designMetrics(REPORT, b);
      for (const dc of [output!.extended, output!.folded]) {
        const pose = solveClosedForm(REPORT, dc.theta2, b)!;
        expectCentersMatchOracle(REPORT, dc.theta2, pose, `dead centre ${b}`);
        expect(Math.abs(instantCenters(REPORT, dc.theta2, pose).I24!.x)).toBeLessThan(1e-14);
      }
    }
  });

  it('returns null at infinity: a parallelogram has both pairs of lines parallel', () => {
    // Case 7 (4, 2, 4, 2) in parallelogram mode: t3 = 0, t4 = t2 for every t2.
    for (const t2 of [0.4, 1.9, -2.6]) {
      expect(instantCenters(CASES[7], t2, { theta3: 0, theta4: t2 })).toEqual({ I13: null, I24: null });
    }
  });

  it('draws the line at PARALLEL_SIN: sin 1e-15 is parallel, sin 4e-15 is a point 1e14 lengths away', () => {
    // Lines through O2 and O4 at t2 = 0.5 and t4 = 0.5 + 1e-15 (pose taken as given, even if it does not close).
    const t2 = 0.5;
    expect(instantCenters(REPORT, t2, { theta3: 0.3, theta4: t2 + 1e-15 }).I13).toBeNull();
    expect(instantCenters(REPORT, t2, { theta3: 0.3, theta4: t2 + Math.PI }).I13).toBeNull();
    const pose = { theta3: 1e-16, theta4: t2 + 4e-15 };
    const got = instantCenters(REPORT, t2, pose);
    expect(got.I24).toBeNull(); // coupler along the ground line
    expect(Math.hypot(got.I13!.x, got.I13!.y)).toBeGreaterThan(1e14);
    expectCentersMatchOracle(REPORT, t2, pose, 'near-parallel');
  });

  it('scales with the linkage: a power-of-two scale moves every point by exactly that factor', () => {
    const k = 2 ** 500;
    const big = { r1: REPORT.r1 * k, r2: REPORT.r2 * k, r3: REPORT.r3 * k, r4: REPORT.r4 * k };
    for (const t2 of [0.3, 2.5]) {
      const pose = solveClosedForm(REPORT, t2, 'open')!;
      const a = instantCenters(REPORT, t2, pose);
      const c = instantCenters(big, t2, pose);
      expect(c.I13).toEqual({ x: a.I13!.x * k, y: a.I13!.y * k });
      expect(c.I24).toEqual({ x: a.I24!.x * k, y: 0 });
    }
  });

  it('throws an Error naming the field and value for a bad length, theta2 or pose', () => {
    const pose = { theta3: 0.5, theta4: 1.8 };
    expect(() => instantCenters({ ...REPORT, r1: 0 }, 1, pose)).toThrow('r1 must be a positive finite length, got 0');
    expect(() => instantCenters(REPORT, NaN, pose)).toThrow('theta2 must be a finite angle in radians, got NaN');
    expect(() => instantCenters(REPORT, Infinity, pose)).toThrow('theta2 must be a finite angle in radians');
    expect(() => instantCenters(REPORT, 1, null as unknown as Angles)).toThrow('pose must be an object');
    expect(() => instantCenters(REPORT, 1, { theta3: NaN, theta4: 1 })).toThrow(
      'pose.theta3 must be a finite angle in radians, got NaN',
    );
    expect(() => instantCenters(REPORT, 1, { theta3: 1 } as Angles)).toThrow(
      'pose.theta4 must be a finite angle in radians, got undefined',
    );
  });
});
