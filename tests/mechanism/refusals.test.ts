import { describe, expect, it } from 'vitest';
import { fourBarSpec, mobility, sweepMechanism } from '../../src/mechanism';
import type { JointSpec, MechanismSpec } from '../../src/mechanism';

const base = (): MechanismSpec => fourBarSpec(6, 2, 5, 5);
const withJoint = (s: MechanismSpec, id: string, patch: Partial<JointSpec>): MechanismSpec => ({
  ...s,
  joints: s.joints.map((j) => (j.id === id ? { ...j, ...patch } : j)),
});

describe('mobility', () => {
  it('counts 3 (n - 1) - 2 joints', () => {
    expect(mobility(base())).toBe(1);
    expect(mobility({ ...base(), links: [...base().links, 'extra'] })).toBe(4);
  });
});

describe('sweepMechanism refuses what is not a mobility-1 linkage, naming the id or field', () => {
  const cases: Array<[string, () => unknown, RegExp | string]> = [
    ['an unknown link', () => withJoint(base(), 'A', { links: ['crank', 'nope'] }), 'joint "A": unknown link "nope"'],
    [
      'a duplicate joint id',
      () => ({ ...base(), joints: base().joints.map((j) => (j.id === 'B' ? { ...j, id: 'A' } : j)) }),
      'joint "A": duplicate joint id',
    ],
    [
      'a P joint without an angle',
      () => withJoint(base(), 'B', { kind: 'P' }),
      'joint "B": a P joint needs an angle (slide direction, radians)',
    ],
    ['an unknown input joint', () => ({ ...base(), input: { joint: 'Z' } }), 'input.joint: unknown joint "Z"'],
    ['a non-finite x', () => withJoint(base(), 'B', { x: NaN }), 'joint "B": x must be a finite number, got NaN'],
    [
      'a non-finite y',
      () => withJoint(base(), 'O4', { y: Infinity }),
      'joint "O4": y must be a finite number, got Infinity',
    ],
    [
      'a non-finite tracer',
      () => ({ ...base(), points: [{ id: 'P', link: 'coupler', x: 1, y: -Infinity }] }),
      'point "P": y must be a finite number, got -Infinity',
    ],
    [
      'a tracer on an unknown link',
      () => ({ ...base(), points: [{ id: 'P', link: 'cupler', x: 1, y: 1 }] }),
      'point "P": unknown link "cupler"',
    ],
    [
      'a joint of a link with itself',
      () => withJoint(base(), 'A', { links: ['crank', 'crank'] }),
      'joint "A": joins link "crank" to itself',
    ],
    ['no ground', () => ({ ...base(), links: ['frame', 'crank', 'coupler', 'rocker'] }), /links must include 'ground'/],
    [
      'mobility 2 (a five-bar)',
      () => ({
        links: ['ground', 'a', 'b', 'c', 'd'],
        joints: [
          { id: 'O1', kind: 'R', links: ['ground', 'a'], x: 0, y: 0 },
          { id: 'J1', kind: 'R', links: ['a', 'b'], x: 1, y: 1 },
          { id: 'J2', kind: 'R', links: ['b', 'c'], x: 2, y: 2 },
          { id: 'J3', kind: 'R', links: ['c', 'd'], x: 3, y: 1 },
          { id: 'O2', kind: 'R', links: ['d', 'ground'], x: 4, y: 0 },
        ],
        input: { joint: 'O1' },
      }),
      'mobility 2: add a joint or fix a link',
    ],
    [
      'mobility 0 (a triangle)',
      () => ({
        links: ['ground', 'a', 'b'],
        joints: [
          { id: 'O1', kind: 'R', links: ['ground', 'a'], x: 0, y: 0 },
          { id: 'J', kind: 'R', links: ['a', 'b'], x: 1, y: 1 },
          { id: 'O2', kind: 'R', links: ['b', 'ground'], x: 2, y: 0 },
        ],
        input: { joint: 'O1' },
      }),
      'mobility 0: this is a structure',
    ],
    [
      'disconnected links',
      () => {
        const s = base();
        const pair = (id: string, x: number): JointSpec => ({ id, kind: 'R', links: ['x', 'y'], x, y: 9 });
        return {
          ...s,
          links: [...s.links, 'x', 'y'],
          joints: [...s.joints, pair('X1', 0), pair('X2', 1), pair('X3', 2)],
        };
      },
      'links "x", "y" are disconnected from the ground',
    ],
  ];
  for (const [what, spec, message] of cases) {
    it(`refuses ${what}`, () => {
      expect(() => sweepMechanism(spec() as MechanismSpec, [0])).toThrow(message);
    });
  }

  it('refuses a non-finite input and bad rates, naming them', () => {
    expect(() => sweepMechanism(base(), [0, NaN])).toThrow('inputs[1] must be a finite number, got NaN');
    expect(() => sweepMechanism(base(), [0], { omega: 1, alpha: Infinity })).toThrow(
      'rates.alpha must be a finite number, got Infinity',
    );
  });
});
