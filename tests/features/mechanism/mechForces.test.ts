import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import { MECHANISM_TEMPLATES, fourBarSpec, sliderCrankSpec } from '../../../src/mechanism';
import { linkForces, solveClosedForm } from '../../../src/solver';
import {
  barMasses,
  barsMass,
  outlineBars,
  reactionJoint,
  reactionMagnitude,
  solveMechForces,
} from '../../../src/features/mechanism/mechForces';
import type { MechForcesJob } from '../../../src/features/mechanism/mechForces';
import { mechanismHandlers } from '../../../src/features/mechanism/mechanismHandlers';

// The Mechanisms page's forces (issue 33): links as uniform bars along their outlines, lengths in the app's unit
// (lu) turned into metres, gravity down, the input at a constant speed. Oracles: the four-bar's closed-form
// Newton–Euler (src/solver linkForces), a power balance computed here in 60 digits from a closed-form pose, and the
// slider-crank's kinetostatics derived below by hand.

const D = Decimal.clone({ precision: 60 });
type Dec = InstanceType<typeof D>;
const d = (x: number | string) => new D(x);

/** Central difference of f at t in 60 digits (step h: truncation h², cancellation 1e-60 / h). */
const diff = (f: (t: Dec) => Dec, t: Dec, h: Dec) =>
  f(t.plus(h))
    .minus(f(t.minus(h)))
    .div(h.times(2));

describe('barsMass', () => {
  it('is a bar for two points, and the perimeter of three (parallel axes), in metres', () => {
    const rho = 3;
    const k = 0.01;
    const two = barsMass(
      outlineBars([
        { x: 0, y: 0 },
        { x: 4, y: 0 },
      ]),
      rho,
      k,
    )!;
    // 4 cm of 3 kg/m: 0.12 kg, I = m L² / 12 = 0.12 · 0.0016 / 12, CG at 2 cm.
    expect(two.mass).toBeCloseTo(0.12, 15);
    expect(two.inertia).toBeCloseTo((0.12 * 0.04 ** 2) / 12, 18);
    expect([two.x, two.y]).toEqual([0.02, 0]);
    // A 3-4-5 right triangle of wire (cm): sides along x (4), y (3) and the hypotenuse (5); by hand, in metres.
    const tri = barsMass(
      outlineBars([
        { x: 0, y: 0 },
        { x: 4, y: 0 },
        { x: 0, y: 3 },
      ]),
      rho,
      k,
    )!;
    const sides = [
      { l: 0.04, x: 0.02, y: 0 },
      { l: 0.03, x: 0, y: 0.015 },
      { l: 0.05, x: 0.02, y: 0.015 },
    ];
    const m = sides.reduce((s, e) => s + rho * e.l, 0);
    const cx = sides.reduce((s, e) => s + rho * e.l * e.x, 0) / m;
    const cy = sides.reduce((s, e) => s + rho * e.l * e.y, 0) / m;
    const inertia = sides.reduce((s, e) => s + rho * e.l * (e.l ** 2 / 12 + (e.x - cx) ** 2 + (e.y - cy) ** 2), 0);
    expect(tri.mass).toBeCloseTo(m, 15);
    expect(tri.x).toBeCloseTo(cx, 15);
    expect(tri.y).toBeCloseTo(cy, 15);
    expect(tri.inertia / inertia).toBeCloseTo(1, 13);
  });

  it('makes three points in line one bar between the farthest two, and a lone point (a block) massless', () => {
    const line = outlineBars([
      { x: 0, y: 0 },
      { x: 1, y: 1 },
      { x: 3, y: 3 },
    ]);
    expect(line).toEqual([
      [
        { x: 0, y: 0 },
        { x: 3, y: 3 },
      ],
    ]);
    expect(
      barsMass(
        outlineBars([
          { x: 2, y: 1 },
          { x: 2, y: 1 },
        ]),
        1,
        1,
      ),
    ).toBeNull();
    // The slider-crank's block has its pin and its slide at one point: no mass; the crank and rod have theirs.
    expect(Object.keys(barMasses(MECHANISM_TEMPLATES.sliderCrank.spec, 1, 1)).sort()).toEqual(['coupler', 'crank']);
  });
});

describe('reactionJoint', () => {
  it('keeps a chosen joint the linkage has, else the first joint after the input', () => {
    const spec = MECHANISM_TEMPLATES.fourBar.spec;
    expect(reactionJoint(spec, 'B')).toBe('B');
    expect(reactionJoint(spec, '')).toBe('A');
    expect(reactionJoint(spec, 'gone')).toBe('A');
  });
});

describe('solveMechForces on the four-bar template (6-2-5-5, lengths in cm)', () => {
  const spec = fourBarSpec(6, 2, 5, 5);
  const job: MechForcesJob = { metresPerUnit: 0.01, rhoKgPerM: 2, gravityMPerS2: 9.81, inputSpeed: 10 };
  const inputs = Float64Array.from({ length: 24 }, (_, i) => -Math.PI + (i + 0.5) * (Math.PI / 12));
  const f = solveMechForces(spec, inputs, job);
  const [o2, a0, b0, o4] = spec.joints;
  const p0 = spec.points![0];

  it('gives linkForces’ input torque and pin forces, with the bars’ mass properties written as the solver’s', () => {
    const k = job.metresPerUnit;
    const l = { r1: 6 * k, r2: 2 * k, r3: 5 * k, r4: 5 * k };
    const masses = barMasses(spec, job.rhoKgPerM, k);
    // The coupler's CG from A along AB (as drawn), its distance and angle: the solver's LinkInertia.
    const ab = Math.atan2(b0.y - a0.y, b0.x - a0.x);
    const c = masses.coupler;
    const cg = (m: typeof c, from: { x: number; y: number }, dir: number) => ({
      mass: m.mass,
      inertia: m.inertia,
      cg: {
        dist: Math.hypot(m.x - from.x * k, m.y - from.y * k),
        angle: Math.atan2(m.y - from.y * k, m.x - from.x * k) - dir,
      },
    });
    const inertias = {
      crank: cg(masses.crank, o2, 0),
      coupler: cg(c, a0, ab),
      rocker: cg(masses.rocker, o4, Math.atan2(b0.y - o4.y, b0.x - o4.x)),
    };
    let worst = 0;
    inputs.forEach((t, i) => {
      expect(f.ok[i]).toBe(1);
      const ref = linkForces(l, t, solveClosedForm(l, t, 'open')!, { omega2: 10, alpha2: 0 }, inertias, {
        gravity: { g: 9.81 },
      });
      const size = Math.max(Math.abs(ref.torque) / l.r2, Math.hypot(ref.F32.x, ref.F32.y));
      const err = [
        (f.input[i] - ref.torque) / l.r2,
        f.joints.A.fx[i] - ref.F32.x,
        f.joints.A.fy[i] - ref.F32.y,
        f.joints.B.fx[i] - ref.F43.x,
        f.joints.B.fy[i] - ref.F43.y,
        f.joints.O4.fx[i] - ref.F14.x,
        f.joints.O4.fy[i] - ref.F14.y,
        f.joints.O2.fx[i] + ref.F12.x,
        f.joints.O2.fy[i] + ref.F12.y,
      ];
      worst = Math.max(worst, ...err.map((e) => Math.abs(e) / size));
    });
    // The template's drawn lengths equal 6-2-5-5 to rounding; a benign linkage (μ in [47°, 106°]): 1e-11.
    expect(worst).toBeLessThan(1e-11);
  });

  it('balances power: T ω = d(kinetic energy)/dt − power of gravity, in 60 digits from the closed-form pose', () => {
    const k = d('0.01');
    const rho = d(2);
    const g = d('9.81');
    const w = d(10);
    const P = (p: { x: number; y: number }) => ({ x: d(p.x).times(k), y: d(p.y).times(k) });
    const [O2, A0, B0, O4, P0] = [P(o2), P(a0), P(b0), P(o4), P(p0)];
    const r2 = D.hypot(A0.x.minus(O2.x), A0.y.minus(O2.y));
    const r3 = D.hypot(B0.x.minus(A0.x), B0.y.minus(A0.y));
    const r4 = D.hypot(B0.x.minus(O4.x), B0.y.minus(O4.y));
    const th0 = D.atan2(A0.y, A0.x);
    const ab0 = D.atan2(B0.y.minus(A0.y), B0.x.minus(A0.x));
    // P in the coupler's frame at A along AB (as drawn): it turns with AB.
    const pu = P0.x
      .minus(A0.x)
      .times(D.cos(ab0))
      .plus(P0.y.minus(A0.y).times(D.sin(ab0)));
    const pv = P0.y
      .minus(A0.y)
      .times(D.cos(ab0))
      .minus(P0.x.minus(A0.x).times(D.sin(ab0)));
    /** The pose at input t: A on the crank circle, B the circle intersection left of A → O4 (as drawn), P on AB's frame. */
    const pose = (t: Dec) => {
      const ax = r2.times(D.cos(th0.plus(t)));
      const ay = r2.times(D.sin(th0.plus(t)));
      const dx = O4.x.minus(ax);
      const dy = O4.y.minus(ay);
      const dd = D.hypot(dx, dy);
      const along = r3.pow(2).minus(r4.pow(2)).plus(dd.pow(2)).div(dd.times(2));
      const h = r3.pow(2).minus(along.pow(2)).sqrt();
      const bx = ax.plus(along.times(dx).minus(h.times(dy)).div(dd));
      const by = ay.plus(along.times(dy).plus(h.times(dx)).div(dd));
      const phi3 = D.atan2(by.minus(ay), bx.minus(ax));
      const px = ax.plus(pu.times(D.cos(phi3))).minus(pv.times(D.sin(phi3)));
      const py = ay.plus(pu.times(D.sin(phi3))).plus(pv.times(D.cos(phi3)));
      const phi4 = D.atan2(by.minus(O4.y), bx.minus(O4.x));
      return { ax, ay, bx, by, px, py, phi3, phi4 };
    };
    type Pose = ReturnType<typeof pose>;
    type Pt = { x: Dec; y: Dec };
    /** A link of bars between points: its mass, its CG's place and its inertia (constant in the link). */
    const bars = (pts: Pt[]) => {
      const edges = pts.length === 2 ? [[pts[0], pts[1]]] : pts.map((p, i) => [p, pts[(i + 1) % pts.length]]);
      const parts = edges.map(([a, b]) => ({
        m: rho.times(D.hypot(b.x.minus(a.x), b.y.minus(a.y))),
        l: D.hypot(b.x.minus(a.x), b.y.minus(a.y)),
        x: a.x.plus(b.x).div(2),
        y: a.y.plus(b.y).div(2),
      }));
      const m = parts.reduce((s, p) => s.plus(p.m), d(0));
      const x = parts.reduce((s, p) => s.plus(p.m.times(p.x)), d(0)).div(m);
      const y = parts.reduce((s, p) => s.plus(p.m.times(p.y)), d(0)).div(m);
      const inertia = parts.reduce(
        (s, p) => s.plus(p.m.times(p.l.pow(2).div(12).plus(p.x.minus(x).pow(2)).plus(p.y.minus(y).pow(2)))),
        d(0),
      );
      return { m, x, y, inertia };
    };
    const pt = (x: Dec, y: Dec): Pt => ({ x, y });
    /** Each link's mass, inertia, CG and rotation at a pose (the CG from its outline's points at the pose). */
    const links = (q: Pose) => [
      { ...bars([O2, pt(q.ax, q.ay)]), phi: d(0) },
      { ...bars([pt(q.ax, q.ay), pt(q.bx, q.by), pt(q.px, q.py)]), phi: q.phi3 },
      { ...bars([O4, pt(q.bx, q.by)]), phi: q.phi4 },
    ];
    const h = d('1e-20');
    /** Each link's CG (x, y) and rotation at input t (the crank turns by t). */
    const state = (t: Dec) => links(pose(t)).map((lk, n) => [lk.x, lk.y, n === 0 ? t : lk.phi]);
    /** Each link's dG/dt and dφ/dt by one 60-digit central difference. */
    const rates = (t: Dec) => {
      const [up, down] = [state(t.plus(h)), state(t.minus(h))];
      return up.map((v, n) => v.map((x, c) => x.minus(down[n][c]).div(h.times(2))));
    };
    const lk0 = links(pose(d(0)));
    /** K(t) = KE / ω² = ½ Σ (m |dG/dt|² + I (dφ/dt)²); masses and inertias are constant in each link. */
    const kPerW2 = (t: Dec) =>
      rates(t)
        .reduce(
          (sum, [gx, gy, dphi], n) =>
            sum.plus(lk0[n].m.times(gx.pow(2).plus(gy.pow(2)))).plus(lk0[n].inertia.times(dphi.pow(2))),
          d(0),
        )
        .div(2);
    const H = d('1e-15');
    let worst = 0;
    let scale = 0;
    inputs.forEach((t, i) => {
      if (i % 2) return;
      const td = d(t);
      // T ω = ω³ dK/dt + g ω Σ m dy_G/dt (gravity's power is −g Σ m v_y).
      const dK = diff(kPerW2, td, H);
      const lift = rates(td).reduce((sum, [, gy], n) => sum.plus(lk0[n].m.times(gy)), d(0));
      const torque = w.pow(2).times(dK).plus(g.times(lift)).toNumber();
      worst = Math.max(worst, Math.abs(f.input[i] - torque));
      scale = Math.max(scale, Math.abs(torque));
    });
    // The pose in doubles carries ~1e-15 of the size; the torque a few eps of its largest term: 1e-12 relative.
    expect(scale).toBeGreaterThan(1e-3);
    expect(worst / scale).toBeLessThan(1e-12);
  });
});

/**
 * The offset slider-crank's kinetostatics in closed form (60 digits), derived here: crank r at θ, rod l at φ with
 * l sin φ = e − r sin θ, the block massless on a smooth guide along x. With ' = d/dθ and α = 0 (a = ω² G''):
 *   φ' = −r cos θ / (l cos φ),  φ'' = (r sin θ + l sin φ φ'²) / (l cos φ);
 *   G2 = A / 2,  G3 = A + (l/2)(cos φ, sin φ);
 *   T = ω² (m2 G2''·G2' + m3 G3''·G3' + I3 φ'' φ') + g (m2 G2'y + m3 G3'y)        (power balance)
 *   The block takes no force along x, so the rod's pin B carries (0, Fy); moments of the rod about A:
 *   l cos φ Fy = I3 ω² φ'' + (G3 − A) × m3 (ω² G3'' − g⃗).
 */
function sliderCrankClosedForm(r: Dec, l: Dec, e: Dec, rho: Dec, g: Dec, w: Dec, theta: Dec) {
  const c = D.cos(theta);
  const s = D.sin(theta);
  const sphi = e.minus(r.times(s)).div(l);
  const cphi = d(1).minus(sphi.pow(2)).sqrt();
  const p1 = r.times(c).neg().div(l.times(cphi));
  const p2 = r
    .times(s)
    .plus(l.times(sphi).times(p1.pow(2)))
    .div(l.times(cphi));
  const m2 = rho.times(r);
  const m3 = rho.times(l);
  const i3 = m3.times(l.pow(2)).div(12);
  const g2d = { x: r.times(s).neg().div(2), y: r.times(c).div(2) };
  const g2dd = { x: r.times(c).neg().div(2), y: r.times(s).neg().div(2) };
  const half = l.div(2);
  const g3d = { x: r.times(s).neg().minus(half.times(sphi).times(p1)), y: r.times(c).plus(half.times(cphi).times(p1)) };
  const g3dd = {
    x: r
      .times(c)
      .neg()
      .minus(half.times(cphi.times(p1.pow(2)).plus(sphi.times(p2)))),
    y: r
      .times(s)
      .neg()
      .minus(half.times(sphi.times(p1.pow(2)).minus(cphi.times(p2)))),
  };
  const dot = (u: { x: Dec; y: Dec }, v: { x: Dec; y: Dec }) => u.x.times(v.x).plus(u.y.times(v.y));
  const w2 = w.pow(2);
  const torque = w2
    .times(
      m2
        .times(dot(g2dd, g2d))
        .plus(m3.times(dot(g3dd, g3d)))
        .plus(i3.times(p2).times(p1)),
    )
    .plus(g.times(m2.times(g2d.y).plus(m3.times(g3d.y))));
  // q = m3 (a3 − g⃗) with g⃗ = (0, −g); (G3 − A) × q.
  const qx = m3.times(w2.times(g3dd.x));
  const qy = m3.times(w2.times(g3dd.y).plus(g));
  const moment = half.times(cphi).times(qy).minus(half.times(sphi).times(qx));
  const fy = i3.times(w2).times(p2).plus(moment).div(l.times(cphi));
  return { torque: torque.toNumber(), fy: fy.toNumber() };
}

describe('solveMechForces on the offset slider-crank (crank 2, rod 5, offset 1; lengths in mm)', () => {
  const spec = sliderCrankSpec(2, 5, 1);
  const job: MechForcesJob = { metresPerUnit: 1e-3, rhoKgPerM: 4, gravityMPerS2: 9.81, inputSpeed: 150 };
  const inputs = Float64Array.from({ length: 36 }, (_, i) => -Math.PI + (i + 0.25) * (Math.PI / 18));
  const f = solveMechForces(spec, inputs, job);

  it('gives the closed form’s input torque, and the pin B and the slide a force across the guide only', () => {
    const k = d('0.001');
    let worstT = 0;
    let worstF = 0;
    let scaleT = 0;
    let scaleF = 0;
    inputs.forEach((t, i) => {
      expect(f.ok[i]).toBe(1);
      const ref = sliderCrankClosedForm(d(2).times(k), d(5).times(k), d(1).times(k), d(4), d('9.81'), d(150), d(t));
      worstT = Math.max(worstT, Math.abs(f.input[i] - ref.torque));
      worstF = Math.max(
        worstF,
        Math.abs(f.joints.B.fx[i]),
        Math.abs(f.joints.B.fy[i] - ref.fy),
        Math.abs(f.joints.S.fx[i]),
        Math.abs(f.joints.S.fy[i] - ref.fy),
      );
      scaleT = Math.max(scaleT, Math.abs(ref.torque));
      scaleF = Math.max(scaleF, Math.abs(ref.fy));
    });
    expect(scaleT).toBeGreaterThan(1e-4);
    expect(worstT / scaleT).toBeLessThan(1e-12);
    expect(worstF / scaleF).toBeLessThan(1e-12);
    // |F| at B is the pin force's magnitude.
    expect(reactionMagnitude(f, 'B')[3]).toBeCloseTo(Math.abs(f.joints.B.fy[3]), 12);
  });

  it('scales with the length unit: the same machine in mm and in m has the same forces', () => {
    const inMetres = solveMechForces(
      { ...spec, joints: spec.joints.map((j) => ({ ...j, x: j.x / 1000, y: j.y / 1000 })) },
      inputs,
      { ...job, metresPerUnit: 1 },
    );
    inputs.forEach((_, i) => expect(inMetres.input[i] / f.input[i]).toBeCloseTo(1, 12));
    // A slider input: its inputs (lu) and speed (lu/s) are lengths too.
    const piston = MECHANISM_TEMPLATES.pistonDriven.spec;
    const slides = Float64Array.from([-1.5, -0.5, 0.5, 1.2]);
    const inMm = solveMechForces(piston, slides, { ...job, inputSpeed: 300 });
    const pistonM = { ...piston, joints: piston.joints.map((j) => ({ ...j, x: j.x / 1000, y: j.y / 1000 })) };
    const inM = solveMechForces(
      pistonM,
      slides.map((x) => x / 1000),
      { ...job, metresPerUnit: 1, inputSpeed: 0.3 },
    );
    slides.forEach((_, i) => expect(inM.input[i] / inMm.input[i]).toBeCloseTo(1, 10));
  });
});

describe('the mechSweep job with forces', () => {
  it('returns the sweep and the forces over the same inputs', async () => {
    const spec = MECHANISM_TEMPLATES.pistonDriven.spec;
    const inputs = Float64Array.from([0, 0.1, 0.2]);
    const job: MechForcesJob = { metresPerUnit: 0.01, rhoKgPerM: 1, gravityMPerS2: 0, inputSpeed: 2 };
    const r = await mechanismHandlers.mechSweep({ spec, inputs, rates: true, forces: job });
    expect(r.ok).toEqual(Uint8Array.from([1, 1, 1]));
    // A slider input: a force (N) along the slide, the same as solveMechForces gives.
    expect(Array.from(r.forces!.input)).toEqual(Array.from(solveMechForces(spec, inputs, job).input));
    expect((await mechanismHandlers.mechSweep({ spec, inputs, rates: false })).forces).toBeUndefined();
  });
});
