/**
 * Burmester theory: the centre-point curve of four poses, the Burmester pairs of five, and the four-bars they make.
 * Oracles: poses computed from a known linkage with the 60-digit oracle's angles (its two dyads must be among the
 * pairs, and one four-bar must be that linkage); an independent multistart Newton on the circle conditions (every
 * real pair it finds must be found); and the defining property, a circle point on its circle in every pose.
 */
import { describe, expect, it } from 'vitest';
import type { Point } from '../../src/solver';
import { PI, angleDiff } from '../../src/solver';
import type { BurmesterPair, PlacedFourBar, Pose } from '../../src/synthesis';
import { CURVE_FAR, burmesterCurves, burmesterFourBars, burmesterPoints, placedJoints } from '../../src/synthesis';
import { dist, inFrame, oraclePose, randomCrankRocker, randomPlaced, seeded } from './motionFixtures';

/** The bar: a circle point stays on its circle in every pose to 1e-9 of the scale. */
const ON_CIRCLE = 1e-9;

/** A coupler-frame point in the plane at a pose (written out here, independent of src/synthesis/poseFrame.ts). */
function onPlane(pose: Pose, q: Point): Point {
  const c = Math.cos(pose.angle);
  const s = Math.sin(pose.angle);
  return { x: pose.x + c * q.x - s * q.y, y: pose.y + s * q.x + c * q.y };
}

/** Largest minus smallest distance of the circle point from its centre over the poses. */
function radiusSpread(poses: readonly Pose[], p: BurmesterPair): number {
  const r = poses.map((q) => dist(onPlane(q, p.circle), p.center));
  return Math.max(...r) - Math.min(...r);
}

/** The size of a pose set: the largest distance of a pose point from the first. */
function scaleOf(poses: readonly Pose[]): number {
  return Math.max(...poses.map((p) => dist(p, poses[0])));
}

/** Five poses of a random crank-rocker at increasing θ2 within one turn, its two dyads and the θ2's. */
function linkagePoses(rnd: () => number) {
  const d = randomPlaced(rnd, randomCrankRocker(rnd), rnd() < 0.5 ? 'open' : 'crossed');
  const start = 2 * PI * rnd() - PI;
  const t2 = [0, 1, 2, 3, 4].map((k) => start + k * 1.1 + 0.3 * rnd());
  const at = t2.map((t) => oraclePose(d, t));
  const poses = at.map((a) => a.pose);
  const crank = { center: d.O2, circle: inFrame(poses[0], at[0].A) };
  const rocker = { center: at[0].O4, circle: inFrame(poses[0], at[0].B) };
  return { d, t2, poses, crank, rocker };
}

/** Random poses: points in the unit square, angles anywhere. */
function randomPoses(rnd: () => number, n: number): Pose[] {
  return Array.from({ length: n }, () => ({ x: 2 * rnd() - 1, y: 2 * rnd() - 1, angle: 2 * PI * rnd() - PI }));
}

/**
 * The oracle: Newton on F_j(m, c) = |Pj + Rj c − m|² − |P1 + R1 c − m|², j = 2..5, from many random starts (own
 * Gaussian elimination), keeping the distinct converged roots within 100 pose scales.
 */
function multistartOracle(poses: readonly Pose[], starts: number, rnd: () => number): number[][] {
  const scale = scaleOf(poses);
  const roots: number[][] = [];
  for (let s = 0; s < starts; s++) {
    let x = [0, 0, 0, 0].map(() => poses[0].x * 0 + (rnd() * 8 - 4) * scale);
    x = [x[0] + poses[0].x, x[1] + poses[0].y, x[2], x[3]];
    for (let it = 0; it < 60; it++) {
      const u = poses.map((q) => {
        const c = Math.cos(q.angle);
        const si = Math.sin(q.angle);
        return { ux: q.x + c * x[2] - si * x[3] - x[0], uy: q.y + si * x[2] + c * x[3] - x[1], c, s: si };
      });
      const M = u
        .slice(1)
        .map((v) => [
          -2 * v.ux + 2 * u[0].ux,
          -2 * v.uy + 2 * u[0].uy,
          2 * (v.c * v.ux + v.s * v.uy) - 2 * (u[0].c * u[0].ux + u[0].s * u[0].uy),
          2 * (-v.s * v.ux + v.c * v.uy) - 2 * (-u[0].s * u[0].ux + u[0].c * u[0].uy),
          v.ux ** 2 + v.uy ** 2 - u[0].ux ** 2 - u[0].uy ** 2,
        ]);
      for (let k = 0; k < 4; k++) {
        let p = k;
        for (let i = k + 1; i < 4; i++) if (Math.abs(M[i][k]) > Math.abs(M[p][k])) p = i;
        [M[k], M[p]] = [M[p], M[k]];
        for (let i = k + 1; i < 4; i++) {
          const f = M[i][k] / M[k][k];
          for (let j = k; j < 5; j++) M[i][j] -= f * M[k][j];
        }
      }
      const step = [0, 0, 0, 0];
      for (let k = 3; k >= 0; k--) {
        let v = M[k][4];
        for (let j = k + 1; j < 4; j++) v -= M[k][j] * step[j];
        step[k] = v / M[k][k];
      }
      x = x.map((v, i) => v - step[i]);
      if (!x.every(Number.isFinite)) break;
    }
    const pair = { center: { x: x[0], y: x[1] }, circle: { x: x[2], y: x[3] } };
    if (!x.every(Number.isFinite) || Math.hypot(x[2], x[3]) > 100 * scale) continue;
    if (dist(pair.center, poses[0]) > 100 * scale || radiusSpread(poses, pair) > 1e-10 * scale) continue;
    if (!roots.some((r) => Math.hypot(r[0] - x[0], r[1] - x[1], r[2] - x[2], r[3] - x[3]) < 1e-6 * scale))
      roots.push(x);
  }
  return roots;
}

/** Whether a pair with this centre and circle point is among the pairs (to tol). */
function has(pairs: readonly BurmesterPair[], want: BurmesterPair, tol: number): boolean {
  return pairs.some((p) => dist(p.center, want.center) < tol && dist(p.circle, want.circle) < tol);
}

describe('burmesterPoints', () => {
  it('finds both dyads of the linkage that generated five poses', () => {
    const rnd = seeded(31);
    for (let trial = 0; trial < 25; trial++) {
      const { poses, crank, rocker } = linkagePoses(rnd);
      const pairs = burmesterPoints(poses);
      // Polished by Newton to rounding; the dyads are recovered to the conditioning of the five-pose problem.
      const tol = 1e-8 * scaleOf(poses);
      expect(has(pairs, crank, tol), `trial ${trial}: crank dyad`).toBe(true);
      expect(has(pairs, rocker, tol), `trial ${trial}: rocker dyad`).toBe(true);
    }
  });

  it('keeps every circle point on its circle through the five poses to 1e-9 of the scale', () => {
    const rnd = seeded(32);
    let checked = 0;
    for (let trial = 0; trial < 150; trial++) {
      const poses = trial % 3 === 0 ? linkagePoses(rnd).poses : randomPoses(rnd, 5);
      for (const p of burmesterPoints(poses)) {
        const scale = Math.max(scaleOf(poses), dist(p.center, poses[0]), Math.hypot(p.circle.x, p.circle.y));
        expect(radiusSpread(poses, p), `trial ${trial}`).toBeLessThan(ON_CIRCLE * scale);
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(200);
  });

  it('finds every real pair an independent multistart Newton finds: 0, 2 or 4 of them', () => {
    const rnd = seeded(33);
    const counts = new Set<number>();
    for (let trial = 0; trial < 30; trial++) {
      const poses = trial % 2 ? linkagePoses(rnd).poses : randomPoses(rnd, 5);
      const pairs = burmesterPoints(poses);
      expect([0, 2, 4], `trial ${trial}: ${pairs.length} pairs`).toContain(pairs.length);
      counts.add(pairs.length);
      const scale = scaleOf(poses);
      for (const r of multistartOracle(poses, 300, seeded(1000 + trial))) {
        const want = { center: { x: r[0], y: r[1] }, circle: { x: r[2], y: r[3] } };
        expect(has(pairs, want, 1e-7 * scale), `trial ${trial}: oracle pair ${r.map((v) => v.toFixed(4))}`).toBe(true);
      }
    }
    expect(counts.has(4) && counts.has(2)).toBe(true);
  });

  it('gives the same pairs whatever the order of the poses', () => {
    const rnd = seeded(34);
    for (let trial = 0; trial < 10; trial++) {
      const poses = randomPoses(rnd, 5);
      const a = burmesterPoints(poses);
      const b = burmesterPoints([poses[3], poses[1], poses[4], poses[0], poses[2]]);
      expect(b.length).toBe(a.length);
      for (const p of a) expect(has(b, p, 1e-8 * scaleOf(poses))).toBe(true);
    }
  });

  it('throws for bad or degenerate poses, naming them', () => {
    const poses = randomPoses(seeded(35), 5);
    expect(() => burmesterPoints(poses.slice(0, 4))).toThrow('poses must hold exactly 5 entries, got 4');
    expect(() => burmesterPoints([...poses.slice(0, 4), { x: 0, y: NaN, angle: 0 }])).toThrow(
      'poses[4].y must be a finite coordinate, got NaN',
    );
    const still = poses.map((p) => ({ ...p, x: 1, y: 2 }));
    expect(() => burmesterPoints(still)).toThrow(/poses must not all share one point/);
    const sliding = poses.map((p) => ({ ...p, angle: 0.5 }));
    expect(() => burmesterPoints(sliding)).toThrow(/poses are degenerate for Burmester theory/);
  });

  it('throws for a repeated pose: four poses and a family of dyads, not five (issue 31, 9)', () => {
    const poses = randomPoses(seeded(36), 5);
    for (const [i, j] of [
      [0, 4],
      [1, 3],
    ]) {
      const repeated = poses.slice();
      // The same pose, its angle a turn on: the coupler is in the same place.
      repeated[j] = { ...poses[i], angle: poses[i].angle + 2 * PI };
      expect(() => burmesterPoints(repeated)).toThrow(
        `poses[${i}] and poses[${j}] are the same pose: five poses with a repeat are four, whose dyads are a one-parameter family (burmesterCurves)`,
      );
    }
  });
});

describe('burmesterCurves', () => {
  it('samples centres whose circle point keeps one distance through the four poses', () => {
    const rnd = seeded(41);
    for (let trial = 0; trial < 20; trial++) {
      const poses = (trial % 2 ? linkagePoses(rnd).poses : randomPoses(rnd, 5)).slice(0, 4);
      const curves = burmesterCurves(poses, { samples: 120 });
      expect(curves.length).toBeGreaterThan(0);
      for (const curve of curves) {
        for (const p of curve) {
          const scale = Math.max(scaleOf(poses), dist(p.center, poses[0]), Math.hypot(p.circle.x, p.circle.y));
          expect(radiusSpread(poses, p), `trial ${trial}`).toBeLessThan(ON_CIRCLE * scale);
          expect(dist(p.center, poses[0])).toBeLessThanOrEqual(CURVE_FAR * scaleOf(poses) * (1 + 1e-12));
        }
      }
    }
  });

  it('passes through the fixed pivots of the linkage that generated the poses', () => {
    const rnd = seeded(42);
    for (let trial = 0; trial < 10; trial++) {
      const { poses, crank, rocker } = linkagePoses(rnd);
      const curves = burmesterCurves(poses.slice(0, 4), { samples: 4000 });
      const nearest = (q: Point) => {
        let best = Infinity;
        for (const c of curves) {
          for (let i = 0; i + 1 < c.length; i++) {
            const a = c[i].center;
            const b = c[i + 1].center;
            const L2 = (b.x - a.x) ** 2 + (b.y - a.y) ** 2;
            const t =
              L2 > 0 ? Math.max(0, Math.min(1, ((q.x - a.x) * (b.x - a.x) + (q.y - a.y) * (b.y - a.y)) / L2)) : 0;
            best = Math.min(best, dist(q, { x: a.x + t * (b.x - a.x), y: a.y + t * (b.y - a.y) }));
          }
        }
        return best;
      };
      // Chords of a curve sampled this finely stay within ~1e-4 of the scale of it where it is not near infinity.
      expect(nearest(crank.center), `trial ${trial}: O2`).toBeLessThan(1e-3 * scaleOf(poses));
      expect(nearest(rocker.center), `trial ${trial}: O4`).toBeLessThan(1e-3 * scaleOf(poses));
    }
  });

  it('splits a branch where its centre goes to infinity, at any sampling (issue 31, 8)', () => {
    // The poses: at the default sampling a chord of about 340 joined the two far ends of the asymptote.
    // A curve crossing infinity between two samples puts them far out on opposite sides of the first pose; a
    // correct polyline never does (two far neighbours lie on the same side, along the same asymptote end).
    const poses: Pose[] = [
      { x: 0, y: 0, angle: 0 },
      { x: 1, y: 0.2, angle: 0.3 },
      { x: 1.8, y: 0.9, angle: 0.7 },
      { x: 2.2, y: 1.8, angle: 1.2 },
    ];
    for (const samples of [8, 50, 200, 201, 600, 1000]) {
      for (const curve of burmesterCurves(poses, { samples })) {
        for (let i = 1; i < curve.length; i++) {
          const p = curve[i - 1].center;
          const q = curve[i].center;
          const far = Math.hypot(p.x, p.y) > 20 && Math.hypot(q.x, q.y) > 20;
          expect(far && p.x * q.x + p.y * q.y < 0, `samples ${samples}: ${JSON.stringify([p, q])}`).toBe(false);
        }
      }
    }
  });

  it('throws for bad poses and options, naming them', () => {
    const poses = randomPoses(seeded(43), 4);
    expect(() => burmesterCurves(poses.slice(0, 3))).toThrow('poses must hold exactly 4 entries, got 3');
    expect(() => burmesterCurves(poses, { samples: 4 })).toThrow(
      'options.samples must be an integer from 8 to 100000, got 4',
    );
    expect(() => burmesterCurves(poses, { samples: 20.5 })).toThrow('got 20.5');
  });
});

describe('burmesterFourBars', () => {
  it('builds the generating linkage from its two dyads, meeting the poses in order with no defect', () => {
    const rnd = seeded(51);
    for (let trial = 0; trial < 15; trial++) {
      const { d, t2, poses } = linkagePoses(rnd);
      const pairs = burmesterPoints(poses);
      const bars = burmesterFourBars(poses, pairs);
      expect(bars).toHaveLength((pairs.length * (pairs.length - 1)) / 2);
      const size = d.links.r1 + d.links.r2 + d.links.r3 + d.links.r4;
      const same = (b: PlacedFourBar) =>
        (['r1', 'r2', 'r3', 'r4'] as const).every((k) => Math.abs(b.links[k] - d.links[k]) < 1e-8 * size) &&
        dist(b.O2, d.O2) < 1e-8 * size;
      const found = bars.find((b) => same(b.design));
      expect(found, `trial ${trial}`).toBeDefined();
      expect(found!.design.branch).toBe(d.branch);
      expect(found!.defects).toEqual([]);
      found!.theta2.forEach((t, i) => expect(Math.abs(angleDiff(t, t2[i]))).toBeLessThan(1e-8));
    }
  });

  it('screens every four-bar: each θ2 puts the coupler at its pose, on the design branch unless it says branch', () => {
    const rnd = seeded(52);
    let screened = 0;
    let onBranch = 0;
    for (let trial = 0; trial < 20; trial++) {
      const poses = trial % 2 ? linkagePoses(rnd).poses : randomPoses(rnd, 5);
      for (const bar of burmesterFourBars(poses, burmesterPoints(poses))) {
        for (const defect of bar.defects) expect(['order', 'branch', 'not-crank']).toContain(defect);
        const other = bar.design.branch === 'open' ? 'crossed' : 'open';
        const size = bar.design.links.r1 + bar.design.links.r2 + bar.design.links.r3 + bar.design.links.r4;
        const misses = bar.theta2.map((t, i) => {
          const here = placedJoints(bar.design, t);
          const there = placedJoints({ ...bar.design, branch: other }, t);
          // The circle points were polished to rounding; the pose is met to the conditioning of the rebuild.
          const hit = (j: typeof here) => j !== null && dist(j.P, poses[i]) < 1e-8 * (size + bar.design.pDist);
          expect(hit(here) || hit(there), `trial ${trial} pose ${i}`).toBe(true);
          return !hit(here);
        });
        expect(misses.some(Boolean)).toBe(bar.defects.includes('branch'));
        screened++;
        if (!bar.defects.includes('branch')) onBranch++;
      }
    }
    expect(screened).toBeGreaterThan(20);
    expect(onBranch).toBeGreaterThan(5);
  });

  it('throws for bad pairs, naming them', () => {
    const poses = randomPoses(seeded(53), 5);
    expect(() => burmesterFourBars(poses, [{ center: { x: 0, y: 0 }, circle: { x: 'a', y: 0 } } as never])).toThrow(
      'pairs[0].circle.x must be a finite coordinate, got "a"',
    );
    expect(() => burmesterFourBars(poses, 3 as never)).toThrow('pairs must be an array of {center, circle}, got 3');
  });
});
