import { describe, expect, it } from 'vitest';
import {
  fourBarSpec,
  jansenSpec,
  mechanismForces,
  pistonDrivenSpec,
  sliderCrankSpec,
  sweepMechanism,
} from '../../src/mechanism';
import type { LinkMass, MechanismLoads, MechanismSpec } from '../../src/mechanism';
import { linkForces, solveClosedForm } from '../../src/solver';
import { grid } from './oracle';

describe('mechanismForces against the four-bar linkForces (src/solver)', () => {
  // 6-2-5-5 drawn at theta2 = 0. CGs: crank 0.8 along O2A; coupler 2 along AB and 0.5 to its left; rocker 3
  // along O4B. Gravity, a force at the coupler point P and a load torque on the rocker.
  const spec = fourBarSpec(6, 2, 5, 5);
  const [, a, b, o4] = spec.joints;
  const ab = Math.atan2(b.y - a.y, b.x - a.x);
  const o4b = Math.atan2(b.y - o4.y, b.x - o4.x);
  const masses: Record<string, LinkMass> = {
    crank: { mass: 1.2, inertia: 0.3, x: 0.8, y: 0 },
    coupler: {
      mass: 2.5,
      inertia: 1.1,
      x: a.x + 2 * Math.cos(ab) - 0.5 * Math.sin(ab),
      y: a.y + 2 * Math.sin(ab) + 0.5 * Math.cos(ab),
    },
    rocker: { mass: 1.7, inertia: 0.6, x: o4.x + 3 * Math.cos(o4b), y: o4.y + 3 * Math.sin(o4b) },
  };
  const pd = 3;
  const pa = 0.4;
  const px = a.x + pd * Math.cos(ab + pa);
  const py = a.y + pd * Math.sin(ab + pa);
  const loads: MechanismLoads = {
    gravity: { g: 9.81 },
    torques: { rocker: -4 },
    forces: [{ link: 'coupler', x: px, y: py, fx: 3, fy: -5 }],
  };
  const inputs = grid(0, 6.2, 32);
  const motion = { omega: 12, alpha: -30 };
  const f = mechanismForces(spec, inputs, motion, masses, loads);
  const r = sweepMechanism(spec, inputs, motion);

  it('gives the same input torque and pin forces at every point', () => {
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    let worst = 0;
    inputs.forEach((t, i) => {
      expect(f.ok[i]).toBe(1);
      // The template's lengths are the drawn doubles; the solver's the exact 6-2-5-5: angles agree to ~1e-15.
      const pose = solveClosedForm(l, t, 'open')!;
      // A load force that turns with the coupler in the solver is fixed in the world here: give the solver the
      // world force at this pose (it is the same vector).
      const ref = linkForces(
        l,
        t,
        pose,
        { omega2: motion.omega, alpha2: motion.alpha },
        {
          crank: { mass: 1.2, inertia: 0.3, cg: { dist: 0.8, angle: 0 } },
          coupler: { mass: 2.5, inertia: 1.1, cg: { dist: Math.hypot(2, 0.5), angle: Math.atan2(0.5, 2) } },
          rocker: { mass: 1.7, inertia: 0.6, cg: { dist: 3, angle: 0 } },
        },
        { gravity: { g: 9.81 }, outputTorque: -4, couplerForce: { pDist: pd, pAngle: pa, fx: 3, fy: -5 } },
      );
      const size = Math.max(Math.abs(ref.torque), Math.hypot(ref.F32.x, ref.F32.y), 1);
      const err = [
        f.input[i] - ref.torque,
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
    // Two independent routes (closed-form Newton–Euler vs a transposed LU solve) on lengths equal to rounding.
    expect(worst).toBeLessThan(1e-11);
    expect(r.ok.every((v) => v === 1)).toBe(true);
  });
});

/** Power balance: the driver's power equals the rate of kinetic energy minus the power of gravity and loads. */
function powerResidual(
  spec: MechanismSpec,
  masses: Record<string, LinkMass>,
  loads: MechanismLoads,
  inputs: Float64Array,
) {
  const motion = { omega: 5, alpha: 2 };
  const f = mechanismForces(spec, inputs, motion, masses, loads);
  // The CG and the load points as tracers: their velocities and accelerations come from the sweep.
  const points = [
    ...Object.entries(masses).map(([link, m]) => ({ id: `cg:${link}`, link, x: m.x, y: m.y })),
    ...(loads.forces ?? []).map((p, k) => ({ id: `f:${k}`, link: p.link, x: p.x, y: p.y })),
  ];
  const r = sweepMechanism({ ...spec, points }, inputs, motion);
  const g = loads.gravity?.g ?? 0;
  const gAngle = loads.gravity?.angle ?? -Math.acos(0);
  const gx = g * Math.cos(gAngle);
  const gy = g * Math.sin(gAngle);
  let worst = 0;
  for (let i = 0; i < inputs.length; i++) {
    let dT = 0;
    let scale = 0;
    for (const [link, m] of Object.entries(masses)) {
      const p = r.points[`cg:${link}`];
      const w = r.links[link].omega![i];
      const al = r.links[link].alpha![i];
      const terms = [
        m.mass * (p.ax![i] * p.vx![i] + p.ay![i] * p.vy![i]),
        m.inertia * al * w,
        -m.mass * (gx * p.vx![i] + gy * p.vy![i]),
      ];
      dT += terms[0] + terms[1] + terms[2];
      scale += terms.reduce((s, v) => s + Math.abs(v), 0);
    }
    (loads.forces ?? []).forEach((p, k) => {
      const q = r.points[`f:${k}`];
      const pw = p.fx * q.vx![i] + p.fy * q.vy![i];
      dT -= pw;
      scale += Math.abs(pw);
    });
    for (const [link, t] of Object.entries(loads.torques ?? {})) {
      dT -= t * r.links[link].omega![i];
      scale += Math.abs(t * r.links[link].omega![i]);
    }
    // The driver turns (or slides) at the input's rate omega = 5.
    const driver = f.input[i] * 5;
    worst = Math.max(worst, Math.abs(driver - dT) / scale);
  }
  return worst;
}

describe('mechanismForces: power balance', () => {
  it("holds on Jansen's leg (dyad path) with gravity, a foot load and a torque", () => {
    const spec = jansenSpec();
    const masses: Record<string, LinkMass> = {};
    for (const j of spec.joints) {
      for (const link of j.links) {
        if (link === 'ground' || masses[link]) continue;
        masses[link] = { mass: 0.1 + j.x / 1000, inertia: 0.01, x: j.x + 3, y: j.y - 2 };
      }
    }
    const foot = spec.points![0];
    const loads: MechanismLoads = {
      gravity: { g: 9.81 },
      torques: { upperTriangle: 0.7 },
      forces: [{ link: 'foot', x: foot.x, y: foot.y, fx: 2, fy: 30 }],
    };
    expect(powerResidual(spec, masses, loads, grid(0, 6.2, 25))).toBeLessThan(1e-12);
  });

  it('holds on an offset slider-crank (Newton path) with a gas force on the piston', () => {
    const spec = sliderCrankSpec(0.05, 0.2, 0.01);
    const b = spec.joints[2];
    const masses: Record<string, LinkMass> = {
      crank: { mass: 0.8, inertia: 1e-3, x: 0.01, y: 0 },
      coupler: { mass: 0.5, inertia: 2e-3, x: 0.1, y: 0.004 },
      slider: { mass: 0.4, inertia: 1e-4, x: b.x, y: b.y },
    };
    const loads: MechanismLoads = {
      gravity: { g: 9.81, angle: -1.2 },
      forces: [{ link: 'slider', x: b.x, y: b.y, fx: -900, fy: 0 }],
    };
    expect(powerResidual(spec, masses, loads, grid(0, 6.2, 25))).toBeLessThan(1e-12);
  });

  it('holds on a piston-driven crank (input force on a P joint) with a load torque on the crank', () => {
    const spec = pistonDrivenSpec();
    const masses: Record<string, LinkMass> = {
      crank: { mass: 1, inertia: 0.2, x: 0.3, y: 0.5 },
      rod: { mass: 2, inertia: 0.9, x: 2, y: 1 },
      piston: { mass: 3, inertia: 0.1, x: spec.joints[2].x, y: 0 },
    };
    const loads: MechanismLoads = { gravity: { g: 9.81 }, torques: { crank: 6 } };
    expect(powerResidual(spec, masses, loads, grid(-2, 1.5, 25))).toBeLessThan(1e-12);
  });

  it('refuses masses on an unknown link and a negative mass, naming them', () => {
    const spec = fourBarSpec(6, 2, 5, 5);
    const m = { mass: 1, inertia: 1, x: 0, y: 0 };
    expect(() => mechanismForces(spec, [0], { omega: 1, alpha: 0 }, { cupler: m })).toThrow(
      'unknown moving link "cupler"',
    );
    expect(() => mechanismForces(spec, [0], { omega: 1, alpha: 0 }, { crank: { ...m, mass: -1 } })).toThrow(
      'masses.crank.mass must be a non-negative finite number, got -1',
    );
  });
});
