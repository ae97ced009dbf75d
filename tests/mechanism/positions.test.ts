import { describe, expect, it } from 'vitest';
import { invertedSliderCrankSpec, sliderCrankSpec, sweepMechanism } from '../../src/mechanism';
import type { MechanismSpec } from '../../src/mechanism';
import { D, circles, dist, dpt, exact, grid, maxRelError, rotate } from './oracle';
import type { DPt } from './oracle';

const joint = (spec: MechanismSpec, id: string) => spec.joints.find((j) => j.id === id)!;

// Errors are judged relative to the linkage's size: a well-conditioned pose (transmission angles away from 0
// and 180 degrees) is determined to a few eps of the largest coordinate; 1e-13 leaves room for the ~10
// rounding steps of the Newton correction and the condition number (< 20 on these linkages).
const TOL = 1e-13;

describe('sweepMechanism: offset slider-crank against a 50-digit construction', () => {
  const spec = sliderCrankSpec(2, 5, 1);
  const inputs = grid(-1, 7.5, 241);
  const r = sweepMechanism(spec, inputs);
  const o2 = dpt(0, 0);
  const a0 = dpt(joint(spec, 'A').x, joint(spec, 'A').y);
  const b0 = dpt(joint(spec, 'B').x, joint(spec, 'B').y);
  const l = dist(a0, b0);
  const ref = { ax: [] as number[], ay: [] as number[], bx: [] as number[], by: [] as number[], s: [] as number[] };
  for (const t of inputs) {
    const a = rotate(a0, o2, exact(t));
    // B on the line y = e (the drawn B's height), right of A: x = Ax + sqrt(l^2 - (e - Ay)^2).
    const bx = a[0].plus(l.pow(2).minus(b0[1].minus(a[1]).pow(2)).sqrt());
    ref.ax.push(a[0].toNumber());
    ref.ay.push(a[1].toNumber());
    ref.bx.push(bx.toNumber());
    ref.by.push(b0[1].toNumber());
    ref.s.push(bx.minus(b0[0]).toNumber());
  }

  it('assembles at every input of a full turn and more (crank + offset < coupler)', () => {
    expect([...r.ok].every((v) => v === 1)).toBe(true);
  });

  it('places the crank pin and the slider block to rounding', () => {
    expect(maxRelError(r.joints.A.x, ref.ax, 8)).toBeLessThan(TOL);
    expect(maxRelError(r.joints.A.y, ref.ay, 8)).toBeLessThan(TOL);
    expect(maxRelError(r.joints.B.x, ref.bx, 8)).toBeLessThan(TOL);
    expect(maxRelError(r.joints.B.y, ref.by, 8)).toBeLessThan(TOL);
    expect(maxRelError(r.joints.S.x, ref.bx, 8)).toBeLessThan(TOL);
    expect(maxRelError(r.sliders.S.s, ref.s, 8)).toBeLessThan(TOL);
  });

  it('reports the crank angle as the input and the slider never turns', () => {
    expect(maxRelError(r.links.crank.angle, inputs, 8)).toBeLessThan(TOL);
    expect(Math.max(...r.links.slider.angle.map(Math.abs))).toBeLessThan(TOL);
  });
});

describe('sweepMechanism: inverted slider-crank (crank-shaper) against a 50-digit construction', () => {
  const spec = invertedSliderCrankSpec(2, 4, 8, 0.3);
  const inputs = grid(0, 6.5, 181);
  const r = sweepMechanism(spec, inputs);
  const o2 = dpt(0, 0);
  const o4: DPt = dpt(0, -4);
  const a0 = dpt(joint(spec, 'A').x, joint(spec, 'A').y);
  const tip0 = dpt(spec.points![0].x, spec.points![0].y);
  const phi0 = D.atan2(a0[1].minus(o4[1]), a0[0].minus(o4[0]));

  it('turns the rocker to point at the crank pin and slides the block along it', () => {
    expect([...r.ok].every((v) => v === 1)).toBe(true);
    const tipX: number[] = [];
    const tipY: number[] = [];
    const s: number[] = [];
    const phi: number[] = [];
    inputs.forEach((t, i) => {
      const a = rotate(a0, o2, exact(t));
      let turn = D.atan2(a[1].minus(o4[1]), a[0].minus(o4[0])).minus(phi0);
      // The rocker swings (O2 inside... no: |O2 O4| > r, a rocker): the unwrapped turn is the wrapped one.
      const ref = r.links.rocker.angle[i];
      const twoPi = D.acos(-1).times(2);
      while (turn.minus(ref).greaterThan(3)) turn = turn.minus(twoPi);
      while (turn.minus(ref).lessThan(-3)) turn = turn.plus(twoPi);
      const tip = rotate(tip0, o4, turn);
      tipX.push(tip[0].toNumber());
      tipY.push(tip[1].toNumber());
      phi.push(turn.toNumber());
      s.push(dist(a, o4).minus(dist(a0, o4)).toNumber());
    });
    expect(maxRelError(r.points.Tip.x, tipX, 8)).toBeLessThan(TOL);
    expect(maxRelError(r.points.Tip.y, tipY, 8)).toBeLessThan(TOL);
    expect(maxRelError(r.links.rocker.angle, phi, 1)).toBeLessThan(TOL);
    expect(maxRelError(r.sliders.S.s, s, 8)).toBeLessThan(TOL);
  });
});

void circles;
