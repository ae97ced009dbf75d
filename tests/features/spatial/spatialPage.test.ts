import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import type { SpatialState } from '../../../src/shared/state/appState';
import {
  DEFAULT_SPATIAL,
  normalizeSpatial,
  spatialFieldProblem,
  spatialReducer,
} from '../../../src/shared/state/slices/spatialSlice';
import { SPATIAL_PRESETS, sweepSpatial } from '../../../src/spatial';
import { pathSegments, sceneLinkage, scenePose } from '../../../src/features/spatial/sceneData';
import { plotColumns } from '../../../src/features/spatial/plotSeries';
import { spatialCsvText, spatialFileStem } from '../../../src/features/spatial/spatialExports';
import { modelOf, presetOf, presetPatch } from '../../../src/features/spatial/spatialModel';

const D = Decimal.clone({ precision: 40 });
const PI = D.acos(-1);

/** The input motion of the rates before ω2 and α2 were fields: ω2 = 1 rad/s, α2 = 0. */
const UNIT_INPUT = { omega2: 1, alpha2: 0 };

type V = [Decimal, Decimal, Decimal];
const dot = (a: V, b: V) => a[0].times(b[0]).plus(a[1].times(b[1])).plus(a[2].times(b[2]));
const lin = (...terms: [Decimal, V][]): V =>
  [0, 1, 2].map((i) => terms.reduce((acc, [k, v]) => acc.plus(k.times(v[i])), new D(0))) as V;
const rad = (deg: number | Decimal) => new D(deg).times(PI).div(180);

/**
 * The open-branch spherical pose at θ2 (degrees) for the input ω2, α2, at 40 digits from docs/spatial.md's
 * conventions: A = Rz(θ2)(sin a2, 0, cos a2), B = cos a4 O4 + sin a4 (cos θ4 u + sin θ4 y), A·B = cos a3, open where
 * (A − B)·∂B/∂θ4 > 0; ω4 and α4 from F = A·B − cos a3 differentiated once and twice in time.
 */
function sphericalOracle(arcsDeg: [number, number, number, number], t2Deg: number, omega2: number, alpha2: number) {
  const [a1, a2, a3, a4] = arcsDeg.map(rad);
  const t2 = rad(t2Deg);
  const [w2, al2] = [new D(omega2), new D(alpha2)];
  const zero = new D(0);
  const A: V = [a2.sin().times(t2.cos()), a2.sin().times(t2.sin()), a2.cos()];
  const dA: V = [a2.sin().times(t2.sin()).neg(), a2.sin().times(t2.cos()), zero];
  const ddA: V = [A[0].neg(), A[1].neg(), zero];
  const O4: V = [a1.sin(), zero, a1.cos()];
  const u: V = [a1.cos(), zero, a1.sin().neg()];
  const y: V = [zero, new D(1), zero];
  const P = a4.sin().times(dot(A, u));
  const Q = a4.sin().times(dot(A, y));
  const R = a3.cos().minus(a4.cos().times(dot(A, O4)));
  const phi = D.atan2(Q, P);
  const psi = D.acos(R.div(P.pow(2).plus(Q.pow(2)).sqrt()));
  const at = (t4: Decimal) => ({
    t4,
    B: lin([a4.cos(), O4], [a4.sin().times(t4.cos()), u], [a4.sin().times(t4.sin()), y]),
    dB: lin([a4.sin().times(t4.sin()).neg(), u], [a4.sin().times(t4.cos()), y]),
    ddB: lin([a4.sin().times(t4.cos()).neg(), u], [a4.sin().times(t4.sin()).neg(), y]),
  });
  const open = [at(phi.minus(psi)), at(phi.plus(psi))].find((c) =>
    dot(lin([new D(1), A], [new D(-1), c.B]), c.dB).gt(0),
  )!;
  const F4 = dot(A, open.dB);
  const omega4 = dot(dA, open.B).times(w2).neg().div(F4);
  const alpha4 = dot(ddA, open.B)
    .times(w2.pow(2))
    .plus(dot(dA, open.B).times(al2))
    .plus(dot(dA, open.dB).times(w2).times(omega4).times(2))
    .plus(dot(A, open.ddB).times(omega4.pow(2)))
    .neg()
    .div(F4);
  let t4Deg = open.t4.times(180).div(PI);
  while (t4Deg.gt(180)) t4Deg = t4Deg.minus(360);
  while (t4Deg.lte(-180)) t4Deg = t4Deg.plus(360);
  return { A, B: open.B, t4Deg, omega4, alpha4 };
}

/** The state of a preset on top of the defaults. */
const presetState = (id: string): SpatialState => ({
  ...DEFAULT_SPATIAL,
  ...presetPatch(SPATIAL_PRESETS.find((p) => p.id === id)!),
});

describe('modelOf and the presets', () => {
  it('turns degrees into radians once, and pd = 0 into no coupler point', () => {
    const m = modelOf({ ...DEFAULT_SPATIAL, a1Deg: 90, pDistDeg: 0 });
    expect(m.kind).toBe('spherical');
    if (m.kind !== 'spherical') return;
    expect(m.linkage.a1).toBe(Math.PI / 2);
    expect(m.linkage).not.toHaveProperty('pDist');
    const r = modelOf({ ...DEFAULT_SPATIAL, kind: 'rssr', betaDeg: -90 });
    expect(r).toMatchObject({ kind: 'rssr', linkage: { r2: 1, r3: 4, r4: 2, a: 3, beta: -Math.PI / 2 } });
  });

  it('gives every preset a state that is that preset again, and the default is the spherical crank-rocker', () => {
    for (const p of SPATIAL_PRESETS) expect(presetOf(presetState(p.id))).toBe(p.id);
    expect(presetOf(DEFAULT_SPATIAL)).toBe('sph-crank-rocker');
    expect(presetOf({ ...DEFAULT_SPATIAL, a3Deg: 56 })).toBeNull();
    // The preset's model is the numerics' preset, to the degree grid of the URL (1e-9 degree).
    for (const p of SPATIAL_PRESETS) {
      const m = modelOf(presetState(p.id));
      for (const [k, v] of Object.entries(p.model.linkage)) {
        expect(Math.abs((m.linkage as unknown as Record<string, number>)[k] - v), `${p.id} ${k}`).toBeLessThan(1e-10);
      }
    }
  });
});

describe('spatialCsvText', () => {
  it("writes the issue's columns and, for the planar RSSR, a first row equal to the planar closed form", () => {
    const s = presetState('rssr-planar');
    const lines = spatialCsvText(modelOf(s), 'open', UNIT_INPUT).trim().split('\n');
    expect(lines[0]).toBe('theta2_deg,A_x,A_y,A_z,B_x,B_y,B_z,theta4_deg,omega4_rad_s,alpha4_rad_s2');
    expect(lines).toHaveLength(362);
    // 6-2-5-5 at θ2 = 0: A = (2, 0, 0), |A − B| = 5 gives cos θ4 = −0.4, the open branch sin θ4 > 0.
    const sin4 = new D('0.84').sqrt();
    const t4Deg = D.atan2(sin4, -0.4).times(180).div(PI);
    const row = lines[1].split(',').map(Number);
    const want = [0, 2, 0, 0, 4, sin4.times(5).toNumber(), 0, t4Deg.toNumber()];
    want.forEach((w, i) =>
      expect(Math.abs(row[i] - w), `column ${i}`).toBeLessThanOrEqual(4e-15 * Math.max(1, Math.abs(w))),
    );
    // ω4 = −F2/F4 with F = |A − B|²/2: F2 = (A − B)·A′, F4 = −(A − B)·B′ (ω2 = 1).
    const A = [new D(2), new D(0)];
    const B = [new D(4), sin4.times(5)];
    const dA = [new D(0), new D(2)];
    const dB = [sin4.times(-5), new D(-2)];
    const AB = [A[0].minus(B[0]), A[1].minus(B[1])];
    const F2 = AB[0].times(dA[0]).plus(AB[1].times(dA[1]));
    const F4 = AB[0].times(dB[0]).plus(AB[1].times(dB[1])).neg();
    expect(Math.abs(row[8] - F2.neg().div(F4).toNumber())).toBeLessThan(1e-14);
  });

  it("writes rates for the state's ω2 and α2 (ω2 = 2.5 rad/s, α2 = −3 rad/s²), each row the oracle's", () => {
    const s = { ...DEFAULT_SPATIAL, pDistDeg: 0, omega2RadPerS: 2.5, alpha2RadPerS2: -3 };
    const lines = spatialCsvText(modelOf(s), 'open', { omega2: 2.5, alpha2: -3 }).trim().split('\n');
    const head = lines[0].split(',');
    expect(head).toEqual([
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
    // A crank-rocker: one row per degree, 0 to 360; rows 0, 37, 181 and 359 against the oracle.
    expect(lines).toHaveLength(362);
    for (const t2 of [0, 37, 181, 359]) {
      const row = lines[1 + t2].split(',').map(Number);
      const o = sphericalOracle([60, 20, 55, 45], t2, 2.5, -3);
      const want = [new D(t2), ...o.A, ...o.B, o.t4Deg, o.omega4, o.alpha4];
      // Full precision: within 1e-13 relative (a few ulps through the solve's conditioning), 1e-13 absolute near 0.
      want.forEach((w, i) => {
        const x = w.toNumber();
        expect(Math.abs(row[i] - x), `θ2 = ${t2}: ${head[i]}`).toBeLessThanOrEqual(1e-13 * Math.max(1, Math.abs(x)));
      });
    }
  });

  it('adds P_x, P_y, P_z with a coupler point only', () => {
    const withP = spatialCsvText(modelOf(DEFAULT_SPATIAL), 'open', UNIT_INPUT).split('\n')[0];
    expect(withP).toBe('theta2_deg,A_x,A_y,A_z,B_x,B_y,B_z,P_x,P_y,P_z,theta4_deg,omega4_rad_s,alpha4_rad_s2');
    const without = spatialCsvText(modelOf({ ...DEFAULT_SPATIAL, pDistDeg: 0 }), 'open', UNIT_INPUT).split('\n')[0];
    expect(without).not.toContain('P_x');
  });

  it('names the files after the kind, the values and the branch', () => {
    expect(spatialFileStem(DEFAULT_SPATIAL)).toBe('spatial_sph_60-20-55-45_open');
    expect(spatialFileStem({ ...presetState('rssr-skew'), branch: 'crossed' })).toBe(
      'spatial_rssr_1-4-2-3-60-0.5-1_crossed',
    );
  });
});

describe('plotColumns', () => {
  it('breaks θ4 where it wraps through ±180° and leaves gaps where the loop cannot close', () => {
    // The drag link's output turns fully: θ4 wraps once per turn.
    const sweep = sweepSpatial(modelOf(presetState('sph-drag-link')), 'open', { steps: 720 });
    const cols = plotColumns(sweep);
    let jumps = 0;
    for (let i = 1; i < cols.theta4Deg.length; i++) {
      const a = cols.theta4Deg[i - 1];
      const b = cols.theta4Deg[i];
      if (Number.isFinite(a) && Number.isFinite(b) && Math.abs(b - a) > 90) jumps++;
    }
    expect(jumps).toBe(0);
    expect(cols.theta4Deg.some((x) => Number.isNaN(x))).toBe(true);
    // A double rocker: arcs 20, 60, 30, 50 cannot turn its crank fully.
    const rocker = plotColumns(
      sweepSpatial(modelOf({ ...DEFAULT_SPATIAL, a1Deg: 50, a2Deg: 60, a3Deg: 20, a4Deg: 30 }), 'open'),
    );
    expect(rocker.omega4.some((x) => Number.isNaN(x))).toBe(true);
    expect(rocker.theta2Deg[360]).toBeCloseTo(360, 12);
  });
});

describe('sceneLinkage', () => {
  it('puts the spherical pivots at O2 = z and O4 at a1 from it, on the unit sphere', () => {
    const model = modelOf(DEFAULT_SPATIAL);
    const l = sceneLinkage(model, sweepSpatial(model, 'open'));
    expect(l.crankPivot).toEqual({ x: 0, y: 0, z: 1 });
    expect(l.rockerPivot.x).toBeCloseTo(Math.sin(Math.PI / 3), 15);
    expect(l.rockerPivot.z).toBeCloseTo(0.5, 15);
    expect(l.curve.length % 6).toBe(0);
    expect(l.curve.length).toBeGreaterThan(6 * 300);
  });

  it('scales an RSSR to about 1 whatever its size, and its pose with it', () => {
    for (const k of [1e-200, 1, 1e200]) {
      const s = { ...presetState('rssr-skew'), r2: k, r3: 4 * k, r4: 2 * k, a: 3 * k, h2: 0.5 * k, h4: k };
      const model = modelOf(s);
      const l = sceneLinkage(model, sweepSpatial(model, 'open'));
      expect(l.radius).toBeGreaterThan(0.5);
      expect(l.radius).toBeLessThan(3);
      const p = scenePose(l, { A: { x: k, y: 0, z: 0.5 * k }, B: { x: 0, y: 0, z: 0 } });
      // The size is a + r4 + |h4| = 6k.
      expect(p.A.x).toBeCloseTo(1 / 6, 12);
    }
  });

  it('joins only neighbouring samples that both close', () => {
    const xyz = new Float64Array([0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0]);
    expect(pathSegments(xyz, Uint8Array.of(1, 1, 0, 1), 2)).toEqual([0, 0, 0, 2, 0, 0]);
  });
});

describe('the spatial slice', () => {
  it('names the key and the value of a refused field', () => {
    expect(spatialFieldProblem('a1Deg', 200)).toBe('a1 must be in (0, 180) degrees, got 200');
    expect(spatialFieldProblem('a1Deg', 180)).not.toBeNull();
    expect(spatialFieldProblem('a3Deg', 0)).not.toBeNull();
    expect(spatialFieldProblem('r2', -1)).toBe('r2 must be in (0, 1e+300], got -1');
    expect(spatialFieldProblem('a', 0)).toBeNull();
    expect(spatialFieldProblem('h2', Number.NaN)).toContain('got NaN');
    expect(spatialFieldProblem('pDistDeg', 0)).toBeNull();
  });

  it('wraps the angles that wrap, and returns the same object when nothing changes', () => {
    expect(normalizeSpatial('theta2Deg', 370)).toBe(10);
    expect(normalizeSpatial('betaDeg', 270)).toBe(-90);
    expect(normalizeSpatial('a1Deg', 270)).toBe(270);
    const s = DEFAULT_STATE.spatial;
    expect(spatialReducer(s, { type: 'setSpatialField', field: 'a1Deg', value: s.a1Deg })).toBe(s);
    expect(spatialReducer(s, { type: 'setSpatial', patch: { kind: 'sph' } })).toBe(s);
    expect(spatialReducer(s, { type: 'setSpatialField', field: 'a1Deg', value: 61 }).a1Deg).toBe(61);
  });
});
