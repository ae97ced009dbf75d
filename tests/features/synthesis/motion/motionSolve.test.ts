import { describe, expect, it } from 'vitest';
import type { SynMotionState } from '../../../../src/shared/state/slices/synMotionSlice';
import {
  DEFAULT_POSES_FIVE,
  DEFAULT_POSES_TURN,
  DEFAULT_SYN_MOTION,
} from '../../../../src/shared/state/slices/synMotionSlice';
import { nextPose } from '../../../../src/features/synthesis/motion/motionEdits';
import { motionMessages } from '../../../../src/features/synthesis/motion/motionMessages';
import { problemText } from '../../../../src/features/synthesis/motion/motionText';
import { nearestDyad, rotationPole, solveMotion, toPose } from '../../../../src/features/synthesis/motion/motionSolve';
import { placedJoints, threePositionSynthesis } from '../../../../src/synthesis';
import { KNOWN, inPlane, knownPose } from './knownLinkage';

const deg = (d: number) => (d * Math.PI) / 180;
const motion = (patch: Partial<SynMotionState>): SynMotionState => ({ ...DEFAULT_SYN_MOTION, ...patch });
const dist = (p: { x: number; y: number }, q: { x: number; y: number }) => Math.hypot(p.x - q.x, p.y - q.y);
/** Pivots found from exact poses: the construction is a few circumcentres, so rounding stays near 1e-15 of the size. */
const TIGHT = 1e-9;

describe('solveMotion with three poses', () => {
  const poses = [30, 100, 170].map((t) => knownPose(deg(t)));

  it('finds the known fixed pivots from the moving pivots, as the circles’ centres', () => {
    const o = solveMotion(motion({ poses, pivotChoice: 'moving', pivots: [KNOWN.a, KNOWN.b] }));
    if (o.count !== 3 || !o.chosen) throw new Error('no design');
    expect(dist(o.construction[0].centre, KNOWN.O2)).toBeLessThan(TIGHT);
    expect(dist(o.construction[1].centre, KNOWN.O4)).toBeLessThan(TIGHT);
    expect(dist(o.chosen.design.O2, KNOWN.O2)).toBeLessThan(TIGHT);
    expect(o.chosen.design.links.r2).toBeCloseTo(KNOWN.r2, 12);
    expect(o.chosen.design.links.r4).toBeCloseTo(KNOWN.r4, 12);
    // A crank-rocker passing its poses in order on its own branch: no defect, and a crank-rocker by type.
    expect(o.chosen.defects).toEqual([]);
    expect(o.chosen.type).toBe('crank-rocker');
    // Every construction point lies on its circle.
    for (const c of o.construction) {
      const r = dist(c.points[0], c.centre);
      for (const p of c.points) expect(Math.abs(dist(p, c.centre) - r)).toBeLessThan(TIGHT);
    }
  });

  it('finds the known moving pivots from the fixed pivots, by inversion', () => {
    const o = solveMotion(motion({ poses, pivotChoice: 'fixed', pivots: [KNOWN.O2, KNOWN.O4] }));
    if (o.count !== 3 || !o.chosen) throw new Error('no design');
    expect(dist(o.construction[0].centre, inPlane(poses[0], KNOWN.a))).toBeLessThan(TIGHT);
    expect(dist(o.construction[1].centre, inPlane(poses[0], KNOWN.b))).toBeLessThan(TIGHT);
    // The design puts its coupler point at each pose.
    o.chosen.theta2.forEach((t, i) => {
      const j = placedJoints(o.chosen!.design, t)!;
      expect(dist(j.P, poses[i])).toBeLessThan(TIGHT);
    });
  });

  it('shows the synthesis module’s own design (threePositionSynthesis), for either choice of pivots', () => {
    const three = [toPose(poses[0]), toPose(poses[1]), toPose(poses[2])] as const;
    for (const [pivotChoice, pivots] of [
      ['moving', [KNOWN.a, KNOWN.b]],
      ['fixed', [KNOWN.O2, KNOWN.O4]],
    ] as const) {
      const o = solveMotion(motion({ poses, pivotChoice, pivots: [pivots[0], pivots[1]] }));
      if (o.count !== 3 || !o.chosen) throw new Error(`no design from the ${pivotChoice} pivots`);
      const given = pivotChoice === 'moving' ? { moving: [pivots[0], pivots[1]] } : { fixed: [pivots[0], pivots[1]] };
      const d = threePositionSynthesis(
        [three[0], three[1], three[2]],
        given as Parameters<typeof threePositionSynthesis>[1],
      );
      expect(o.chosen.design).toEqual(d.design);
      expect(o.chosen.theta2).toEqual(d.theta2);
      expect(o.chosen.defects).toEqual(d.defects);
    }
  });

  it('says the input cannot turn fully when the rocker’s dyad drives (the Grashof check)', () => {
    const o = solveMotion(motion({ poses, pivots: [KNOWN.b, KNOWN.a] }));
    expect(o.chosen?.defects).toContain('not-crank');
    // Still Grashof (the same lengths), but the shortest link is now the output: the input rocks.
    expect(o.chosen?.design.links.r4).toBeCloseTo(KNOWN.r2, 12);
  });

  it('says which pivot has no circle when its three positions are collinear', () => {
    const translate = [0, 1, 2].map((k) => ({ x: k, y: 0, angleDeg: 0 }));
    const o = solveMotion(
      motion({
        poses: translate,
        pivots: [
          { x: 0, y: 1 },
          { x: 1, y: 1 },
        ],
      }),
    );
    expect(o.problem).toEqual({ code: 'collinear', pivot: 'A' });
    expect(o.chosen).toBeNull();
    const fixed = solveMotion(
      motion({
        poses: translate,
        pivotChoice: 'fixed',
        pivots: [
          { x: 0, y: 1 },
          { x: 1, y: 1 },
        ],
      }),
    );
    expect(fixed.problem).toEqual({ code: 'collinear', pivot: 'O2' });
  });

  it('says so when two pivots coincide', () => {
    const o = solveMotion(motion({ poses, pivots: [KNOWN.a, KNOWN.a] }));
    expect(o.problem).toEqual({ code: 'coincident' });
  });
});

describe('solveMotion with two poses', () => {
  it('turns the body about the poses’ pole: O4 is the pole and the crank-rockers swing between the poses', () => {
    const C = { x: 2, y: -1 };
    const P1 = { x: 4, y: 0.5 };
    const turn = deg(40);
    const P2 = {
      x: C.x + Math.cos(turn) * (P1.x - C.x) - Math.sin(turn) * (P1.y - C.y),
      y: C.y + Math.sin(turn) * (P1.x - C.x) + Math.cos(turn) * (P1.y - C.y),
    };
    const poses = [
      { ...P1, angleDeg: 10 },
      { ...P2, angleDeg: 50 },
    ];
    const o = solveMotion(motion({ poses }));
    if (o.count !== 2 || !o.chosen || !o.pole) throw new Error('no design');
    expect(dist(o.pole, C)).toBeLessThan(1e-12);
    expect(o.rocker).toBeCloseTo(dist(P1, C), 12);
    expect(o.ground).toBeCloseTo(2 * o.rocker, 12);
    const { design } = o.chosen;
    const O4 = {
      x: design.O2.x + design.links.r1 * Math.cos(design.groundAngle),
      y: design.O2.y + design.links.r1 * Math.sin(design.groundAngle),
    };
    expect(dist(O4, C)).toBeLessThan(1e-9);
    o.chosen.theta2.forEach((t, i) => expect(dist(placedJoints(design, t)!.P, poses[i])).toBeLessThan(1e-9));
    expect(o.chosen.type).toBe('crank-rocker');
  });

  it('asks for a turn, less than half a turn, and a ground long enough', () => {
    const same = solveMotion(
      motion({
        poses: [
          { x: 0, y: 0, angleDeg: 5 },
          { x: 1, y: 0, angleDeg: 5 },
        ],
      }),
    );
    expect(same.problem).toEqual({ code: 'noRotation' });
    const half = solveMotion(
      motion({
        poses: [
          { x: 0, y: 0, angleDeg: 0 },
          { x: 1, y: 0, angleDeg: 180 },
        ],
      }),
    );
    expect(half.problem).toEqual({ code: 'halfTurn' });
    const short = solveMotion(
      motion({
        poses: [
          { x: 1, y: 0, angleDeg: 0 },
          { x: 0, y: 1, angleDeg: 90 },
        ],
        groundLength: 0.5,
      }),
    );
    expect(short.problem).toMatchObject({ code: 'noCrankPivot', ground: 0.5 });
  });

  it('finds the pole by the complex formula on a pure rotation', () => {
    const r = rotationPole({ x: 1, y: 0, angle: 0 }, { x: 0, y: 1, angle: deg(90) });
    expect(r!.pole.x).toBeCloseTo(0, 15);
    expect(r!.pole.y).toBeCloseTo(0, 15);
    expect(rotationPole({ x: 1, y: 0, angle: 0 }, { x: 3, y: 0, angle: 0 })).toBeNull();
  });
});

describe('solveMotion with four poses', () => {
  const poses = [20, 80, 140, 230].map((t) => knownPose(deg(t)));

  it('draws the centre-point curve through the known fixed pivots, its circle points through the moving ones', () => {
    const o = solveMotion(motion({ poses }));
    if (o.count !== 4) throw new Error('not four');
    const samples = o.curves.flat();
    // Within the sampling: the known dyads are on the curves.
    const near = (p: { x: number; y: number }) => Math.min(...samples.map((d) => dist(d.center, p)));
    expect(near(KNOWN.O2)).toBeLessThan(0.05);
    expect(near(KNOWN.O4)).toBeLessThan(0.05);
    expect(o.problem).toEqual({ code: 'pickTwo', picked: 0 });
  });

  it('makes a linkage of two picked dyads that reaches all four poses', () => {
    const o = solveMotion(motion({ poses, dyadPicks: [KNOWN.O2, KNOWN.O4] }));
    if (o.count !== 4 || !o.chosen) throw new Error('no design');
    expect(dist(o.chosen.design.O2, KNOWN.O2)).toBeLessThan(0.05);
    // The sampled dyads are exact Burmester dyads: the coupler point meets every pose to rounding.
    o.chosen.theta2.forEach((t, i) => expect(dist(placedJoints(o.chosen!.design, t)!.P, poses[i])).toBeLessThan(1e-9));
    const one = solveMotion(motion({ poses, dyadPicks: [KNOWN.O2] }));
    expect(one.problem).toEqual({ code: 'pickTwo', picked: 1 });
  });

  it('picks the sample nearest the click', () => {
    const curves = [
      [
        { center: { x: 0, y: 0 }, circle: { x: 1, y: 1 } },
        { center: { x: 5, y: 0 }, circle: { x: 2, y: 2 } },
      ],
    ];
    expect(nearestDyad(curves, { x: 4, y: 1 })?.circle).toEqual({ x: 2, y: 2 });
    expect(nearestDyad([], { x: 0, y: 0 })).toBeNull();
  });
});

describe('solveMotion with five poses', () => {
  it('marks the Burmester points, the known linkage’s dyads among them, and lists their four-bars', () => {
    const poses = [20, 75, 130, 200, 270].map((t) => knownPose(deg(t)));
    const o = solveMotion(motion({ poses }));
    if (o.count !== 5) throw new Error('not five');
    expect(o.points.length === 2 || o.points.length === 4).toBe(true);
    for (const pivot of [KNOWN.O2, KNOWN.O4])
      expect(Math.min(...o.points.map((p) => dist(p.center, pivot)))).toBeLessThan(1e-7);
    const known = o.fourBars.find((b) => dist(b.design.O2, KNOWN.O2) < 1e-7 || dist(b.design.O2, KNOWN.O4) < 1e-7);
    expect(known).toBeDefined();
    expect(o.fourBars).toHaveLength((o.points.length * (o.points.length - 1)) / 2);
    expect(o.chosen).toBe(o.fourBars[0]);
    // Fewest defects first, then the smallest: the known crank-rocker (no defect, pivots near the poses) leads.
    const key = (b: (typeof o.fourBars)[number]) => [
      b.defects.length,
      b.design.links.r1 + b.design.links.r2 + b.design.links.r3 + b.design.links.r4,
    ];
    for (let i = 1; i < o.fourBars.length; i++) {
      const [d0, s0] = key(o.fourBars[i - 1]);
      const [d1, s1] = key(o.fourBars[i]);
      expect(d0 < d1 || (d0 === d1 && s0 <= s1)).toBe(true);
    }
    expect(dist(o.fourBars[0].design.O2, KNOWN.O2) < 1e-7 || dist(o.fourBars[0].design.O2, KNOWN.O4) < 1e-7).toBe(true);
  });

  it('says the poses are degenerate when they do not turn', () => {
    const poses = [0, 1, 2, 3, 4].map((k) => ({ x: k, y: k * k, angleDeg: 0 }));
    expect(solveMotion(motion({ poses })).problem).toEqual({ code: 'degenerate' });
  });
});

describe('solveMotion with six to twenty poses (issue 34, item 9)', () => {
  it('fits 8 poses of the known linkage by least squares: its pivots first, zero error at every pose', () => {
    const poses = [10, 50, 90, 130, 170, 210, 250, 290].map((t) => knownPose(deg(t)));
    const o = solveMotion(motion({ poses }));
    if (o.count !== 6) throw new Error('not least squares');
    expect(o.problem).toBeNull();
    const chosen = o.chosen!;
    expect(chosen.defects).toEqual([]);
    expect(dist(chosen.design.O2, KNOWN.O2)).toBeLessThan(1e-7);
    expect(chosen.errors).toHaveLength(8);
    for (const e of chosen.errors!) expect(e.position).toBeLessThan(1e-9);
    // Another choice is another four-bar of the dyads, with a larger rms error.
    const other = solveMotion(motion({ poses, choice: 1 }));
    if (other.count !== 6 || !other.chosen) throw new Error('no second four-bar');
    expect(other.chosen.rms!).toBeGreaterThan(chosen.rms!);
  });

  it('gives each pose an error when the poses are not on one linkage', () => {
    const poses = [10, 50, 90, 130, 170, 210].map((t, i) => {
      const p = knownPose(deg(t));
      return { ...p, x: p.x + (i % 2 ? 0.03 : -0.03) };
    });
    const o = solveMotion(motion({ poses }));
    if (o.count !== 6 || !o.chosen) throw new Error('no design');
    const worst = Math.max(...o.chosen.errors!.map((e) => e.position));
    expect(worst).toBeGreaterThan(1e-3);
    expect(worst).toBeLessThan(0.2);
  });
});

describe('Add pose past the default five (issue 34, item 9)', () => {
  /**
   * The default crank-rocker's coupler pose at θ2 (degrees), computed here by circle intersection, independently of
   * src/synthesis: r1..r4 = 10, 3, 9, 7, O2 = (−5, −6), ground along +x, P at 5 from A at 34° from AB, open branch.
   */
  function crankRockerPose(theta2Deg: number) {
    const t = deg(theta2Deg);
    const O2 = { x: -5, y: -6 };
    const O4 = { x: 5, y: -6 };
    const A = { x: O2.x + 3 * Math.cos(t), y: O2.y + 3 * Math.sin(t) };
    const d = dist(A, O4);
    const along = (d * d + 81 - 49) / (2 * d);
    const h = Math.sqrt(81 - along * along);
    const u = { x: (O4.x - A.x) / d, y: (O4.y - A.y) / d };
    const B = { x: A.x + along * u.x - h * u.y, y: A.y + along * u.y + h * u.x };
    const th3 = Math.atan2(B.y - A.y, B.x - A.x);
    return {
      x: A.x + 5 * Math.cos(th3 + deg(34)),
      y: A.y + 5 * Math.sin(th3 + deg(34)),
      angleDeg: (th3 * 180) / Math.PI,
    };
  }

  it('appends the default crank-rocker’s own poses, θ2 = 240° to 360°, rounded to 0.1 and 1°', () => {
    // Half a rounding step, and a little more: the first pose's x, −0.84997, was rounded to −0.9.
    DEFAULT_POSES_TURN.forEach((p, i) => {
      const q = crankRockerPose(40 * (i + 1));
      expect(Math.abs(p.x - q.x), `x${i}`).toBeLessThanOrEqual(0.06);
      expect(Math.abs(p.y - q.y), `y${i}`).toBeLessThanOrEqual(0.06);
      expect(Math.abs(p.angleDeg - q.angleDeg), `angle${i}`).toBeLessThanOrEqual(0.6);
    });
  });

  it('offers a defect-free four-bar near the crank-rocker for six to nine poses grown by Add pose', () => {
    let poses = [...DEFAULT_POSES_FIVE];
    for (let n = 6; n <= 9; n++) {
      poses = [...poses, nextPose(poses)!];
      const o = solveMotion(motion({ poses }));
      if (o.count !== 6) throw new Error('not least squares');
      expect(o.problem, `${n} poses`).toBeNull();
      const chosen = o.chosen!;
      expect(chosen.defects, `${n} poses`).toEqual([]);
      // The poses are rounded to 0.1: the fit lands within a few tenths of the crank-rocker, its error below 0.05.
      expect(dist(chosen.design.O2, { x: -5, y: -6 }), `${n} poses`).toBeLessThan(0.5);
      expect(chosen.design.links.r2, `${n} poses`).toBeCloseTo(3, 0);
      expect(chosen.rms!, `${n} poses`).toBeLessThan(0.05);
    }
  });

  it('says the fit found a single dyad, not that pivots coincide, when a pose strays from the motion', () => {
    const poses = [...DEFAULT_POSES_FIVE, { x: -6.8, y: -4, angleDeg: 45 }];
    const o = solveMotion(motion({ poses }));
    expect(o.chosen).toBeNull();
    expect(o.problem).toEqual({ code: 'fewDyads', found: 1 });
    const text = problemText(motionMessages.get('en'), o.problem!);
    expect(text).toContain('only one dyad');
    expect(text).not.toMatch(/coincide/);
  });
});

describe('toPose', () => {
  it('turns degrees into the synthesis module’s radians', () => {
    expect(toPose({ x: 1, y: 2, angleDeg: 90 })).toEqual({ x: 1, y: 2, angle: Math.PI / 2 });
  });
});
