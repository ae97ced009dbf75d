/**
 * Bad input to the force functions throws an Error that names the field and shows the value; expected
 * outcomes (a limit position, a crank that cannot turn) are data, tested elsewhere.
 */
import { describe, expect, it } from 'vitest';
import type { LinkInertias, Loads } from '../../src/solver';
import { forceCycle, linkForces, solveClosedForm, sweepForces, torqueCycleStats } from '../../src/solver';

const l = { r1: 0.3, r2: 0.1, r3: 0.25, r4: 0.25 };
const theta2 = 0.5;
const pose = solveClosedForm(l, theta2, 'open')!;
const input = { omega2: 10, alpha2: 0 };
const link = { mass: 1, inertia: 0.01, cg: { dist: 0.05, angle: 0 } };
const inertia: LinkInertias = { crank: link, coupler: link, rocker: link };
const loads: Loads = { gravity: { g: 9.81 } };

/** Calls linkForces with one argument replaced (as unknown: these are the shapes a JS caller can send). */
function call(patch: { input?: unknown; inertia?: unknown; loads?: unknown }): () => void {
  return () =>
    linkForces(
      l,
      theta2,
      pose,
      (patch.input ?? input) as typeof input,
      (patch.inertia ?? inertia) as LinkInertias,
      (patch.loads ?? loads) as Loads,
    );
}

const withCrank = (crank: unknown) => ({ inertia: { ...inertia, crank } });

describe('linkForces argument errors', () => {
  it.each([
    [
      'a negative mass',
      withCrank({ ...link, mass: -1 }),
      'inertia.crank.mass must be a non-negative finite mass in kg, got -1',
    ],
    [
      'a non-finite inertia',
      { inertia: { ...inertia, coupler: { ...link, inertia: Infinity } } },
      'inertia.coupler.inertia must be a non-negative finite moment of inertia in kg·m², got Infinity',
    ],
    [
      'a mass that is a string',
      withCrank({ ...link, mass: '2' }),
      'inertia.crank.mass must be a non-negative finite mass in kg, got "2"',
    ],
    [
      'a missing link',
      { inertia: { crank: link, coupler: link } },
      'inertia.rocker must be an object, got undefined (missing)',
    ],
    ['a missing CG', withCrank({ mass: 1, inertia: 0 }), 'inertia.crank.cg must be an object, got undefined (missing)'],
    [
      'a CG distance of NaN',
      { inertia: { ...inertia, rocker: { ...link, cg: { dist: NaN, angle: 0 } } } },
      'inertia.rocker.cg.dist must be a finite length in m, got NaN',
    ],
    [
      'omega2 not finite',
      { input: { omega2: NaN, alpha2: 0 } },
      'input.omega2 must be a finite angular velocity in rad/s, got NaN',
    ],
    [
      'a gravity object without g',
      { loads: { gravity: {} } },
      'loads.gravity.g must be a non-negative finite acceleration in m/s², got undefined (missing)',
    ],
    [
      'a gravity g that is a string',
      { loads: { gravity: { g: '9.81' } } },
      'loads.gravity.g must be a non-negative finite acceleration in m/s², got "9.81"',
    ],
    [
      'a negative g',
      { loads: { gravity: { g: -9.81 } } },
      'loads.gravity.g must be a non-negative finite acceleration in m/s², got -9.81',
    ],
    [
      'a gravity angle of Infinity',
      { loads: { gravity: { g: 1, angle: Infinity } } },
      'loads.gravity.angle must be a finite angle in radians, got Infinity',
    ],
    [
      'a coupler force without fy',
      { loads: { couplerForce: { pDist: 0.1, pAngle: 0, fx: 1 } } },
      'loads.couplerForce.fy must be a finite force in N, got undefined (missing)',
    ],
    [
      'an output torque that is a string',
      { loads: { outputTorque: '3' } },
      'loads.outputTorque must be a finite torque in N·m, got "3"',
    ],
    ['loads that are not an object', { loads: 5 }, 'loads must be an object, got 5'],
    ['inertia that is an array', { inertia: [] }, 'inertia must be an object, got []'],
  ])('names %s', (_what, patch, message) => {
    expect(call(patch)).toThrow(message);
  });

  it('names a bad pose or linkage through the rates it needs', () => {
    expect(() => linkForces(l, theta2, { theta3: NaN, theta4: 1 }, input, inertia, loads)).toThrow(
      'pose.theta3 must be a finite angle in radians, got NaN',
    );
    expect(() => linkForces({ ...l, r2: -1 }, theta2, pose, input, inertia, loads)).toThrow(
      'r2 must be a positive finite length, got -1',
    );
  });
});

describe('sweepForces, torqueCycleStats and forceCycle argument errors', () => {
  it('names the field and value', () => {
    const ok = () => true;
    expect(() =>
      sweepForces(l, [theta2], [pose.theta3], [pose.theta4], ok, input, inertia, { outputTorque: NaN }),
    ).toThrow('loads.outputTorque must be a finite torque in N·m, got NaN');
    expect(() => sweepForces(l, [theta2], [pose.theta3], [NaN], ok, input, inertia, loads)).toThrow('theta4[0]');
    const theta = [0, 2, 4, 2 * Math.PI];
    expect(() => torqueCycleStats(theta, [1, 2, 3], 1, 0.05)).toThrow(
      'torque must have the length of theta2 (4), got 3',
    );
    expect(() => torqueCycleStats(theta, [1, 2, 3, 1], 1, 0)).toThrow(
      'k must be a positive finite coefficient of speed fluctuation, got 0',
    );
    expect(() => torqueCycleStats(theta, [1, 2, 3, 1], Infinity, 0.05)).toThrow(
      'omega2 must be a finite angular velocity in rad/s, got Infinity',
    );
    expect(() => torqueCycleStats(theta, [1, '2', 3, 1] as unknown as number[], 1, 0.05)).toThrow(
      'torque[1] must be a number, got "2"',
    );
    expect(() => forceCycle(l, 'open', input, inertia, loads, { points: 2.5 })).toThrow(
      'opts.points must be an integer from 3 to 1e7, got 2.5',
    );
    expect(() => forceCycle(l, 'open', input, inertia, loads, { k: -1 })).toThrow(
      'opts.k must be a positive finite coefficient of speed fluctuation, got -1',
    );
    expect(() => forceCycle(l, 'sideways' as 'open', input, inertia, loads)).toThrow(
      `branch must be 'open' or 'crossed', got "sideways"`,
    );
  });
});
