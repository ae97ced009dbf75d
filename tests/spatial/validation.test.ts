import { describe, expect, it } from 'vitest';
import {
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
import type { RSSRLinkage, SpatialModel, SphericalLinkage } from '../../src/spatial';

const SPH: SphericalLinkage = { a1: 1, a2: 0.3, a3: 0.9, a4: 0.7 };
const RSSR: RSSRLinkage = { r2: 1, r3: 4, r4: 2, a: 3, beta: 1, h2: 0.5, h4: -0.25 };
const bad = <T>(base: T, patch: Record<string, unknown>) => ({ ...base, ...patch }) as T;

describe('refusals name the field and the value', () => {
  it.each([
    ['a1', 0],
    ['a1', Math.PI],
    ['a2', -1],
    ['a3', NaN],
    ['a4', Infinity],
    ['a4', '0.5'],
  ])('solveSpherical refuses %s = %s as an arc in (0, pi)', (field, value) => {
    expect(() => solveSpherical(bad(SPH, { [field]: value }), 0, 'open')).toThrow(
      new RegExp(`^${field} must be an arc in \\(0, pi\\) radians, got ${String(value === '0.5' ? '"0.5"' : value)}`),
    );
  });

  it.each([
    ['pDist', -0.1],
    ['pDist', 4],
    ['pDist', NaN],
  ])('solveSpherical refuses %s = %s', (field, value) => {
    expect(() => solveSpherical(bad(SPH, { [field]: value }), 0, 'open')).toThrow(
      new RegExp(`^pDist must be an arc in \\[0, pi\\] radians, got ${value}`),
    );
  });

  it('solveSpherical refuses a non-number pAngle', () => {
    expect(() => solveSpherical(bad(SPH, { pDist: 0.2, pAngle: NaN }), 0, 'open')).toThrow(/^pAngle must be a finite/);
  });

  it.each([
    ['r2', 0, 'positive'],
    ['r3', -1, 'positive'],
    ['r4', NaN, 'positive'],
    ['a', -1e-9, 'non-negative'],
  ])('solveRSSR refuses %s = %s as a length', (field, value, kind) => {
    expect(() => solveRSSR(bad(RSSR, { [field]: value }), 0, 'open')).toThrow(
      new RegExp(`^${field} must be a ${kind} finite length, got ${value}`),
    );
  });

  it.each([
    ['beta', NaN],
    ['h2', Infinity],
    ['h4', 'x'],
  ])('solveRSSR refuses %s = %s', (field, value) => {
    expect(() => solveRSSR(bad(RSSR, { [field]: value }), 0, 'open')).toThrow(new RegExp(`^${field} must be a finite`));
  });

  it('both refuse a bad theta2, branch, input, or no linkage at all', () => {
    for (const solve of [
      (t: unknown, b: unknown, i?: unknown) => solveSpherical(SPH, t as number, b as 'open', i as undefined),
      (t: unknown, b: unknown, i?: unknown) => solveRSSR(RSSR, t as number, b as 'open', i as undefined),
    ]) {
      expect(() => solve(NaN, 'open')).toThrow(/^theta2 must be a finite angle in radians, got NaN/);
      expect(() => solve(Infinity, 'open')).toThrow(/^theta2 .* got Infinity/);
      expect(() => solve('1', 'open')).toThrow(/^theta2 .* got "1"/);
      expect(() => solve(0, 'up')).toThrow(/^branch must be 'open' or 'crossed', got "up"/);
      expect(() => solve(0, 'open', { omega2: NaN, alpha2: 0 })).toThrow(/^omega2 must be a finite .* got NaN/);
      expect(() => solve(0, 'open', { omega2: 1, alpha2: Infinity })).toThrow(
        /^alpha2 must be a finite .* got Infinity/,
      );
      expect(() => solve(0, 'open', 3)).toThrow(/^input must be an object, got 3/);
    }
    expect(() => solveSpherical(null as unknown as SphericalLinkage, 0, 'open')).toThrow(/^linkage must be an object/);
    expect(() => solveRSSR(undefined as unknown as RSSRLinkage, 0, 'open')).toThrow(/^linkage must be an object/);
  });

  it('the sweeps, exports, motion and classification refuse bad options and models', () => {
    const sph: SpatialModel = { kind: 'spherical', linkage: SPH };
    expect(() => sweepSpatial({ kind: 'planar' } as unknown as SpatialModel, 'open')).toThrow(
      /^model.kind must be 'spherical' or 'rssr', got "planar"/,
    );
    expect(() => sweepSpatial(sph, 'open', { steps: 0 })).toThrow(/^steps must be an integer .* got 0/);
    expect(() => sweepSpatial(sph, 'open', { steps: 1.5 })).toThrow(/^steps .* got 1.5/);
    expect(() => sweepSpatial(sph, 'open', { start: NaN })).toThrow(/^start must be a finite/);
    expect(() => sweepSpatial(sph, 'open', { omega2: Infinity })).toThrow(/^omega2 must be a finite/);
    expect(() => spatialCsvRows(sph, 'open', { stepDeg: 0 })).toThrow(/^stepDeg must be a positive .* got 0/);
    expect(() => spatialCsvRows(sph, 'open', { stepDeg: -1 })).toThrow(/^stepDeg .* got -1/);
    expect(() => spatialCsvRows(sph, 'open', { stepDeg: 1e-9 })).toThrow(/^stepDeg gives more than/);
    expect(() => spatialCsvRows(sph, 'open', { alpha2: NaN })).toThrow(/^alpha2 must be a finite/);
    expect(() => outputMotion(sph, 'open', 3)).toThrow(/^samples must be an integer .* got 3/);
    expect(() => outputMotion(sph, 'sideways' as 'open')).toThrow(/^branch must be/);
    expect(() => transmissionAngle(sph, NaN, 'open')).toThrow(/^theta2 must be a finite/);
    expect(() => sphericalCouplerCurve(SPH, 'open')).toThrow(/^pDist must be set for a coupler curve, got undefined/);
    expect(() => classifySpherical(bad(SPH, { a3: 4 }))).toThrow(/^a3 must be an arc/);
    expect(() => classifyRSSR(bad(RSSR, { r3: 0 }))).toThrow(/^r3 must be a positive/);
  });
});
