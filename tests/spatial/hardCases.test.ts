import { describe, expect, it } from 'vitest';
import { solveRSSR, solveSpherical } from '../../src/spatial';
import type { RSSRLinkage, SpatialPose } from '../../src/spatial';
import { angleGap, rssrOracle, sphericalOracle } from './oracle';

const EPS = Number.EPSILON;
const planar = (r1: number, r2: number, r3: number, r4: number): RSSRLinkage => ({
  r2,
  r3,
  r4,
  a: r1,
  beta: 0,
  h2: 0,
  h4: 0,
});
const finiteOrInfinite = (x: number) => !Number.isNaN(x);
const noNaN = (p: SpatialPose) =>
  [p.omega4, p.alpha4, ...Object.values(p.velocity.B), ...Object.values(p.acceleration.B)].every(finiteOrInfinite);

describe('near-toggle poses', () => {
  it('RSSR 4-1-3-(2+1e-9) at theta2 = pi: theta4 within eps / sin(psi) of the oracle (hard case 2)', () => {
    const l = planar(4, 1, 3, 2 + 1e-9);
    for (const branch of ['open', 'crossed'] as const) {
      const o = rssrOracle(l, Math.PI, branch, 1, 0)!;
      const s = solveRSSR(l, Math.PI, branch, { omega2: 1, alpha2: 0 })!;
      expect(o.sinPsi).toBeLessThan(1e-4);
      expect(Math.abs(angleGap(s.theta4, o.theta4))).toBeLessThanOrEqual((32 * EPS) / o.sinPsi);
      expect(Math.abs(s.omega4 - o.omega4)).toBeLessThanOrEqual(
        ((32 * EPS) / o.sinPsi ** 2) * (1 + Math.abs(o.omega4)),
      );
    }
  });

  it('RSSR 4-3-2.5-2.5 at fl(pi/2) is a limit: both branches within 1e-7 rad, null a step past (hard case 13)', () => {
    const l = planar(4, 3, 2.5, 2.5);
    const open = solveRSSR(l, Math.PI / 2, 'open')!;
    const crossed = solveRSSR(l, Math.PI / 2, 'crossed')!;
    const o = rssrOracle(l, Math.PI / 2, 'open')!;
    // sqrt(eps) conditioning at the fold: the best achievable is about 1e-8 rad.
    expect(Math.abs(angleGap(open.theta4, o.theta4))).toBeLessThan(1e-7);
    expect(Math.abs(angleGap(crossed.theta4, o.theta4))).toBeLessThan(1e-7);
    // Reach is decided to a few ulps of the lengths (docs/spatial.md): 1e-12 past the fold is beyond them.
    expect(rssrOracle(l, Math.PI / 2 + 1e-12, 'open')).toBeNull();
    expect(solveRSSR(l, Math.PI / 2 + 1e-12, 'open')).toBeNull();
  });

  it('RSSR 6-1-2-3 closes only flat at theta2 = 0: theta4 = pi, unbounded rates that are never NaN (hard case 22)', () => {
    const l = planar(6, 1, 2, 3);
    const s = solveRSSR(l, 0, 'open', { omega2: 1, alpha2: 0 })!;
    expect(s.theta4).toBe(Math.PI);
    expect(Math.abs(s.omega4)).toBe(Infinity);
    expect(noNaN(s)).toBe(true);
    // 1e-8 rad misses by 6e-17 of a length of 5 (below its ulp): a flat limit within rounding; 1e-6 misses by 5e-13.
    expect(solveRSSR(l, 1e-6, 'open')).toBeNull();
    const still = solveRSSR(l, 0, 'crossed', { omega2: 0, alpha2: 0 })!;
    expect([still.omega4, still.alpha4]).toEqual([0, 0]);
  });

  it('spherical 1.2-0.3-0.8-(0.7+1e-9) near its toggle at theta2 = pi: within eps / sin(psi) of the oracle', () => {
    const l = { a1: 1.2, a2: 0.3, a3: 0.8, a4: 0.7 + 1e-9, pDist: 0.4, pAngle: 1 };
    for (const t2 of [Math.PI, Math.PI - 1e-6, Math.PI - 1e-3]) {
      for (const branch of ['open', 'crossed'] as const) {
        const o = sphericalOracle(l, t2, branch, 1, 0)!;
        const s = solveSpherical(l, t2, branch, { omega2: 1, alpha2: 0 })!;
        expect(Math.abs(angleGap(s.theta4, o.theta4))).toBeLessThanOrEqual((32 * EPS) / o.sinPsi);
        expect(Math.abs(s.omega4 - o.omega4)).toBeLessThanOrEqual(
          ((32 * EPS) / o.sinPsi ** 2) * (1 + Math.abs(o.omega4)),
        );
      }
    }
  });

  it("spherical crank pin passing 1e-9 rad from the rocker's axis O4: theta4 within 4 eps of the oracle", () => {
    // d = |A O4| is 6e-6 rad here, so the direction of A seen from O4 amplifies any absolute error in A . u by 1 / d:
    // 1 - cos(theta2) in place of 2 sin^2(theta2 / 2) misses by 1e3 to 1e5 eps.
    const l = { a1: 0.7, a2: 0.7 + 1e-9, a3: 0.8, a4: 0.8 };
    for (const t2 of [1e-5, 3e-5, -2e-5, 1e-7]) {
      for (const branch of ['open', 'crossed'] as const) {
        const o = sphericalOracle(l, t2, branch)!;
        const s = solveSpherical(l, t2, branch)!;
        expect(Math.abs(angleGap(s.theta4, o.theta4))).toBeLessThanOrEqual(4 * EPS);
      }
    }
  });

  it('spherical flat at a limit: a3 + a4 = d exactly closes with both branches equal and no NaN', () => {
    // a1 = 1, a2 = 0.5 at theta2 = pi: d = 1.5 = a3 + a4.
    const l = { a1: 1, a2: 0.5, a3: 1, a4: 0.5 };
    const open = solveSpherical(l, Math.PI, 'open', { omega2: 1, alpha2: 0 })!;
    const crossed = solveSpherical(l, Math.PI, 'crossed')!;
    expect(Math.abs(angleGap(open.theta4, crossed.theta4))).toBeLessThan(1e-7);
    expect(noNaN(open)).toBe(true);
  });

  it('spherical arcs over 90 degrees and near pi match the oracle', () => {
    const cases = [
      { a1: 2.5, a2: 2.9, a3: 2.2, a4: 1.75, pDist: 2.5, pAngle: -2 },
      { a1: Math.PI - 1e-6, a2: 1.2, a3: 1.5, a4: 0.4 },
      { a1: 1.5707963267948966, a2: 1.5707963267948966, a3: 1.5707963267948966, a4: 1.5707963267948966 },
    ];
    for (const l of cases) {
      for (const t2 of [-2.5, -0.7, 0, 0.3, 1.9, 3]) {
        const o = sphericalOracle(l, t2, 'open', 1, 0);
        const s = solveSpherical(l, t2, 'open', { omega2: 1, alpha2: 0 });
        // All arcs 90 degrees at theta2 = 0: A is on O4 and a3 = a4, every theta4 closes (a continuum: the constraint's
        // P, Q and R are all 0, so 50 digits decide its reach by their rounding alone).
        if (l.a1 === l.a2 && l.a3 === l.a4 && t2 === 0) {
          expect(s).not.toBeNull();
          continue;
        }
        expect(s === null).toBe(o === null);
        if (!s || !o) continue;
        expect(Math.abs(angleGap(s.theta4, o.theta4))).toBeLessThanOrEqual((32 * EPS) / o.sinPsi);
        if (o.P) expect(Math.hypot(s.P!.x - o.P.x, s.P!.y - o.P.y, s.P!.z - o.P.z)).toBeLessThan((64 * EPS) / o.sinPsi);
      }
    }
  });
});

describe('huge and tiny scales', () => {
  const base: RSSRLinkage = { r2: 1, r3: 4, r4: 2, a: 3, beta: 1, h2: 0.5, h4: -0.25 };
  const scaled = (k: number): RSSRLinkage => ({
    ...base,
    r2: base.r2 * k,
    r3: base.r3 * k,
    r4: base.r4 * k,
    a: base.a * k,
    h2: base.h2 * k,
    h4: base.h4 * k,
  });

  for (const k of [1e150, 1e-150, 1e300, 1e-300, 2 ** 1000, 2 ** -1000]) {
    it(`RSSR lengths x ${k}: the oracle's angles and rates, positions and velocities in scale`, () => {
      const l = scaled(k);
      for (const t2 of [-2, 0, 0.5, 2.5]) {
        for (const branch of ['open', 'crossed'] as const) {
          const o = rssrOracle(l, t2, branch, 1.5, 0.25)!;
          const s = solveRSSR(l, t2, branch, { omega2: 1.5, alpha2: 0.25 })!;
          expect(Math.abs(angleGap(s.theta4, o.theta4))).toBeLessThanOrEqual((32 * EPS) / o.sinPsi);
          expect(Math.abs(s.omega4 - o.omega4)).toBeLessThanOrEqual(
            (64 * EPS * (1 + Math.abs(o.omega4))) / o.sinPsi ** 2,
          );
          expect(Math.abs(s.alpha4 - o.alpha4)).toBeLessThanOrEqual(
            (128 * EPS * (1 + Math.abs(o.alpha4))) / o.sinPsi ** 3,
          );
          // Relative to the scale (a power of ten is not a power of two, so positions are compared, not bits).
          expect(Math.abs(s.B.y - o.B.y) / k).toBeLessThan(1e-13);
          expect(Math.abs(s.velocity.B.z - o.vB.z) / k).toBeLessThan(1e-12);
          expect(Math.abs(s.acceleration.B.x - o.aB.x) / k).toBeLessThan(1e-12);
        }
      }
    });
  }

  it('RSSR scaled by a power of two gives bit-identical angles and rates', () => {
    const a = solveRSSR(base, 0.7, 'open', { omega2: 1, alpha2: 1 })!;
    const b = solveRSSR(scaled(2 ** -900), 0.7, 'open', { omega2: 1, alpha2: 1 })!;
    expect([b.theta4, b.omega4, b.alpha4]).toEqual([a.theta4, a.omega4, a.alpha4]);
    expect(b.B.x).toBe(a.B.x * 2 ** -900);
  });

  it('spherical tiny arcs (1e-100 rad) keep theta4 (the planar four-bar of the same shape)', () => {
    const k = 1e-100;
    const s = solveSpherical({ a1: 6 * k, a2: 2 * k, a3: 5 * k, a4: 5 * k }, Math.PI / 2, 'open')!;
    // docs/hard-cases.md case 1 at 90 degrees: open theta4 = 110.7965716607 degrees.
    expect(Math.abs(s.theta4 - (110.7965716607 * Math.PI) / 180)).toBeLessThan(1e-11);
  });
});
