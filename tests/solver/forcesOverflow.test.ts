/**
 * Forces past the double range say so (issue 31, 11): a torque cycle whose ΔE would pass 1.8e308 reports
 * 'overflow', not 'ok' with NaN; linkForces whose forces overflow at a regular pose reports 'overflow', not the NaN
 * of a limit position. Oracles: the closed forms of a sinusoidal torque and of an unbalanced crank.
 */
import { describe, expect, it } from 'vitest';
import type { LinkInertia } from '../../src/solver';
import { forceCycle, linkForces, solveClosedForm, torqueCycleStats } from '../../src/solver';

const MASSLESS: LinkInertia = { mass: 0, inertia: 0, cg: { dist: 0, angle: 0 } };
const grid = Float64Array.from({ length: 361 }, (_, i) => (2 * Math.PI * i) / 360);

describe('torqueCycleStats near the double range', () => {
  it('reports overflow when ΔE passes the doubles (T = 1.7e308 sin θ: ΔE = 3.4e308), or the flywheel does', () => {
    const s = torqueCycleStats(
      grid,
      grid.map((t) => 1.7e308 * Math.sin(t)),
      10,
      0.05,
    );
    expect(s.status).toBe('overflow');
    expect(s.energyFluctuation).toBeNaN();
    // ΔE = 1.6e308 is a double; ΔE / (k ω²) at ω = 1, k = 0.05 is 3.2e309, which is not.
    const f = torqueCycleStats(
      grid,
      grid.map((t) => 0.8e308 * Math.sin(t)),
      1,
      0.05,
    );
    expect(f.status).toBe('overflow');
  });

  it('gives ΔE to the trapezoid rule’s accuracy just inside the range (T = 0.8e308 sin θ: ΔE = 1.6e308)', () => {
    // E(θ) = A (1 − cos θ) for T = A sin θ: ΔE = 2A; the linear interpolant on 360 steps is within (2π/360)²/8.
    const A = 0.8e308;
    const s = torqueCycleStats(
      grid,
      grid.map((t) => A * Math.sin(t)),
      1000,
      0.05,
    );
    expect(s.status, 'sine').toBe('ok');
    expect(Math.abs(s.energyFluctuation / (2 * A) - 1)).toBeLessThan(1e-4);
    // A torque near 1e308 with a ripple: ΔE = 2 · 1e300 (the mean cancels exactly in the scaled sum).
    const r = torqueCycleStats(
      grid,
      grid.map((t) => 1.7e308 + 1e300 * Math.sin(t)),
      1000,
      0.05,
    );
    expect(r.status, 'ripple').toBe('ok');
    expect(Number.isFinite(r.energyFluctuation)).toBe(true);
  });
});

describe('linkForces past the double range', () => {
  const l = { r1: 0.6, r2: 0.3, r3: 0.4, r4: 0.5 };
  const pose = solveClosedForm(l, 0.7, 'open')!;

  it("says 'overflow' with every field NaN when m ω² passes the doubles at a regular pose", () => {
    // An unbalanced crank: |F12| = m d ω2² = 1e300 · 0.15 · 1e20 (with α2 = 0): past 1.8e308.
    const crank: LinkInertia = { mass: 1e300, inertia: 0, cg: { dist: 0.15, angle: 0 } };
    const f = linkForces(l, 0.7, pose, { omega2: 1e10, alpha2: 0 }, { crank, coupler: MASSLESS, rocker: MASSLESS }, {});
    expect(f.status).toBe('overflow');
    expect(f.torque).toBeNaN();
    expect(f.F12.x).toBeNaN();
    // Just inside: m d ω² = 1e300 · 0.15 · 1e6 = 1.5e305, and |F12| is that (the crank carries its own d'Alembert force).
    const g = linkForces(l, 0.7, pose, { omega2: 1e3, alpha2: 0 }, { crank, coupler: MASSLESS, rocker: MASSLESS }, {});
    expect(g.status).toBe('ok');
    expect(Math.abs(Math.hypot(g.F12.x, g.F12.y) / 1.5e305 - 1)).toBeLessThan(1e-12);
  });

  it("forceCycle reports 'overflow' for a turn whose torque statistics overflow", () => {
    const coupler: LinkInertia = { mass: 1e300, inertia: 1e300, cg: { dist: 0.2, angle: 0.1 } };
    // A crank-rocker (S + L = 0.8 < P + Q = 0.95): its turn has no limit position.
    const cr = { r1: 0.6, r2: 0.2, r3: 0.5, r4: 0.45 };
    const c = forceCycle(cr, 'open', { omega2: 1e6, alpha2: 0 }, { crank: MASSLESS, coupler, rocker: MASSLESS }, {});
    expect(c.status).toBe('overflow');
    expect(c.stats.energyFluctuation).toBeNaN();
  });
});
