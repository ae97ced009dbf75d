import { describe, expect, it } from 'vitest';
import { solveRSSR, solveSpherical } from '../../src/spatial';
import { EPS, INPUT, expectPose, gap, size } from './expectPose';
import { rssrOracle, sphericalOracle } from './oracle';
import { seeded } from './random';

describe('solveSpherical', () => {
  it('matches the 50-digit oracle (positions, theta4, rates, coupler point) on 150 seeded linkages', () => {
    const rnd = seeded(32);
    let solved = 0;
    for (let i = 0; i < 150; i++) {
      const l = {
        a1: 0.05 + 3 * rnd(),
        a2: 0.05 + 3 * rnd(),
        a3: 0.05 + 3 * rnd(),
        a4: 0.05 + 3 * rnd(),
        pDist: 3 * rnd(),
        pAngle: 6 * rnd() - 3,
      };
      const t2 = 7 * rnd() - 3.5;
      const branch = rnd() < 0.5 ? 'open' : 'crossed';
      const o = sphericalOracle(l, t2, branch, INPUT.omega2, INPUT.alpha2);
      expectPose(solveSpherical(l, t2, branch, INPUT), o, 1);
      if (o) solved++;
    }
    expect(solved).toBeGreaterThan(40);
  }, 60_000);

  it('keeps every pin on the unit sphere and the coupler arc a3', () => {
    const l = { a1: 1.1, a2: 0.4, a3: 1.2, a4: 0.9, pDist: 0.5, pAngle: 0.8 };
    for (let t = -3; t <= 3; t += 0.25) {
      const s = solveSpherical(l, t, 'open')!;
      for (const p of [s.A, s.B, s.P!]) expect(Math.abs(size(p) - 1)).toBeLessThan(4 * EPS);
      expect(Math.abs(Math.acos(s.A.x * s.B.x + s.A.y * s.B.y + s.A.z * s.B.z) - 1.2)).toBeLessThan(1e-14);
    }
  });

  it('returns zero rates without an input motion', () => {
    const s = solveSpherical({ a1: 1.1, a2: 0.4, a3: 1.2, a4: 0.9 }, 0.3, 'crossed')!;
    expect([s.omega4, s.alpha4, s.velocity.B.x, s.acceleration.A.y]).toEqual([0, 0, 0, 0]);
    expect(s.P).toBeUndefined();
  });
});

describe('solveRSSR', () => {
  it('matches the 50-digit oracle (positions, theta4, rates) on 150 seeded linkages', () => {
    const rnd = seeded(2032);
    let solved = 0;
    for (let i = 0; i < 150; i++) {
      const l = {
        r2: 0.2 + 3 * rnd(),
        r3: 0.2 + 5 * rnd(),
        r4: 0.2 + 3 * rnd(),
        a: 4 * rnd(),
        beta: 6 * rnd() - 3,
        h2: 2 * rnd() - 1,
        h4: 2 * rnd() - 1,
      };
      const t2 = 7 * rnd() - 3.5;
      const branch = rnd() < 0.5 ? 'open' : 'crossed';
      const o = rssrOracle(l, t2, branch, INPUT.omega2, INPUT.alpha2);
      expectPose(solveRSSR(l, t2, branch, INPUT), o, 8);
      if (o) solved++;
    }
    expect(solved).toBeGreaterThan(40);
  }, 60_000);

  it('keeps |A - B| = r3 and B on the rocker circle', () => {
    const l = { r2: 1, r3: 4, r4: 2, a: 3, beta: 1, h2: 0.5, h4: -0.25 };
    for (let t = -3; t <= 3; t += 0.25) {
      const s = solveRSSR(l, t, 'open')!;
      expect(Math.abs(Math.hypot(s.A.x - s.B.x, s.A.y - s.B.y, s.A.z - s.B.z) - 4)).toBeLessThan(1e-14);
      const C = { x: 3, y: 0.25 * Math.sin(1), z: -0.25 * Math.cos(1) };
      expect(Math.abs(gap(s.B, C) - 2)).toBeLessThan(1e-14);
    }
  });
});
