import { describe, expect, it } from 'vitest';
import { designMetrics, solveClosedForm } from '../../src/solver';
import {
  SPATIAL_PRESETS,
  classifyRSSR,
  classifySpherical,
  outputMotion,
  solveRSSR,
  solveSpherical,
  spatialCsvRows,
  sphericalCouplerCurve,
  sweepSpatial,
  transmissionAngle,
} from '../../src/spatial';
import type { SpatialModel } from '../../src/spatial';
import { angleGap, rssrOracle, sphericalOracle } from './oracle';

const SPH = { a1: 1.05, a2: 0.35, a3: 0.96, a4: 0.79, pDist: 0.44, pAngle: 0.7 };
const SKEW = { r2: 1, r3: 4, r4: 2, a: 3, beta: 1.0471975511965976, h2: 0.5, h4: 1 };

describe('outputMotion', () => {
  it('finds dead centres where the 50-digit oracle has omega4 = 0, and the swing between them', () => {
    for (const model of [
      { kind: 'spherical', linkage: SPH },
      { kind: 'rssr', linkage: SKEW },
    ] as SpatialModel[]) {
      for (const branch of ['open', 'crossed'] as const) {
        const m = outputMotion(model, branch);
        expect(m.deadCentres).toHaveLength(2);
        const oracle = (t: number) =>
          model.kind === 'spherical'
            ? sphericalOracle(model.linkage, t, branch, 1, 0)!
            : rssrOracle(model.linkage, t, branch, 1, 0)!;
        const [lo, hi] = m.deadCentres.map((d) => oracle(d.theta2));
        for (const [d, o] of [
          [m.deadCentres[0], lo],
          [m.deadCentres[1], hi],
        ] as const) {
          // theta2 is bisected to the double, so omega4 there is ~ eps times its curvature; theta4 is the oracle's.
          expect(Math.abs(o.omega4)).toBeLessThan(1e-12);
          expect(Math.abs(angleGap(d.theta4, o.theta4))).toBeLessThan(1e-14);
          expect(o.alpha4 > 0).toBe(d.kind === 'min');
        }
        const swing = Math.abs(angleGap(m.deadCentres[0].theta4, m.deadCentres[1].theta4));
        expect(Math.abs(m.swings[0].swing - swing)).toBeLessThan(1e-14);
        expect(m.swings[0].full).toBe(false);
      }
    }
  });

  it('matches designMetrics on a spherical linkage with tiny arcs (the planar 6-2-5-5)', () => {
    const e = 1e-7;
    const m = outputMotion({ kind: 'spherical', linkage: { a1: 6 * e, a2: 2 * e, a3: 5 * e, a4: 5 * e } }, 'open');
    const planar = designMetrics({ r1: 6, r2: 2, r3: 5, r4: 5 }, 'open');
    expect(Math.abs(m.swings[0].swing - planar.output!.swing!)).toBeLessThan(1e-9);
    expect(Math.abs(m.transmission!.min - planar.transmission.min)).toBeLessThan(1e-9);
    expect(Math.abs(m.transmission!.max - planar.transmission.max)).toBeLessThan(1e-9);
  });

  it('reports a drag link (both cranks) as a full output turn without dead centres', () => {
    const m = outputMotion(SPATIAL_PRESETS.find((p) => p.id === 'sph-drag-link')!.model, 'open');
    expect(m.swings).toEqual([expect.objectContaining({ full: true, swing: 2 * Math.PI })]);
    expect(m.deadCentres).toEqual([]);
  });

  it('covers each interval of a rocker input (one swing per interval)', () => {
    const m = outputMotion({ kind: 'rssr', linkage: { r2: 3, r3: 1, r4: 3.5, a: 4, beta: 0, h2: 0, h4: 0 } }, 'open');
    expect(m.swings).toHaveLength(2);
  });
});

describe('transmissionAngle', () => {
  it('is the angle at B between the coupler and the rocker (spherical: the law of cosines on the oracle pose)', () => {
    for (const t2 of [-2, -0.5, 0.4, 1.7, 3]) {
      const o = sphericalOracle(SPH, t2, 'open')!;
      const dotAO4 = o.A.x * Math.sin(SPH.a1) + o.A.z * Math.cos(SPH.a1);
      const want = Math.acos((dotAO4 - Math.cos(SPH.a3) * Math.cos(SPH.a4)) / (Math.sin(SPH.a3) * Math.sin(SPH.a4)));
      expect(Math.abs(transmissionAngle({ kind: 'spherical', linkage: SPH }, t2, 'open')! - want)).toBeLessThan(1e-12);
    }
  });

  it('is the in-plane angle between A - B and B -> axis for RSSR, and null where the loop does not close', () => {
    for (const t2 of [-2, 0.4, 3]) {
      const o = rssrOracle(SKEW, t2, 'crossed')!;
      const C = { x: SKEW.a, y: -SKEW.h4 * Math.sin(SKEW.beta), z: SKEW.h4 * Math.cos(SKEW.beta) };
      const e1 = [1, 0, 0];
      const e2 = [0, Math.cos(SKEW.beta), Math.sin(SKEW.beta)];
      const d = [o.A.x - o.B.x, o.A.y - o.B.y, o.A.z - o.B.z];
      const r = [C.x - o.B.x, C.y - o.B.y, C.z - o.B.z];
      const proj = (v: number[]) => [
        v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2],
        v[0] * e2[0] + v[1] * e2[1] + v[2] * e2[2],
      ];
      const [dp, rp] = [proj(d), proj(r)];
      const want = Math.acos((dp[0] * rp[0] + dp[1] * rp[1]) / (Math.hypot(...dp) * Math.hypot(...rp)));
      expect(Math.abs(transmissionAngle({ kind: 'rssr', linkage: SKEW }, t2, 'crossed')! - want)).toBeLessThan(1e-12);
    }
    const limited = { kind: 'rssr', linkage: { r2: 3, r3: 1, r4: 3.5, a: 4, beta: 0, h2: 0, h4: 0 } } as const;
    expect(transmissionAngle(limited, 0, 'open')).toBeNull();
  });
});

describe('sweepSpatial and sphericalCouplerCurve', () => {
  it('is solveSpherical at every angle: the same bits, NaN and valid 0 where it returns null', () => {
    const model = { kind: 'spherical', linkage: { a1: 0.7, a2: 0.52, a3: 0.61, a4: 0.52, pDist: 0.3 } } as const;
    const s = sweepSpatial(model, 'crossed', { steps: 90, start: -1, omega2: 2, alpha2: -1 });
    expect(s.theta2).toHaveLength(91);
    expect(s.P).toHaveLength(273);
    let gaps = 0;
    for (let i = 0; i < 91; i++) {
      const pose = solveSpherical(model.linkage, s.theta2[i], 'crossed', { omega2: 2, alpha2: -1 });
      expect(s.valid[i]).toBe(pose === null ? 0 : 1);
      if (pose === null) {
        gaps++;
        expect([s.theta4[i], s.omega4[i], s.B[3 * i], s.P![3 * i + 2]].every(Number.isNaN)).toBe(true);
        continue;
      }
      expect([s.theta4[i], s.omega4[i], s.alpha4[i]]).toEqual([pose.theta4, pose.omega4, pose.alpha4]);
      expect([s.B[3 * i], s.B[3 * i + 1], s.B[3 * i + 2]]).toEqual([pose.B.x, pose.B.y, pose.B.z]);
      expect([s.P![3 * i], s.P![3 * i + 1], s.P![3 * i + 2]]).toEqual([pose.P!.x, pose.P!.y, pose.P!.z]);
    }
    expect(gaps).toBeGreaterThan(0);
  });

  it('scales RSSR pins back to the linkage unit', () => {
    const s = sweepSpatial({ kind: 'rssr', linkage: SKEW }, 'open', { steps: 8 });
    const pose = solveRSSR(SKEW, s.theta2[3], 'open', { omega2: 1, alpha2: 0 })!;
    expect([s.A[9], s.B[10], s.B[11]]).toEqual([pose.A.x, pose.B.y, pose.B.z]);
    expect(s.P).toBeUndefined();
  });

  it('traces the coupler point on the unit sphere, at the oracle P', () => {
    const curve = sphericalCouplerCurve(SPH, 'open', 36);
    expect(curve).toHaveLength(111);
    for (let i = 0; i <= 36; i += 6) {
      const t2 = (2 * Math.PI * i) / 36;
      const o = sphericalOracle(SPH, t2, 'open')!;
      expect(Math.hypot(curve[3 * i] - o.P!.x, curve[3 * i + 1] - o.P!.y, curve[3 * i + 2] - o.P!.z)).toBeLessThan(
        1e-14,
      );
    }
  });
});

describe('spatialCsvRows', () => {
  it("has the issue's columns, one row per degree over a crank's turn, and the oracle's first row", () => {
    const csv = spatialCsvRows({ kind: 'spherical', linkage: SPH }, 'open', { omega2: 2, alpha2: 0.5 });
    expect(csv.columns).toEqual([
      'theta2_deg',
      'A_x',
      'A_y',
      'A_z',
      'B_x',
      'B_y',
      'B_z',
      'P_x',
      'P_y',
      'P_z',
      'theta4_deg',
      'omega4_rad_s',
      'alpha4_rad_s2',
    ]);
    expect(csv.rows).toHaveLength(361);
    expect(csv.rows[360][0]).toBe(360);
    const o = sphericalOracle(SPH, 0, 'open', 2, 0.5)!;
    const want = [0, o.A.x, o.A.y, o.A.z, o.B.x, o.B.y, o.B.z, o.P!.x, o.P!.y, o.P!.z];
    csv.rows[0].slice(0, 10).forEach((x, j) => expect(Math.abs(x - want[j])).toBeLessThan(1e-15));
    expect(Math.abs(csv.rows[0][10] - (o.theta4 * 180) / Math.PI)).toBeLessThan(1e-12);
    expect(Math.abs(csv.rows[0][11] - o.omega4)).toBeLessThan(1e-14);
    expect(Math.abs(csv.rows[0][12] - o.alpha4)).toBeLessThan(1e-13);
  });

  it('runs each interval of a limited input from end to end, without P columns for RSSR', () => {
    const l = { r2: 3, r3: 1, r4: 3.5, a: 4, beta: 0, h2: 0, h4: 0 };
    const csv = spatialCsvRows({ kind: 'rssr', linkage: l }, 'open', { stepDeg: 5 });
    expect(csv.columns).toEqual([
      'theta2_deg',
      'A_x',
      'A_y',
      'A_z',
      'B_x',
      'B_y',
      'B_z',
      'theta4_deg',
      'omega4_rad_s',
      'alpha4_rad_s2',
    ]);
    const ranges = classifyRSSR(l).inputRange.intervals;
    const firsts = csv.rows.filter((r, i) => i === 0 || r[0] - csv.rows[i - 1][0] > 5 + 1e-9).map((r) => r[0]);
    expect(firsts.map((d) => (d * Math.PI) / 180)).toEqual(ranges.map((iv) => expect.closeTo(iv.lo, 12)));
    expect(csv.rows.at(-1)![0]).toBeCloseTo((ranges.at(-1)!.hi * 180) / Math.PI, 10);
    expect(csv.rows.every((r) => r.every((x) => !Number.isNaN(x)))).toBe(true);
  });
});

describe('SPATIAL_PRESETS', () => {
  it('are the five designs of issue 32, each of its stated kind', () => {
    const types = SPATIAL_PRESETS.map((p) =>
      p.model.kind === 'spherical' ? classifySpherical(p.model.linkage).type : classifyRSSR(p.model.linkage).type,
    );
    expect(SPATIAL_PRESETS.map((p) => p.id)).toEqual([
      'sph-crank-rocker',
      'sph-drag-link',
      'sph-universal-joint',
      'rssr-skew',
      'rssr-planar',
    ]);
    expect(types).toEqual(['crank-rocker', 'double-crank', 'double-crank', 'crank-rocker', 'crank-rocker']);
  });

  it('the universal joint follows Hooke: omega4 / omega2 = 1 / cos(shaft angle) at theta2 = 0', () => {
    const { linkage } = SPATIAL_PRESETS.find((p) => p.id === 'sph-universal-joint')!.model as {
      linkage: { a1: number; a2: number; a3: number; a4: number };
    };
    const s = solveSpherical(linkage, 0, 'open', { omega2: 1, alpha2: 0 })!;
    expect(Math.abs(Math.abs(s.omega4) - 1 / Math.cos(linkage.a1))).toBeLessThan(1e-14);
  });

  it("the planar RSSR is the report's 6-2-5-5 (docs/hard-cases.md case 1)", () => {
    const { linkage } = SPATIAL_PRESETS.find((p) => p.id === 'rssr-planar')!.model as { linkage: typeof SKEW };
    for (const t2 of [0, 1, 2.5, -1.2]) {
      const planar = solveClosedForm({ r1: 6, r2: 2, r3: 5, r4: 5 }, t2, 'open')!;
      expect(Math.abs(angleGap(solveRSSR(linkage, t2, 'open')!.theta4, planar.theta4))).toBeLessThan(1e-14);
    }
  });
});
