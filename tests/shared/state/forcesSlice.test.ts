import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE, reducer } from '../../../src/shared/state/appState';
import type { ForcesState } from '../../../src/shared/state/slices/forcesSlice';
import {
  DEFAULT_FORCES,
  DEFAULT_LINK_MASS,
  FORCES_URL_KEYS,
  forcesReducer,
} from '../../../src/shared/state/slices/forcesSlice';
import { parseUrl, serializeState } from '../../../src/shared/url/url';

const quiet = () => undefined;
const withForces = (forces: ForcesState) => ({ ...DEFAULT_STATE, forces });

describe('forcesReducer', () => {
  it('returns the same object for an action it does not handle, or values it already has', () => {
    expect(forcesReducer(DEFAULT_FORCES, { type: 'setTheta2', deg: 10 })).toBe(DEFAULT_FORCES);
    expect(forcesReducer(DEFAULT_FORCES, { type: 'setForces', patch: { enabled: false, gravityMPerS2: 9.81 } })).toBe(
      DEFAULT_FORCES,
    );
    expect(forcesReducer(DEFAULT_FORCES, { type: 'setLinkMass', link: 'crank', props: { massKg: 1 } })).toBe(
      DEFAULT_FORCES,
    );
    expect(forcesReducer(DEFAULT_FORCES, { type: 'setMassModel', model: 'bars' })).toBe(DEFAULT_FORCES);
  });

  it('sets settings, one link at a time, and seeds the per-link model when asked', () => {
    let s = forcesReducer(DEFAULT_FORCES, { type: 'setForces', patch: { enabled: true, gravityMPerS2: 0 } });
    expect(s).toMatchObject({ enabled: true, gravityMPerS2: 0 });
    s = forcesReducer(s, { type: 'setLinkMass', link: 'rocker', props: { massKg: 3 } });
    expect(s.rocker).toEqual({ ...DEFAULT_LINK_MASS, massKg: 3 });
    expect(s.crank).toBe(DEFAULT_LINK_MASS);
    const seed = {
      crank: { massKg: 2, inertiaKgM2: 0.5, cgDistance: 1, cgAngleDeg: 0 },
      coupler: { massKg: 5, inertiaKgM2: 7, cgDistance: 2.5, cgAngleDeg: 0 },
      rocker: { massKg: 5, inertiaKgM2: 7, cgDistance: 2.5, cgAngleDeg: 0 },
    };
    s = forcesReducer(s, { type: 'setMassModel', model: 'links', seed });
    expect(s.massModel).toBe('links');
    expect(s.coupler).toEqual(seed.coupler);
    expect(s.coupler).not.toBe(seed.coupler);
  });

  it('is composed into the app reducer, leaving the other slices alone', () => {
    const next = reducer(DEFAULT_STATE, { type: 'setForces', patch: { rhoKgPerM: 2 } });
    expect(next.forces.rhoKgPerM).toBe(2);
    expect(next.design).toBe(DEFAULT_STATE.design);
    expect(reducer(DEFAULT_STATE, { type: 'setForces', patch: { rhoKgPerM: 1 } })).toBe(DEFAULT_STATE);
  });
});

describe('forces URL keys', () => {
  it('writes nothing for the default slice', () => {
    const params = new URLSearchParams(serializeState(DEFAULT_STATE));
    for (const k of FORCES_URL_KEYS) expect(params.has(k.name), k.name).toBe(false);
  });

  it('reads the keys the issue names: frc=1, lu, rho, g, fv=1', () => {
    const r = parseUrl('frc=1&lu=mm&rho=2.5&g=0&fv=1', DEFAULT_STATE, quiet);
    expect(r.ignored).toEqual([]);
    expect(r.state.design.lengthUnit).toBe('mm');
    expect(r.state.forces).toEqual({
      ...DEFAULT_FORCES,
      enabled: true,
      rhoKgPerM: 2.5,
      gravityMPerS2: 0,
      showVectors: true,
    });
  });

  it('round-trips every field, the per-link ones with mass=link', () => {
    const forces: ForcesState = {
      enabled: true,
      massModel: 'links',
      rhoKgPerM: 0.75,
      crank: { massKg: 1.25, inertiaKgM2: 0.002, cgDistance: 1.5, cgAngleDeg: 0 },
      coupler: { massKg: 3, inertiaKgM2: 0.125, cgDistance: -0.5, cgAngleDeg: 12.5 },
      rocker: { massKg: 0, inertiaKgM2: 0, cgDistance: 2, cgAngleDeg: -90 },
      gravityMPerS2: 1.62,
      gravityAngleDeg: 180,
      pointForceXN: -12.5,
      pointForceYN: 3e-4,
      loadTorqueNm: -7,
      showVectors: true,
      speedFluctuation: 0.02,
    };
    const text = serializeState(withForces(forces));
    for (const key of ['mass=link', 'm2=1.25', 'i3=0.125', 'c3=-0.5', 'ca3=12.5', 'tl=-7', 'cs=0.02']) {
      expect(text).toContain(key);
    }
    const back = parseUrl(text, DEFAULT_STATE, quiet);
    expect(back.ignored).toEqual([]);
    expect(back.state.forces).toEqual(forces);
  });

  it('leaves the per-link keys out with the uniform bars', () => {
    const forces = { ...DEFAULT_FORCES, enabled: true, crank: { ...DEFAULT_LINK_MASS, massKg: 9 } };
    expect(serializeState(withForces(forces))).not.toMatch(/\bm2=/);
  });

  it('refuses every bad value with its reason, keeping the default', () => {
    const r = parseUrl(
      'frc=2&lu=km&mass=solid&rho=-1&m2=abc&i3=-0.5&g=2000&gd=400&pfx=1e10&tl=x&fv=yes please&cs=0',
      DEFAULT_STATE,
      quiet,
    );
    expect(r.state.forces).toEqual(DEFAULT_FORCES);
    expect(r.ignored.map((p) => [p.key, p.why])).toEqual([
      ['frc', 'expected 0 or 1'],
      ['lu', 'expected mm, cm, m or in'],
      ['mass', 'expected bar or link'],
      ['rho', 'out of range (allowed 0 to 1000000)'],
      ['m2', 'not a number'],
      ['i3', 'out of range (allowed 0 to 1000000000)'],
      ['g', 'out of range (allowed 0 to 1000)'],
      ['gd', 'out of range (allowed -360 to 360)'],
      ['pfx', 'out of range (allowed -1000000000 to 1000000000)'],
      ['tl', 'not a number'],
      ['fv', 'expected 0 or 1'],
      ['cs', 'out of range (allowed 0.000001 to 1)'],
    ]);
  });
});
