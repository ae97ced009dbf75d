import { describe, expect, it } from 'vitest';
import { invertedSliderCrankSpec, sliderCrankSpec, stephensonIIISpec } from '../../src/mechanism';
import type { MechanismSpec, MechanismSweep } from '../../src/mechanism';
import { sweepWith } from '../../src/mechanism/sweep';
import { D, circles, dist, dpt, exact, grid, rotate, sideOf } from './oracle';
import type { DPt, Dec } from './oracle';

const at = (spec: MechanismSpec, id: string): DPt => {
  const j = spec.joints.find((k) => k.id === id)!;
  return dpt(j.x, j.y);
};

/** A 50-digit pose of named points as a function of the input (Decimal), from the drawn doubles taken as exact. */
type Oracle = (t: Dec) => Record<string, DPt>;

/** Stephenson III: crank O2A, four-bar to O4 (B on the drawn side), coupler point C, dyad C–D–O6. */
function stephensonIIIOracle(spec: MechanismSpec): Oracle {
  const [o2, a0, b0, o4, c0, d0, o6] = ['O2', 'A', 'B', 'O4', 'C', 'D', 'O6'].map((id) => at(spec, id));
  const sideB = sideOf(a0, o4, b0);
  const sideD = sideOf(c0, o6, d0);
  const ab = dist(a0, b0);
  const o4b = dist(o4, b0);
  const cd = dist(c0, d0);
  const o6d = dist(o6, d0);
  const ang = (p: DPt, q: DPt) => D.atan2(q[1].minus(p[1]), q[0].minus(p[0]));
  return (t) => {
    const a = rotate(a0, o2, t);
    const b = circles(a, ab, o4, o4b, sideB)!;
    // C is fixed in the coupler: turn A0C0 by the coupler's rotation about A.
    const turn = ang(a, b).minus(ang(a0, b0));
    const moved = rotate(c0, a0, turn);
    const c: DPt = [moved[0].plus(a[0]).minus(a0[0]), moved[1].plus(a[1]).minus(a0[1])];
    const d = circles(c, cd, o6, o6d, sideD)!;
    return { A: a, B: b, C: c, D: d };
  };
}

/** Offset slider-crank: B on the drawn line y = e, right of A. */
function sliderCrankOracle(spec: MechanismSpec): Oracle {
  const a0 = at(spec, 'A');
  const b0 = at(spec, 'B');
  const l = dist(a0, b0);
  return (t) => {
    const a = rotate(a0, dpt(0, 0), t);
    const bx = a[0].plus(l.pow(2).minus(b0[1].minus(a[1]).pow(2)).sqrt());
    return { A: a, B: [bx, b0[1]] };
  };
}

/** Inverted slider-crank: the block at A (the crank pin) slides on the rocker about O4 = (0, -4). */
function invertedOracle(spec: MechanismSpec): Oracle {
  const a0 = at(spec, 'A');
  return (t) => {
    const a = rotate(a0, dpt(0, 0), t);
    return { A: a, S: a };
  };
}

const CASES: Array<[string, MechanismSpec, (s: MechanismSpec) => Oracle, boolean]> = [
  ['Stephenson III six-bar (dyad path)', stephensonIIISpec(0.5), stephensonIIIOracle, true],
  ['Stephenson III six-bar (Newton path)', stephensonIIISpec(0.5), stephensonIIIOracle, false],
  ['offset slider-crank (Newton path)', sliderCrankSpec(2, 5, 1), sliderCrankOracle, false],
  ['inverted slider-crank (Newton path)', invertedSliderCrankSpec(2, 4, 8, 0.3), invertedOracle, false],
];

// Central differences in 50 digits: first derivative with h = 1e-15 (truncation ~h^2 = 1e-30), second with
// h = 1e-10 (truncation ~1e-20, cancellation 50 - 20 = 30 digits left): both exact to double precision.
const H1 = new D('1e-15');
const H2 = new D('1e-10');

function check(r: MechanismSweep, inputs: Float64Array, oracle: Oracle, omega: number, alpha: number): number {
  let worst = 0;
  const w = new D(omega);
  const al = new D(alpha);
  inputs.forEach((ti, i) => {
    const t = exact(ti);
    const p0 = oracle(t);
    const p1 = oracle(t.plus(H1));
    const m1 = oracle(t.minus(H1));
    const p2 = oracle(t.plus(H2));
    const m2 = oracle(t.minus(H2));
    for (const id of Object.keys(p0)) {
      const s = r.joints[id];
      for (const c of [0, 1] as const) {
        const x = p0[id][c];
        const dx = p1[id][c].minus(m1[id][c]).div(H1.times(2));
        const ddx = p2[id][c].minus(x.times(2)).plus(m2[id][c]).div(H2.pow(2));
        const v = dx.times(w);
        const acc = ddx.times(w.pow(2)).plus(dx.times(al));
        const got = c === 0 ? [s.x[i], s.vx![i], s.ax![i]] : [s.y[i], s.vy![i], s.ay![i]];
        // Relative to the linkage's size (8) and the rates' size (8 |omega|, 8 omega^2 + 8 |alpha|).
        worst = Math.max(
          worst,
          Math.abs(got[0] - x.toNumber()) / 8,
          Math.abs(got[1] - v.toNumber()) / (8 * Math.abs(omega)),
          Math.abs(got[2] - acc.toNumber()) / (8 * (omega * omega + Math.abs(alpha))),
        );
      }
    }
  });
  return worst;
}

describe('sweepMechanism: positions and rates against 50-digit constructions and differences', () => {
  for (const [name, spec, make, dyads] of CASES) {
    it(`poses and moves ${name} to rounding`, () => {
      const inputs = grid(-0.5, 6.5, 15);
      const r = sweepWith(spec, inputs, { omega: 3, alpha: -7 }, dyads);
      expect([...r.ok].every((v) => v === 1)).toBe(true);
      // Poses to ~1e-15 of the size; rates carry one more factor of the Jacobian's condition (< 100 here).
      expect(check(r, inputs, make(spec), 3, -7)).toBeLessThan(1e-12);
    });
  }

  it('gives the slider its displacement, speed and acceleration (the inverted slider-crank)', () => {
    const spec = invertedSliderCrankSpec(2, 4, 8, 0.3);
    const inputs = grid(0, 6, 13);
    const r = sweepWith(spec, inputs, { omega: 2, alpha: 1 }, false);
    const a0 = at(spec, 'A');
    const o4 = dpt(0, -4);
    const s = (t: Dec) => dist(rotate(a0, dpt(0, 0), t), o4).minus(dist(a0, o4));
    inputs.forEach((ti, i) => {
      const t = exact(ti);
      const ds = s(t.plus(H1))
        .minus(s(t.minus(H1)))
        .div(H1.times(2));
      const dds = s(t.plus(H2))
        .minus(s(t).times(2))
        .plus(s(t.minus(H2)))
        .div(H2.pow(2));
      expect(Math.abs(r.sliders.S.s[i] - s(t).toNumber())).toBeLessThan(1e-13);
      expect(Math.abs(r.sliders.S.v![i] - ds.times(2).toNumber())).toBeLessThan(1e-12);
      expect(Math.abs(r.sliders.S.a![i] - dds.times(4).plus(ds).toNumber())).toBeLessThan(1e-11);
    });
  });
});
