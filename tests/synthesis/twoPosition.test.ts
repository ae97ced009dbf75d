/**
 * twoPositionRocker against the 40-digit oracle (twoPositionOracle.ts): the same designs (both dead centres on one
 * branch), the ground met to a few ulps as Q → 1, and any scale of the task.
 */
import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import { PI, designMetrics } from '../../src/solver';
import { twoPositionRocker } from '../../src/synthesis';
import type { TwoPositionRocker, TwoPositionRockerTask } from '../../src/synthesis';
import { seeded } from './motionFixtures';
import { oracleTwoPosition } from './twoPositionOracle';

const D = Decimal.clone({ precision: 40 });

/** Relative agreement with the oracle: the pivot is a circle intersection at a well-conditioned angle (the tasks
 *  keep clear of tangencies), so 1e-10 of the rocker leaves room for the conditioning and none for a wrong pivot. */
const REL = 1e-10;

function expectOracle(task: TwoPositionRockerTask, got: TwoPositionRocker[], ctx: string): void {
  const want = oracleTwoPosition(task);
  expect(got.length, `${ctx}: number of designs`).toBe(want.length);
  const scale = task.rocker;
  for (const w of want) {
    const match = got.find(
      (r) =>
        new D(r.design.O2.x)
          .minus(w.O2.x)
          .abs()
          .lt(REL * scale) &&
        new D(r.design.O2.y)
          .minus(w.O2.y)
          .abs()
          .lt(REL * scale),
    );
    expect(match, `${ctx}: pivot ${w.O2.x.toNumber()}, ${w.O2.y.toNumber()}`).toBeDefined();
    expect(new D(match!.design.links.r2).minus(w.r2).abs().toNumber(), `${ctx}: r2`).toBeLessThan(REL * scale);
    expect(new D(match!.design.links.r3).minus(w.r3).abs().toNumber(), `${ctx}: r3`).toBeLessThan(REL * scale);
  }
  for (const r of got) {
    // Each design's own stroke is the task's (the solver's designMetrics, exact to rounding).
    const m = designMetrics(r.design.links, r.design.branch);
    expect(Math.abs(m.output!.swing - Math.abs(task.swing)), `${ctx}: swing`).toBeLessThan(1e-9);
    expect(Math.abs(m.timeRatio! - (task.timeRatio ?? 1)), `${ctx}: Q`).toBeLessThan(1e-9);
  }
}

/** |O2 − O4| in ulps of the asked ground, measured in 40 digits. */
function groundUlps(task: TwoPositionRockerTask, r: TwoPositionRocker): number {
  const dx = new D(r.design.O2.x).minus(task.O4.x);
  const dy = new D(r.design.O2.y).minus(task.O4.y);
  const ulp = 2 ** (Math.floor(Math.log2(task.ground)) - 52);
  return D.sqrt(dx.pow(2).plus(dy.pow(2)))
    .minus(task.ground)
    .abs()
    .div(ulp)
    .toNumber();
}

describe('twoPositionRocker', () => {
  it('returns no design when the two dead centres of every pivot lie on opposite branches (issue 31, 1)', () => {
    const task = { O4: { x: 0, y: 0 }, rocker: 1, startAngle: 0.3, swing: 2.5, ground: 2.5, timeRatio: 1.5 };
    expect(oracleTwoPosition(task)).toEqual([]);
    expect(twoPositionRocker(task)).toEqual([]);
  });

  it('returns the oracle designs, and only designs of the task’s swing and time ratio, on random tasks', () => {
    // A small seeded sample; the campaign of issue 31 (20,000 tasks) found 44 % of results wrong before the fix.
    const rnd = seeded(31);
    for (let trial = 0; trial < 8; trial++) {
      const task = {
        O4: { x: 2 * rnd() - 1, y: 2 * rnd() - 1 },
        rocker: 0.5 + rnd(),
        startAngle: 2 * PI * rnd(),
        swing: (rnd() < 0.5 ? -1 : 1) * (0.1 + 2.9 * rnd()),
        ground: 0,
        timeRatio: 1 + rnd(),
      };
      task.ground = task.rocker * (0.5 + 3.5 * rnd());
      expectOracle(task, twoPositionRocker(task), `trial ${trial}`);
    }
  });

  it('meets the ground to a few ulps and finds every design as Q → 1 (issue 31, 2)', () => {
    const base = { O4: { x: 0.3, y: -0.2 }, rocker: 1.7, startAngle: 0.4, swing: 1.1, ground: 3.827 };
    for (const q1 of [0, 2 ** -52, 1e-12, 4.9e-9, 1e-6]) {
      const task = { ...base, timeRatio: 1 + q1 };
      const got = twoPositionRocker(task);
      expect(got.length, `Q − 1 = ${q1}`).toBe(q1 === 0 ? 2 : 4);
      expectOracle(task, got, `Q − 1 = ${q1}`);
      for (const r of got) {
        expect(groundUlps(task, r), `Q − 1 = ${q1}: |O2 − O4|`).toBeLessThan(4);
        expect(r.design.links.r1).toBe(task.ground);
      }
    }
  });

  it('gives the same designs, scaled, from 1e-200 to 1e200, and keeps the swing at a start angle of 1e16 (issue 31, 3)', () => {
    const unit = { O4: { x: 0.2, y: 0.1 }, rocker: 1, startAngle: 0.7, swing: -0.9, ground: 2.2, timeRatio: 1.3 };
    const ref = twoPositionRocker(unit);
    expect(ref.length).toBe(oracleTwoPosition(unit).length);
    expect(ref.length).toBeGreaterThan(0);
    for (const k of [1e-200, 1e-160, 1e160, 1e200]) {
      const task = { ...unit, O4: { x: unit.O4.x * k, y: unit.O4.y * k }, rocker: k, ground: unit.ground * k };
      const got = twoPositionRocker(task);
      expect(got.length, `scale ${k}`).toBe(ref.length);
      got.forEach((r, i) => {
        for (const key of ['r1', 'r2', 'r3', 'r4'] as const) {
          expect(Math.abs(r.design.links[key] / k - ref[i].design.links[key]), `scale ${k}: ${key}`).toBeLessThan(
            1e-14,
          );
        }
        expect(r.swing).toBeCloseTo(ref[i].swing, 14);
        expect(r.timeRatio).toBeCloseTo(ref[i].timeRatio, 14);
      });
    }
    const far = { ...unit, startAngle: 1e16 };
    const got = twoPositionRocker(far);
    expect(got.length).toBeGreaterThan(0);
    expectOracle(far, got, 'start angle 1e16');
  });
});
