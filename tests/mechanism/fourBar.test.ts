import { describe, expect, it } from 'vitest';
import { fourBarSpec, peaucellierSpec } from '../../src/mechanism';
import { sweepWith } from '../../src/mechanism/sweep';
import { solveClosedForm } from '../../src/solver';
import { grid } from './oracle';

const PATHS = [
  ['dyad path', true],
  ['Newton path', false],
] as const;

describe('sweepMechanism: the four-bar template against src/solver', () => {
  // The template is drawn from r1..r4 in doubles, so its lengths differ from 6-2-5-5 by rounding (~1e-16
  // relative); the transmission angle stays in [47, 107] degrees, so poses agree to ~1e-15 rad. 1e-13 leaves
  // a margin of 100.
  const spec = fourBarSpec(6, 2, 5, 5);
  const b0 = spec.joints.find((j) => j.id === 'B')!;
  const theta30 = Math.atan2(b0.y, b0.x - 2);
  const theta40 = Math.atan2(b0.y, b0.x - 6);
  const inputs = grid(0, 4 * Math.acos(-1), 721);
  for (const [name, dyads] of PATHS) {
    it(`matches solveClosedForm at every point of two turns (${name})`, () => {
      const r = sweepWith(spec, inputs, undefined, dyads);
      expect(r.method).toBe(dyads ? 'dyads' : 'newton');
      let worst = 0;
      inputs.forEach((t, i) => {
        const ref = solveClosedForm({ r1: 6, r2: 2, r3: 5, r4: 5 }, t, 'open')!;
        const d3 = Math.abs(Math.sin(theta30 + r.links.coupler.angle[i] - ref.theta3));
        const d4 = Math.abs(Math.sin(theta40 + r.links.rocker.angle[i] - ref.theta4));
        const bx = 6 + 5 * Math.cos(ref.theta4);
        const by = 5 * Math.sin(ref.theta4);
        worst = Math.max(worst, d3, d4, Math.abs(r.joints.B.x[i] - bx) / 6, Math.abs(r.joints.B.y[i] - by) / 6);
        expect(r.ok[i]).toBe(1);
      });
      expect(worst).toBeLessThan(1e-13);
    });
  }
});

describe('sweepMechanism: Peaucellier–Lipkin', () => {
  // |OC| |OP| = L^2 - s^2 makes P run on x = (L^2 - s^2) / (2c) = 3.375; the drawn doubles make the four sides
  // equal only to rounding, so the line holds to a few eps of the linkage's size (1e-14 of 4: 2e-15 spread).
  const spec = peaucellierSpec();
  for (const [name, dyads] of PATHS) {
    it(`keeps its tracer on x = 3.375 to rounding (${name})`, () => {
      const inputs = grid(-1.4, 1.4, 281);
      const r = sweepWith(spec, inputs, undefined, dyads);
      expect([...r.ok].every((v) => v === 1)).toBe(true);
      for (let i = 0; i < inputs.length; i++) expect(Math.abs(r.points.Tracer.x[i] - 3.375)).toBeLessThan(4e-14);
      // And it does move along the line: a straight-line mechanism, not a stuck one.
      expect(Math.max(...r.points.Tracer.y) - Math.min(...r.points.Tracer.y)).toBeGreaterThan(3);
    });
  }
});
