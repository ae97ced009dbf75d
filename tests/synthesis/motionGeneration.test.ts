/**
 * Motion generation: three-position synthesis (both given-pivot forms) and the two-position rocker. Oracles by
 * construction: poses computed from a known linkage with the 60-digit oracle's angles (motionFixtures.ts) must give
 * that linkage back; defects are checked on hand-made defective linkages, each with a positive control.
 */
import { describe, expect, it } from 'vitest';
import type { Branch } from '../../src/solver';
import { PI, angleDiff, classify, designMetrics, inputRange } from '../../src/solver';
import type { PlacedFourBar, Pose } from '../../src/synthesis';
import { placedJoints, screenPoses, threePositionSynthesis, twoPositionRocker } from '../../src/synthesis';
import { dist, inFrame, oraclePose, randomCrankRocker, randomPlaced, seeded } from './motionFixtures';

/** Relative agreement expected of a rebuilt design: circumcentres of well-spread positions (poses ≥ 0.5 rad apart
 *  in θ2 on links of comparable size) lose a few digits to the triangle's shape; 1e-9 of the size is generous. */
const REL = 1e-9;

function expectSameDesign(got: PlacedFourBar, want: PlacedFourBar, ctx: string): void {
  const size = want.links.r1 + want.links.r2 + want.links.r3 + want.links.r4;
  for (const k of ['r1', 'r2', 'r3', 'r4'] as const) {
    expect(Math.abs(got.links[k] - want.links[k]), `${ctx}: ${k}`).toBeLessThan(REL * size);
  }
  expect(dist(got.O2, want.O2), `${ctx}: O2`).toBeLessThan(REL * size);
  expect(Math.abs(angleDiff(got.groundAngle, want.groundAngle)), `${ctx}: ground angle`).toBeLessThan(REL);
  expect(got.branch, `${ctx}: branch`).toBe(want.branch);
  expect(Math.abs(got.pDist - want.pDist), `${ctx}: pDist`).toBeLessThan(REL * size);
  expect(Math.abs(angleDiff(got.pAngle, want.pAngle)), `${ctx}: pAngle`).toBeLessThan(REL * (size / want.pDist));
}

/** Three poses of a design at θ2 values, from the oracle, with the pins of each. */
function posesOf(d: PlacedFourBar, t2: number[], branches: Branch[] = t2.map(() => d.branch)) {
  return t2.map((t, i) => oraclePose(d, t, branches[i]));
}

describe('threePositionSynthesis', () => {
  it('gives back the linkage whose three poses it is given, from its moving pivots', () => {
    const rnd = seeded(21);
    for (let trial = 0; trial < 30; trial++) {
      const d = randomPlaced(rnd, randomCrankRocker(rnd), trial % 2 ? 'open' : 'crossed');
      const start = 2 * PI * rnd() - PI;
      const t2 = [start, start + 0.8 + rnd(), start + 2.4 + rnd()];
      const at = posesOf(d, t2);
      const poses = at.map((a) => a.pose) as [Pose, Pose, Pose];
      const out = threePositionSynthesis(poses, { moving: [inFrame(poses[0], at[0].A), inFrame(poses[0], at[0].B)] });
      expectSameDesign(out.design, d, `trial ${trial}`);
      expect(out.defects).toEqual([]);
      out.theta2.forEach((t, i) => {
        expect(Math.abs(angleDiff(t, t2[i]))).toBeLessThan(REL);
        // The design's own coupler reaches the pose (solver's closed form, to 1e-9 of the size).
        const j = placedJoints(out.design, t)!;
        expect(dist(j.P, poses[i])).toBeLessThan(1e-9 * 10);
      });
    }
  });

  it('gives back the same linkage from its fixed pivots, by inversion', () => {
    const rnd = seeded(22);
    for (let trial = 0; trial < 30; trial++) {
      const d = randomPlaced(rnd, randomCrankRocker(rnd), trial % 2 ? 'open' : 'crossed');
      const start = 2 * PI * rnd() - PI;
      const t2 = [start, start + 0.8 + rnd(), start + 2.4 + rnd()];
      const at = posesOf(d, t2);
      const poses = at.map((a) => a.pose) as [Pose, Pose, Pose];
      const out = threePositionSynthesis(poses, { fixed: [d.O2, at[0].O4] });
      expectSameDesign(out.design, d, `trial ${trial}`);
      out.theta2.forEach((t, i) => expect(Math.abs(angleDiff(t, t2[i]))).toBeLessThan(REL));
    }
  });

  it('gives back the linkage scaled, from either pivots, at sizes from 1e-300 to 1e300 (issue 31, 3)', () => {
    // The oracle's poses of a unit design, scaled by k: the answer is that design scaled by k, with the same θ2 and
    // branch. Before the fix the circumcentres and cross products overflowed past 1e103 and underflowed below 1e-110.
    const rnd = seeded(24);
    for (let trial = 0; trial < 4; trial++) {
      const d = randomPlaced(rnd, randomCrankRocker(rnd), trial % 2 ? 'open' : 'crossed');
      const start = 2 * PI * rnd() - PI;
      const t2 = [start, start + 0.8 + rnd(), start + 2.4 + rnd()];
      const at = posesOf(d, t2);
      for (const k of [1e-300, 1e-105, 1e105, 1e300]) {
        const s = (p: { x: number; y: number }) => ({ x: p.x * k, y: p.y * k });
        const poses = at.map((a) => ({ ...s(a.pose), angle: a.pose.angle })) as [Pose, Pose, Pose];
        const want: PlacedFourBar = {
          ...d,
          links: { r1: d.links.r1 * k, r2: d.links.r2 * k, r3: d.links.r3 * k, r4: d.links.r4 * k },
          O2: s(d.O2),
          pDist: d.pDist * k,
        };
        const moving = threePositionSynthesis(poses, {
          moving: [s(inFrame(at[0].pose, at[0].A)), s(inFrame(at[0].pose, at[0].B))],
        });
        expectSameDesign(moving.design, want, `trial ${trial}, scale ${k}, moving`);
        const fixed = threePositionSynthesis(poses, { fixed: [s(d.O2), s(at[0].O4)] });
        expectSameDesign(fixed.design, want, `trial ${trial}, scale ${k}, fixed`);
        moving.theta2.forEach((t, i) => expect(Math.abs(angleDiff(t, t2[i]))).toBeLessThan(REL));
      }
    }
  });

  it("reports 'branch' when a pose needs the other branch", () => {
    const rnd = seeded(23);
    const d = randomPlaced(rnd, { r1: 4, r2: 1, r3: 3.5, r4: 3 }, 'open');
    const t2 = [0.2, 1.5, 3];
    const at = posesOf(d, t2, ['open', 'open', 'crossed']);
    const poses = at.map((a) => a.pose) as [Pose, Pose, Pose];
    const out = threePositionSynthesis(poses, { moving: [inFrame(poses[0], at[0].A), inFrame(poses[0], at[0].B)] });
    expect(out.defects).toEqual(['branch']);
    // Positive control: all three on the open branch.
    const same = posesOf(d, t2);
    const ok = threePositionSynthesis(same.map((a) => a.pose) as [Pose, Pose, Pose], {
      moving: [inFrame(same[0].pose, same[0].A), inFrame(same[0].pose, same[0].B)],
    });
    expect(ok.defects).toEqual([]);
  });

  it("reports 'order' and 'not-crank' when a rocking input meets the poses out of order", () => {
    // A triple rocker: the input rocks within [−t, t]; poses at −0.6t, +0.6t, 0 cannot be met in that order.
    const l = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
    const t = inputRange(l).intervals[0].hi;
    const d = randomPlaced(seeded(24), l, 'open');
    const build = (t2: number[]) => {
      const at = posesOf(d, t2);
      const poses = at.map((a) => a.pose) as [Pose, Pose, Pose];
      return threePositionSynthesis(poses, { moving: [inFrame(poses[0], at[0].A), inFrame(poses[0], at[0].B)] });
    };
    expect(build([-0.6 * t, 0.6 * t, 0]).defects).toEqual(['order', 'not-crank']);
    // Positive control: in order along the rocking range, only the information that the input is not a crank.
    expect(build([-0.6 * t, 0, 0.6 * t]).defects).toEqual(['not-crank']);
  });

  it('throws naming the pivot whose three positions are collinear', () => {
    // Pure translation along a line: every coupler point moves on a line, and so does the fixed pivot seen from the coupler.
    const poses: [Pose, Pose, Pose] = [
      { x: 0, y: 0, angle: 0.3 },
      { x: 1, y: 0, angle: 0.3 },
      { x: 3, y: 0, angle: 0.3 },
    ];
    expect(() =>
      threePositionSynthesis(poses, {
        moving: [
          { x: 0, y: 1 },
          { x: 1, y: 1 },
        ],
      }),
    ).toThrow(/no circle passes through the three positions of moving pivot A in the plane/);
    expect(() =>
      threePositionSynthesis(poses, {
        fixed: [
          { x: 0, y: 1 },
          { x: 2, y: 1 },
        ],
      }),
    ).toThrow(/no circle passes through the three positions of fixed pivot O2 in the coupler frame/);
  });

  it('throws for bad poses and pivots, naming them', () => {
    const poses: [Pose, Pose, Pose] = [
      { x: 0, y: 0, angle: 0 },
      { x: 1, y: 0.5, angle: 0.4 },
      { x: 2, y: 0.7, angle: 0.9 },
    ];
    const moving: [{ x: number; y: number }, { x: number; y: number }] = [
      { x: 0, y: -1 },
      { x: 1, y: -1 },
    ];
    expect(() => threePositionSynthesis(poses.slice(0, 2) as never, { moving })).toThrow(
      'poses must hold exactly 3 entries, got 2',
    );
    expect(() => threePositionSynthesis([poses[0], { x: 1, y: 0.5, angle: NaN }, poses[2]], { moving })).toThrow(
      'poses[1].angle must be a finite angle in radians, got NaN',
    );
    expect(() => threePositionSynthesis(poses, {} as never)).toThrow(
      /given must be \{ moving: \[A, B\] \} or \{ fixed/,
    );
    // Both kinds of pivot: refused rather than one silently used (issue 31, 10).
    expect(() => threePositionSynthesis(poses, { moving, fixed: moving } as never)).toThrow(
      'given must hold either moving or fixed pivots, not both',
    );
    expect(() =>
      threePositionSynthesis(poses, {
        fixed: [
          { x: 0, y: Infinity },
          { x: 1, y: 1 },
        ],
      }),
    ).toThrow('given.fixed[0].y must be a finite coordinate, got Infinity');
  });
});

describe('screenPoses', () => {
  it("reports 'order' when a crank needs more than one turn to meet the poses in order", () => {
    const d = randomPlaced(seeded(25), { r1: 4, r2: 1, r3: 3.5, r4: 3 }, 'open');
    const screen = (t2: number[]) => screenPoses(d, posesOf(d, t2));
    // 0 → 2 → 4 → 1 turning either way sweeps more than a full turn.
    expect(screen([0, 2, 4, 1]).defects).toEqual(['order']);
    expect(screen([0, 1, 2, 4]).defects).toEqual([]);
    expect(screen([4, 2, 1, 0]).defects).toEqual([]);
    screen([0, 1, 2, 4]).theta2.forEach((t, i) => expect(Math.abs(angleDiff(t, [0, 1, 2, 4][i]))).toBeLessThan(1e-12));
  });
});

describe('twoPositionRocker', () => {
  const job = { O4: { x: 1, y: 2 }, rocker: 2, startAngle: 1.2, swing: 0.8, ground: 3 };

  it('swings the rocker between the two given positions with the chosen time ratio (designMetrics)', () => {
    for (const timeRatio of [1, 1.15, 1.3, 1.5]) {
      for (const swing of [0.8, -0.8]) {
        const out = twoPositionRocker({ ...job, swing, timeRatio });
        expect(out.length, `Q ${timeRatio} swing ${swing}`).toBeGreaterThan(0);
        for (const r of out) {
          expect(classify(r.design.links).type).toBe('crank-rocker');
          const m = designMetrics(r.design.links, r.design.branch);
          // designMetrics is exact to rounding; the construction loses a few digits in the circle intersections.
          expect(Math.abs(m.output!.swing - Math.abs(swing))).toBeLessThan(1e-12);
          expect(Math.abs(m.timeRatio! - timeRatio)).toBeLessThan(1e-12);
          // Reported from the design in the rocker's frame (rocker 1): the same to rounding.
          expect(r.swing).toBeCloseTo(m.output!.swing, 13);
          expect(r.timeRatio).toBeCloseTo(m.timeRatio!, 13);
          // The dead centres put the rocker pin on the two given positions.
          const want = [job.startAngle, job.startAngle + swing].map((a) => ({
            x: job.O4.x + job.rocker * Math.cos(a),
            y: job.O4.y + job.rocker * Math.sin(a),
          }));
          r.theta2.forEach((t, i) => expect(dist(placedJoints(r.design, t)!.B, want[i])).toBeLessThan(1e-12 * 10));
          const ends = [m.output!.extended.theta2, m.output!.folded.theta2];
          for (const t of r.theta2) expect(Math.min(...ends.map((e) => Math.abs(angleDiff(e, t))))).toBeLessThan(1e-9);
          expect(r.design.links.r1).toBeCloseTo(job.ground, 12);
          expect(r.design.links.r4).toBeCloseTo(job.rocker, 12);
        }
      }
    }
  });

  it('orders the candidates by transmission-angle margin, best first', () => {
    const out = twoPositionRocker({ ...job, timeRatio: 1.2, ground: 3.5 });
    const margin = out.map((r) => Math.min(r.transmission.min, PI - r.transmission.max));
    for (let i = 1; i < margin.length; i++) expect(margin[i]).toBeLessThanOrEqual(margin[i - 1]);
  });

  it('returns no design when no crank pivot at that ground length works', () => {
    // Q = 1 puts O2 on the line B1B2 outside the segment, which is farther from O4 than the rocker.
    expect(twoPositionRocker({ ...job, ground: 1.9 })).toEqual([]);
  });

  it('throws for a bad job, naming the field and the value', () => {
    expect(() => twoPositionRocker({ ...job, swing: PI })).toThrow(/swing must be a turn between 0 and π/);
    expect(() => twoPositionRocker({ ...job, swing: 0 })).toThrow('got 0');
    expect(() => twoPositionRocker({ ...job, timeRatio: 0.9 })).toThrow(
      'timeRatio must be a finite number ≥ 1, got 0.9',
    );
    expect(() => twoPositionRocker({ ...job, rocker: -1 })).toThrow('rocker must be a positive finite length, got -1');
    expect(() => twoPositionRocker({ ...job, ground: 0 })).toThrow('ground must be a positive finite length, got 0');
    expect(() => twoPositionRocker({ ...job, O4: { x: 1 } as never })).toThrow('O4.y must be a finite coordinate');
  });
});
