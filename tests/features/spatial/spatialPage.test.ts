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
    const lines = spatialCsvText(modelOf(s), 'open').trim().split('\n');
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

  it('adds P_x, P_y, P_z with a coupler point only', () => {
    const withP = spatialCsvText(modelOf(DEFAULT_SPATIAL), 'open').split('\n')[0];
    expect(withP).toBe('theta2_deg,A_x,A_y,A_z,B_x,B_y,B_z,P_x,P_y,P_z,theta4_deg,omega4_rad_s,alpha4_rad_s2');
    const without = spatialCsvText(modelOf({ ...DEFAULT_SPATIAL, pDistDeg: 0 }), 'open').split('\n')[0];
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
