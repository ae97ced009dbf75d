/**
 * sweepForces checked by the balance laws, with no Newton–Euler equation on the test's side: at every
 * point of a turn of random cases, the power of the motor and the external loads equals the rate of change
 * of kinetic energy, and the force and moment the linkage puts on the ground equal the external loads
 * less the rate of change of momentum. The CG motions come from tests/solver/forcesOracle.ts (relative
 * motion, in double) with the solver's linkRates (checked against its own oracles in rates.test.ts).
 *
 * The pose is taken as exact on both sides, so each balance holds to rounding: a few eps of the sum of its
 * terms' sizes (|a| |b| for a dot or cross product, whose components can cancel) and of the larger values the
 * solver forms its answer from (A × F32 for T12, the pin forces for the shaking force). Near a toggle the
 * rates and the pin forces each carry one more 1 / |sin mu|: the tolerance is 16 eps (sizes) / sin² mu.
 * Measured over these seeds: 2 eps for the power and force balances, 1.4 eps / sin² mu for the moment.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { STATUS_CODE, linkRates, sweep, sweepForces } from '../../src/solver';
import type { SweepForces } from '../../src/solver';
import type { ForceCase, LinkMotion, Pt } from './forcesOracle';
import { forceCaseArb, gravityVector, linkMotions } from './forcesOracle';

const K = 16 * Number.EPSILON;
/** A turn in 5 degree steps. */
const GRID = Float64Array.from({ length: 73 }, (_, i) => (i * 2 * Math.PI) / 72);

/** A term of a balance and its size: the scale its rounding is judged against. */
interface Term {
  value: number;
  size: number;
}
const norm = (a: Pt) => Math.hypot(a.x, a.y);
const scalar = (value: number): Term => ({ value, size: Math.abs(value) });
// A dot or cross product's components can cancel (a centripetal acceleration is normal to the velocity):
// its rounding is relative to |a| |b|, not to the product.
const dot = (a: Pt, b: Pt, k = 1): Term => ({
  value: k * (a.x * b.x + a.y * b.y),
  size: Math.abs(k) * norm(a) * norm(b),
});
const cross = (a: Pt, b: Pt, k = 1): Term => ({
  value: k * (a.x * b.y - a.y * b.x),
  size: Math.abs(k) * norm(a) * norm(b),
});
/** A balance's residual and the sum of its terms' sizes. */
const total = (terms: Term[]) => ({
  sum: terms.reduce((s, t) => s + t.value, 0),
  size: terms.reduce((s, t) => s + t.size, 0),
});

interface Point {
  c: ForceCase;
  f: SweepForces;
  i: number;
  links: LinkMotion[];
  P: Pt;
  vP: Pt;
  sinMu: number;
}

/** Calls check at every solved point of a turn of the case, with the test's own account of the motion. */
function eachPoint(c: ForceCase, check: (p: Point) => void): void {
  const r = sweep(c.l, GRID, { branch: c.branch });
  const ok = (i: number) => r.statusCodes[i] === STATUS_CODE.ok;
  const f = sweepForces(c.l, r.theta2, r.theta3, r.theta4, ok, c.motion, c.inertia, c.loads);
  for (let i = 0; i < GRID.length; i++) {
    if (!ok(i)) continue;
    const pose = { theta3: r.theta3[i], theta4: r.theta4[i] };
    const sinMu = Math.sin(pose.theta4 - pose.theta3);
    if (Math.abs(sinMu) < 1e-3) continue;
    const rates = linkRates(c.l, GRID[i], pose, c.motion);
    const m = linkMotions(c.l, GRID[i], pose, c.motion, rates, c.inertia, c.loads);
    check({ c, f, i, ...m, sinMu });
  }
}

function fp(c: ForceCase): Pt {
  return { x: c.loads.couplerForce?.fx ?? 0, y: c.loads.couplerForce?.fy ?? 0 };
}

describe('sweepForces: energy and momentum balance', () => {
  it('gives T12 omega2 + external power = d(kinetic energy)/dt at every point of random cases (seeded)', () => {
    fc.assert(
      fc.property(forceCaseArb, (c) => {
        const g = gravityVector(c.loads);
        eachPoint(c, ({ f, i, links, vP, sinMu }) => {
          const rocker = links[2];
          const terms = [
            scalar(f.torque[i] * c.motion.omega2),
            ...links.map((k) => dot(g, k.vG, k.mass)),
            dot(fp(c), vP),
            scalar((c.loads.outputTorque ?? 0) * rocker.omega),
            // d(KE)/dt = sum of m v_G . a_G + I omega alpha, moved to this side.
            ...links.map((k) => dot(k.vG, k.aG, -k.mass)),
            ...links.map((k) => scalar(-k.inertia * k.omega * k.alpha)),
          ];
          const { sum, size } = total(terms);
          // The solver forms T12 from A × F32, which can be far larger than T12 itself.
          const inner = Math.abs(c.motion.omega2) * c.l.r2 * Math.hypot(f.f32x[i], f.f32y[i]);
          expect(Math.abs(sum), `${JSON.stringify(c)} at point ${i}: ${JSON.stringify(terms)}`).toBeLessThanOrEqual(
            (K * (size + inner)) / sinMu ** 2,
          );
        });
      }),
      { seed: 30, numRuns: 120 },
    );
  });

  it('gives a shaking force F21 + F41 = external forces - sum of m a_G at every point (seeded)', () => {
    fc.assert(
      fc.property(forceCaseArb, (c) => {
        const g = gravityVector(c.loads);
        eachPoint(c, ({ f, i, links, sinMu }) => {
          for (const axis of ['x', 'y'] as const) {
            const shaking = axis === 'x' ? f.shakingX[i] : f.shakingY[i];
            // The solver forms the shaking force from the pin forces, which can be far larger than it.
            const pins = [f.f12x, f.f12y, f.f14x, f.f14y].map((a) => Math.abs(a[i]));
            const terms = [
              scalar(-shaking),
              scalar(fp(c)[axis]),
              ...links.flatMap((k) => [
                scalar(k.mass * g[axis]),
                { value: -k.mass * k.aG[axis], size: k.mass * norm(k.aG) },
              ]),
            ];
            const { sum, size } = total(terms);
            const tol = (K * (size + Math.max(...pins))) / sinMu ** 2;
            expect(Math.abs(sum), `${JSON.stringify(c)} at point ${i}, ${axis}`).toBeLessThanOrEqual(tol);
          }
        });
      }),
      { seed: 31, numRuns: 120 },
    );
  });

  it('gives a shaking moment about O2 = external moments - d(angular momentum)/dt at every point (seeded)', () => {
    fc.assert(
      fc.property(forceCaseArb, (c) => {
        const g = gravityVector(c.loads);
        eachPoint(c, ({ f, i, links, P, sinMu }) => {
          const terms = [
            scalar(-f.shakingMoment[i]),
            cross(P, fp(c)),
            scalar(c.loads.outputTorque ?? 0),
            ...links.flatMap((k) => [cross(k.G, g, k.mass), cross(k.G, k.aG, -k.mass), scalar(-k.inertia * k.alpha)]),
          ];
          const { sum, size } = total(terms);
          // The solver forms the moment from T12 (itself from A × F32) and r1 F14y: their sizes count too.
          const parts = c.l.r2 * Math.hypot(f.f32x[i], f.f32y[i]) + c.l.r1 * Math.abs(f.f14y[i]);
          const tol = (K * (size + parts)) / sinMu ** 2;
          expect(Math.abs(sum), `${JSON.stringify(c)} at point ${i}`).toBeLessThanOrEqual(tol);
        });
      }),
      { seed: 32, numRuns: 120 },
    );
  });
});
