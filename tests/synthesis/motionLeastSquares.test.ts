import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import type { Pose } from '../../src/synthesis';
import { approximateDyads, approximateMotion, burmesterFourBars, poseErrors } from '../../src/synthesis';
import { KNOWN, knownPose } from '../features/synthesis/motion/knownLinkage';
import { seeded } from './motionFixtures';

const rad = (d: number) => (d * Math.PI) / 180;
/** n poses of the known crank-rocker (an independent circle intersection) at θ2 = 10°, 10° + 340°/n, … */
const knownPoses = (n: number): Pose[] =>
  Array.from({ length: n }, (_, k) => knownPose(rad(10 + (340 * k) / n))).map((p) => ({
    x: p.x,
    y: p.y,
    angle: rad(p.angleDeg),
  }));
const dist = (a: { x: number; y: number }, b: { x: number; y: number }) => Math.hypot(a.x - b.x, a.y - b.y);

Decimal.set({ precision: 40 });

/** Σ (|P_i(Z) − C| − R)² in 40 digits: the objective the dyads minimise, computed independently of the module. */
function objective(poses: readonly Pose[], z: [number, number], c: [number, number], r: number): Decimal {
  let sum = new Decimal(0);
  for (const p of poses) {
    const cos = Decimal.cos(p.angle);
    const sin = Decimal.sin(p.angle);
    const px = new Decimal(p.x).plus(cos.times(z[0])).minus(sin.times(z[1])).minus(c[0]);
    const py = new Decimal(p.y).plus(sin.times(z[0])).plus(cos.times(z[1])).minus(c[1]);
    const e = px.pow(2).plus(py.pow(2)).sqrt().minus(r);
    sum = sum.plus(e.pow(2));
  }
  return sum;
}

describe('approximateMotion (issue 34, item 9)', () => {
  it.each([6, 10, 20])('recovers the known crank-rocker from %i exact poses, with zero error at every pose', (n) => {
    const poses = knownPoses(n);
    const { dyads, fourBars } = approximateMotion(poses);
    // The known dyads are exact solutions: their rms is rounding (1e-15 of lengths about 1), found to 1e-9.
    for (const [C, z] of [
      [KNOWN.O2, KNOWN.a],
      [KNOWN.O4, KNOWN.b],
    ]) {
      const d = dyads.find((e) => dist(e.center, C) < 1e-9 && dist(e.circle, z) < 1e-9);
      expect(d).toBeDefined();
      expect(d!.rms).toBeLessThan(1e-12);
    }
    const best = fourBars[0];
    expect(best.defects).toEqual([]);
    expect(best.rms).toBeLessThan(1e-9);
    expect(best.errors).toHaveLength(n);
    for (const e of best.errors) {
      expect(e.position).toBeLessThan(1e-9);
      expect(Math.abs(e.angle)).toBeLessThan(1e-9);
    }
  });

  it('finds a least-squares minimum for noisy poses: every small step of Z, C or R raises Σ e² (40 digits)', () => {
    const rnd = seeded(34);
    const poses = knownPoses(12).map((p) => ({
      x: p.x + 0.02 * (rnd() - 0.5),
      y: p.y + 0.02 * (rnd() - 0.5),
      angle: p.angle + 0.01 * (rnd() - 0.5),
    }));
    const dyads = approximateDyads(poses);
    expect(dyads.length).toBeGreaterThanOrEqual(2);
    for (const d of dyads.slice(0, 2)) {
      const x = [d.circle.x, d.circle.y, d.center.x, d.center.y, d.radius];
      const f = (v: number[]) => objective(poses, [v[0], v[1]], [v[2], v[3]], v[4]);
      const f0 = f(x);
      // The rms the module reports is the objective's, to rounding.
      expect(Math.sqrt(f0.toNumber() / poses.length)).toBeCloseTo(d.rms, 12);
      // A step of 1e-5 changes a minimum's objective by about 1e-10 (quadratic) and a non-minimum's by 1e-5 × the
      // gradient: every step up, and the change at most 1e-7, is a stationary point that is a minimum.
      for (let i = 0; i < 5; i++) {
        for (const s of [-1e-5, 1e-5]) {
          const v = [...x];
          v[i] += s;
          const df = f(v).minus(f0).toNumber();
          expect(df).toBeGreaterThan(-1e-14);
          expect(df).toBeLessThan(1e-7);
        }
      }
    }
    // The fit stays near the known linkage: its dyads are within the noise of the known ones.
    expect(dyads.some((e) => dist(e.center, KNOWN.O2) < 0.05)).toBe(true);
    expect(dyads.some((e) => dist(e.center, KNOWN.O4) < 0.1)).toBe(true);
  });

  it('measures a pose’s error: pose 3 turned by δ about its crank pin is off by δ and 2|a| sin(δ/2)', () => {
    const poses = knownPoses(8);
    const delta = 0.05;
    // Turning pose 3 about its crank pin A keeps A, so the crank's θ2 there; the linkage's pose is the known one.
    const p = poses[2];
    const A = { x: p.x + Math.cos(p.angle) * KNOWN.a.x - Math.sin(p.angle) * KNOWN.a.y };
    const Ay = p.y + Math.sin(p.angle) * KNOWN.a.x + Math.cos(p.angle) * KNOWN.a.y;
    const c = Math.cos(delta);
    const s = Math.sin(delta);
    poses[2] = {
      x: A.x + c * (p.x - A.x) - s * (p.y - Ay),
      y: Ay + s * (p.x - A.x) + c * (p.y - Ay),
      angle: p.angle + delta,
    };
    const pairs = [
      { center: KNOWN.O2, circle: KNOWN.a },
      { center: KNOWN.O4, circle: KNOWN.b },
    ];
    const bar = burmesterFourBars(poses, pairs).find((b) => b.pairs[0] === 0)!;
    const errors = poseErrors(poses, bar, KNOWN.a, KNOWN.b);
    expect(errors[2].angle).toBeCloseTo(-delta, 12);
    expect(errors[2].position).toBeCloseTo(2 * Math.hypot(KNOWN.a.x, KNOWN.a.y) * Math.sin(delta / 2), 12);
    for (const i of [0, 1, 3, 4, 5, 6, 7]) expect(errors[i].position).toBeLessThan(1e-12);
  });

  it('refuses fewer than 6 or more than 20 poses, naming them', () => {
    expect(() => approximateMotion(knownPoses(5))).toThrow(/poses/);
    expect(() => approximateMotion(knownPoses(21))).toThrow(/poses/);
  });
});
