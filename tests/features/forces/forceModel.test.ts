import { describe, expect, it } from 'vitest';
import { linkForces } from '../../../src/solver/forces';
import { solveClosedForm } from '../../../src/solver/closedForm';
import { DEFAULT_STATE, reducer } from '../../../src/shared/state/appState';
import { parseUrl } from '../../../src/shared/url/url';
import type { AppState } from '../../../src/shared/state/appState';
import type { LengthUnit } from '../../../src/shared/state/slices/designSlice';
import { localPose } from '../../../src/shared/linkage/localPose';
import { barSeeds, forceSetup, linkInertias, poseForces } from '../../../src/features/forces/forceModel';
import { slenderBar } from '../../../src/shared/linkage/slenderBar';

/** The 6-2-5-5 linkage as long as 6, 2, 5 and 5 decimetres, written in a unit (mm, cm, m or in). */
function stateIn(unit: LengthUnit, perDecimetre: number, extra: Partial<AppState['forces']> = {}): AppState {
  const k = perDecimetre;
  return {
    ...DEFAULT_STATE,
    design: {
      ...DEFAULT_STATE.design,
      linkage: { r1: 6 * k, r2: 2 * k, r3: 5 * k, r4: 5 * k },
      coupler: { distance: 2.5 * k, angleDeg: 30 },
      lengthUnit: unit,
    },
    forces: { ...DEFAULT_STATE.forces, enabled: true, pointForceXN: 12, loadTorqueNm: -2, ...extra },
  };
}

/** The torque at 45° of a state's setup. */
function torqueAt45(s: AppState): number {
  const setup = forceSetup(s);
  const theta2 = Math.PI / 4;
  const a = solveClosedForm(setup.linkage, theta2, 'open');
  if (!a) throw new Error('the test linkage assembles at 45°');
  return poseForces(setup, theta2, a).forces?.torque ?? Number.NaN;
}

describe('slenderBar', () => {
  it('is a uniform bar: m = ρL, I = mL²/12, the CG at mid-link', () => {
    expect(slenderBar(0.5, 4)).toEqual({ mass: 2, inertia: (2 * 0.25) / 12, cg: { dist: 0.25, angle: 0 } });
  });
});

describe('forceSetup', () => {
  it('gives the same torque for the same linkage in mm, cm, m and in', () => {
    const m = torqueAt45(stateIn('m', 0.1));
    expect(Math.abs(m)).toBeGreaterThan(0.1);
    // 0.1 m is 100 mm, 10 cm and 100 / 25.4 in; each length's conversion rounds once (relative 1e-16), which
    // moves the torque by a few eps of its terms: 1e-12 still fails for a unit slip (a factor 10 or more).
    for (const [unit, k] of [
      ['mm', 100],
      ['cm', 10],
      ['in', 100 / 25.4],
    ] as const) {
      expect(Math.abs(torqueAt45(stateIn(unit, k)) - m), unit).toBeLessThan(1e-12 * Math.abs(m));
    }
  });

  it('converts the lengths and the coupler point to metres at the edge, and the per-link CG offsets too', () => {
    const s = stateIn('mm', 100, {
      massModel: 'links',
      crank: { massKg: 1, inertiaKgM2: 0.1, cgDistance: 50, cgAngleDeg: 90 },
    });
    const setup = forceSetup(s);
    expect(setup.linkage).toEqual({ r1: 0.6, r2: 0.2, r3: 0.5, r4: 0.5 });
    expect(setup.loads.couplerForce?.pDist).toBeCloseTo(0.25, 15);
    expect(setup.inertia.crank.cg.dist).toBeCloseTo(0.05, 15);
    expect(setup.inertia.crank.cg.angle).toBeCloseTo(Math.PI / 2, 15);
    // Gravity straight down is left to the solver's exact -y.
    expect(setup.loads.gravity).toEqual({ g: 9.81 });
  });

  it('signs ω2 by the animation direction, as the motion panel does', () => {
    const s = stateIn('m', 0.1);
    expect(forceSetup({ ...s, motion: { ...s.motion, direction: -1 } }).input.omega2).toBe(-s.motion.omega2RadPerS);
  });

  it('leaves the kinematics as they are in any unit: the pose is the same numbers', () => {
    const s = stateIn('m', 1);
    const mm = { ...s, design: { ...s.design, lengthUnit: 'mm' as const } };
    const a = localPose(s.design.linkage, 45, 'open', s.design.coupler, false);
    const b = localPose(mm.design.linkage, 45, 'open', mm.design.coupler, false);
    expect(b.pose).toEqual(a.pose);
  });
});

describe('the length unit (issue 34 item 11)', () => {
  it('converts the lengths when switched, m to mm: 6 m is 6000 mm, the same machine, the same T12', () => {
    const links = {
      crank: { massKg: 2, inertiaKgM2: 0.1, cgDistance: 1.2, cgAngleDeg: 10 },
      coupler: { massKg: 3, inertiaKgM2: 0.4, cgDistance: 2.5, cgAngleDeg: -20 },
      rocker: { massKg: 2.5, inertiaKgM2: 0.3, cgDistance: 2, cgAngleDeg: 0 },
    };
    for (const extra of [{}, { massModel: 'links' as const, ...links }]) {
      const m = stateIn('m', 1, extra);
      const mm = reducer(m, { type: 'setLengthUnit', from: 'm', to: 'mm' });
      expect(mm.design.lengthUnit).toBe('mm');
      expect(mm.design.linkage).toEqual({ r1: 6000, r2: 2000, r3: 5000, r4: 5000 });
      expect(mm.design.coupler.distance).toBe(2500);
      // The same machine: T12 agrees to rounding (the SI lengths are the same doubles up to one unit in the last place).
      expect(torqueAt45(mm)).toBeCloseTo(torqueAt45(m), 9);
      expect(Math.abs(torqueAt45(mm) - torqueAt45(m))).toBeLessThanOrEqual(1e-12 * Math.abs(torqueAt45(m)));
      if ('massModel' in extra) expect(mm.forces.coupler.cgDistance).toBe(2500);
    }
  });

  it('comes back to the same numbers from inches (no float noise kept)', () => {
    const m = stateIn('m', 1);
    const back = reducer(reducer(m, { type: 'setLengthUnit', from: 'm', to: 'in' }), {
      type: 'setLengthUnit',
      from: 'in',
      to: 'm',
    });
    expect(back.design.linkage).toEqual(m.design.linkage);
    expect(back.design.coupler).toEqual(m.design.coupler);
  });

  it('reads an old link with lu as before: its numbers are already in the unit (lu=mm&r1=600 is 600 mm)', () => {
    const r = parseUrl('r1=600&r2=200&r3=500&r4=500&lu=mm', DEFAULT_STATE, () => {});
    expect(r.ignored).toEqual([]);
    expect(r.state.design.linkage).toEqual({ r1: 600, r2: 200, r3: 500, r4: 500 });
    expect(r.state.design.lengthUnit).toBe('mm');
  });
});

describe('linkInertias and barSeeds', () => {
  it('seeds the per-link model with the bars shown, so switching models keeps the numbers', () => {
    const s = stateIn('cm', 10, { rhoKgPerM: 3 });
    const bars = linkInertias(s.design.linkage, s.design.lengthUnit, s.forces);
    const seeded = linkInertias(s.design.linkage, s.design.lengthUnit, {
      ...s.forces,
      massModel: 'links',
      ...barSeeds(s.design.linkage, s.design.lengthUnit, s.forces),
    });
    for (const k of ['crank', 'coupler', 'rocker'] as const) {
      expect(seeded[k].mass).toBeCloseTo(bars[k].mass, 14);
      expect(seeded[k].inertia).toBeCloseTo(bars[k].inertia, 14);
      expect(seeded[k].cg.dist).toBeCloseTo(bars[k].cg.dist, 14);
    }
  });
});

describe('poseForces', () => {
  it('says limit-position, not NaN, where the coupler and rocker are in line', () => {
    const s = stateIn('m', 1);
    const setup = forceSetup(s);
    // A pose with theta4 = theta3: the determinant r3 r4 sin mu is 0.
    const p = poseForces(setup, 0.3, { theta3: 1, theta4: 1 });
    expect(p.status).toBe('limit-position');
    expect(p.forces).toBeNull();
    expect(poseForces(setup, 0.3, null).status).toBe('no-pose');
  });

  it('is the solver at the pose, in SI', () => {
    const s = stateIn('mm', 100);
    const setup = forceSetup(s);
    const a = solveClosedForm(setup.linkage, 1, 'open')!;
    const f = linkForces(setup.linkage, 1, a, setup.input, setup.inertia, setup.loads);
    expect(poseForces(setup, 1, a).forces).toEqual(f);
  });
});
