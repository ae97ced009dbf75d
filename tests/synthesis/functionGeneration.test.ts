/**
 * Function generation: Freudenstein's equation and the Chebyshev-spaced function generator. Oracles by construction:
 * angle pairs from a known linkage (θ4 by the 60-digit oracle, tests/oracle/reference.ts) must give that linkage
 * back; the log10 generator must be exact at its precision points by the oracle too.
 */
import { describe, expect, it } from 'vitest';
import type { Branch, Linkage } from '../../src/solver';
import { PI, designMetrics, inputRange, solveClosedForm } from '../../src/solver';
import { NoLinkageError, chebyshevPoints, freudenstein, functionGenerator } from '../../src/synthesis';
import { angleDiff, referenceAngles } from '../oracle/reference';
import { randomCrankRocker, seeded, sigmaOf } from './motionFixtures';

const deg = PI / 180;
const BRANCHES: Branch[] = ['open', 'crossed'];

/** θ4 of a linkage at θ2 on a branch, by the 60-digit oracle. */
function theta4(l: Linkage, theta2: number, b: Branch): number {
  const ref = referenceAngles(l, theta2, sigmaOf(b));
  if (!ref) throw new Error(`fixture: no pose at θ2 = ${theta2}`);
  return ref.theta4;
}

/** Relative difference of two linkages (largest over the four lengths). */
function linkError(a: Linkage, b: Linkage): number {
  return Math.max(...(['r1', 'r2', 'r3', 'r4'] as const).map((k) => Math.abs(a[k] - b[k]) / b[k]));
}

describe('freudenstein', () => {
  // Three pairs at least 30° apart in θ2 on a crank-rocker: the 3×3 system's condition number stays below ~1e4, so
  // the K's (and the lengths, which are ratios of them) come back to about 1e4 ε; 1e-10 leaves a margin.
  it('gives back the linkage that generated three angle pairs, on its branch', () => {
    const rnd = seeded(17);
    for (let trial = 0; trial < 20; trial++) {
      const l = randomCrankRocker(rnd);
      const b = BRANCHES[trial % 2];
      const start = 2 * PI * rnd();
      const t2 = [start, start + (0.6 + rnd()) * 1, start + 2.2 + rnd()];
      const out = freudenstein(
        t2.map((t) => ({ theta2: t, theta4: theta4(l, t, b) })),
        { r1: l.r1 },
      );
      expect(linkError(out.links, l), `trial ${trial}`).toBeLessThan(1e-10);
      expect(out.links.r1).toBe(l.r1);
      expect(out.branch).toBe(b);
      // Three equations, three unknowns: the residual is rounding (cos of O(1) terms, ε ≈ 2e-16 each).
      expect(out.residual).toBeLessThan(1e-14);
    }
  });

  it('fits many exact pairs by least squares with a residual at rounding and the same linkage', () => {
    const rnd = seeded(5);
    for (let trial = 0; trial < 8; trial++) {
      const l = randomCrankRocker(rnd);
      const b = BRANCHES[trial % 2];
      const pairs = Array.from({ length: 12 }, (_, k) => {
        const t = (2 * PI * k) / 12 + 0.1 * rnd();
        return { theta2: t, theta4: theta4(l, t, b) };
      });
      const out = freudenstein(pairs, { r1: l.r1 });
      expect(linkError(out.links, l)).toBeLessThan(1e-10);
      expect(out.branch).toBe(b);
      expect(out.residual).toBeLessThan(1e-14);
    }
  });

  it('scales the lengths so that r1 is options.r1, 1 by default', () => {
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    const pairs = [0.3, 1.4, 2.9].map((t) => ({ theta2: t, theta4: theta4(l, t, 'open') }));
    const unit = freudenstein(pairs);
    expect(unit.links.r1).toBe(1);
    expect(linkError(unit.links, { r1: 1, r2: 2 / 6, r3: 5 / 6, r4: 5 / 6 })).toBeLessThan(1e-12);
    expect(freudenstein(pairs, { r1: 0.25 }).links.r1).toBe(0.25);
  });

  it('reads a noisy least-squares fit: residual of the order of the noise, lengths close', () => {
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    const rnd = seeded(9);
    const pairs = Array.from({ length: 20 }, (_, k) => {
      const t = (2 * PI * k) / 20;
      return { theta2: t, theta4: theta4(l, t, 'open') + 1e-6 * (rnd() - 0.5) };
    });
    const out = freudenstein(pairs, { r1: 6 });
    expect(out.residual).toBeGreaterThan(1e-9);
    expect(out.residual).toBeLessThan(1e-5);
    expect(linkError(out.links, l)).toBeLessThan(1e-4);
  });

  it('throws that no real linkage fits when the rocker would have to point the other way', () => {
    // θ4 + π on every pair: Freudenstein's equation holds with K2 and K3 negated, i.e. r4 < 0.
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    const pairs = [0.3, 1.4, 2.9].map((t) => ({ theta2: t, theta4: theta4(l, t, 'open') + PI }));
    expect(() => freudenstein(pairs)).toThrow(/no real linkage fits these pairs: r4 would be -/);
    const crank = [0.3, 1.4, 2.9].map((t) => ({ theta2: t + PI, theta4: theta4(l, t, 'open') + PI }));
    expect(() => freudenstein(crank)).toThrow(/no real linkage fits these pairs: r2 would be -/);
    // The same as a NoLinkageError, the reason and the length (the oracle's −r2, −r4 in units of r1) for a page.
    const caught = (pp: typeof pairs) => {
      try {
        freudenstein(pp);
      } catch (e) {
        return e;
      }
      throw new Error('no throw');
    };
    const rocker = caught(pairs);
    expect(rocker).toBeInstanceOf(NoLinkageError);
    expect(rocker).toMatchObject({ reason: 'rocker', value: expect.closeTo(-5 / 6, 9) });
    expect(caught(crank)).toMatchObject({ reason: 'crank', value: expect.closeTo(-2 / 6, 9) });
    const same = [0.3, 1.4, 2.9].map((t) => ({ theta2: t, theta4: t }));
    expect(caught(same)).toMatchObject({ reason: 'singular' });
  });

  it('gives the same linkage, scaled, for r1 from 1e-300 to 1e300 (issue 31, 3)', () => {
    // The pairs do not depend on the scale; the oracle's linkage scaled by r1 is the answer at every r1.
    const rnd = seeded(3);
    const l = randomCrankRocker(rnd);
    const t2 = [0.3, 1.4, 3.1];
    const pairs = t2.map((t) => ({ theta2: t, theta4: theta4(l, t, 'open') }));
    for (const r1 of [1e-300, 1e-160, 1e-100, 1e100, 1.3e154, 1e200, 1e300]) {
      const k = r1 / l.r1;
      const want = { r1, r2: l.r2 * k, r3: l.r3 * k, r4: l.r4 * k };
      const out = freudenstein(pairs, { r1 });
      expect(linkError(out.links, want), `r1 ${r1}`).toBeLessThan(1e-10);
      expect(out.branch).toBe('open');
    }
  });

  it('refuses an r1 that would put a length outside the double range, naming r1', () => {
    const pairs = [0.3, 1.4, 3.1].map((t) => ({
      theta2: t,
      theta4: theta4({ r1: 1, r2: 0.3, r3: 1.2, r4: 1.1 }, t, 'open'),
    }));
    expect(() => freudenstein(pairs, { r1: 1.7e308 })).toThrow(
      /options\.r1 = 1\.7e\+308 puts r3 = .* outside the double range/,
    );
  });

  it('throws for bad pairs and options, naming the parameter and the value', () => {
    const ok = [
      { theta2: 0, theta4: 1 },
      { theta2: 1, theta4: 1.5 },
      { theta2: 2, theta4: 2.2 },
    ];
    expect(() => freudenstein(ok.slice(0, 2))).toThrow('pairs must hold 3 to 10000 entries, got 2');
    expect(() => freudenstein([ok[0], { theta2: 1, theta4: NaN }, ok[2]])).toThrow(
      'pairs[1].theta4 must be a finite angle in radians, got NaN',
    );
    expect(() => freudenstein([ok[0], null as never, ok[2]])).toThrow('pairs[1] must be {theta2, theta4}, got null');
    expect(() => freudenstein(ok, { r1: -2 })).toThrow('options.r1 must be a positive finite length, got -2');
    expect(() => freudenstein([ok[0], ok[0], ok[1]])).toThrow(/singular/);
    // A sparse array's hole is a pair too (issue 31, 10).
    const sparse = [ok[0], ok[1], ok[2]];
    delete sparse[1];
    expect(() => freudenstein(sparse)).toThrow('pairs[1] must be {theta2, theta4}, got undefined');
  });
});

describe('chebyshevPoints', () => {
  it('spaces n points as (x0+x1)/2 − (x1−x0)/2 cos((2j−1)π/(2n)), ascending', () => {
    const xs = chebyshevPoints(1, 10, 3);
    const want = [1, 2, 3].map((j) => 5.5 - 4.5 * Math.cos(((2 * j - 1) * PI) / 6));
    xs.forEach((x, i) => expect(x).toBeCloseTo(want[i], 14));
    const five = chebyshevPoints(-2, 3, 5);
    for (let i = 1; i < five.length; i++) expect(five[i]).toBeGreaterThan(five[i - 1]);
  });
});

describe('functionGenerator', () => {
  // y = log10 x on [1, 10]; θ2 from 30° to 90°, θ4 from −60° to −150°: a defect-free crank-rocker design.
  const task = { f: Math.log10, x: [1, 10] as [number, number], theta2: [30 * deg, 90 * deg] as [number, number] };
  const log10Task = { ...task, theta4: [-60 * deg, -150 * deg] as [number, number] };

  it('generates log10 exactly at its three Chebyshev points and to within 1% of the range elsewhere', () => {
    const out = functionGenerator({ ...log10Task, points: 3 });
    expect(out.defects).toEqual([]);
    expect(out.precision.map((p) => p.x)).toEqual(chebyshevPoints(1, 10, 3));
    for (const p of out.precision) {
      // Exact at a precision point: the 60-digit oracle's θ4 on the design agrees with the prescribed θ4 to the
      // conditioning of the fit (1e-12 rad; y per rad is 1/(π/2) here, so the y error is below 1e-12 too).
      const ref = referenceAngles(out.links, p.theta2, sigmaOf(out.branch))!;
      expect(Math.abs(angleDiff(ref.theta4, p.theta4))).toBeLessThan(1e-12);
    }
    expect(out.structuralError.length).toBeGreaterThanOrEqual(50);
    expect(out.structuralError[0].x).toBe(1);
    expect(out.structuralError.at(-1)!.x).toBe(10);
    // The textbook size of a three-point log10 generator's structural error: well under 1% of y's range (1).
    expect(out.maxError).toBeLessThan(0.01);
    expect(out.maxError).toBeGreaterThan(1e-4);
    expect(out.maxError).toBe(Math.max(...out.structuralError.map((s) => Math.abs(s.error))));
  });

  it('measures the structural error on the design branch, as y generated − f(x)', () => {
    const out = functionGenerator({ ...log10Task, points: 3, samples: 60 });
    for (const s of out.structuralError.filter((_, k) => k % 7 === 0)) {
      const t2 = 30 * deg + ((s.x - 1) / 9) * 60 * deg;
      const ref = referenceAngles(out.links, t2, sigmaOf(out.branch))!;
      const yGenerated = ((ref.theta4 - -60 * deg) / (-90 * deg)) * 1;
      // Oracle θ4 (60 digits) against the solver's: both within ~1e-15 rad; y per rad is 2/π.
      expect(Math.abs(s.error - (yGenerated - Math.log10(s.x)))).toBeLessThan(1e-12);
    }
  });

  it('fits five Chebyshev points by least squares: not exact, still small, residual reported', () => {
    const out = functionGenerator({ ...log10Task, points: 5 });
    expect(out.precision).toHaveLength(5);
    expect(out.residual).toBeGreaterThan(1e-6);
    expect(out.maxError).toBeLessThan(0.01);
    expect(out.defects).toEqual([]);
  });

  it("reports 'limit' when the rocker turns back inside the input range", () => {
    // A crank-rocker generating its own θ4(θ2) across its extended dead centre: the rocker stops and returns.
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    const dead = designMetrics(l, 'open').output!.extended.theta2;
    const f = (x: number) => solveClosedForm(l, x, 'open')!.theta4;
    const x: [number, number] = [dead - 1, dead + 0.5];
    const out = functionGenerator({ f, x, theta2: x, theta4: [f(x[0]), f(x[1])], points: 3, r1: 6 });
    expect(linkError(out.links, l)).toBeLessThan(1e-10);
    expect(out.defects).toEqual(['limit']);
    // Positive control: the same linkage short of the dead centre has no defect.
    const y: [number, number] = [dead - 1.2, dead - 0.2];
    expect(functionGenerator({ f, x: y, theta2: y, theta4: [f(y[0]), f(y[1])], points: 3 }).defects).toEqual([]);
  });

  it("reports 'not-assemblable' and 'limit' when the input range runs past the input's own limit", () => {
    // A triple rocker (input range limited): the range runs past its upper limit after the last precision point.
    const l = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
    const hi = inputRange(l).intervals[0].hi;
    const x: [number, number] = [hi - 1, hi + 0.05];
    // θ4 where it assembles; past the limit any finite continuation (never used by the design).
    const f = (t: number) => solveClosedForm(l, Math.min(t, hi), 'open')!.theta4 + Math.max(0, t - hi);
    const out = functionGenerator({ f, x, theta2: x, theta4: [f(x[0]), f(x[1])], points: 3, r1: 4 });
    expect(linkError(out.links, l)).toBeLessThan(1e-8);
    expect(out.defects).toEqual(['not-assemblable', 'limit']);
    expect(out.maxError).toBe(Infinity);
    expect(out.structuralError.at(-1)!.error).toBeNaN();
  });

  it("reports 'branch' when the precision pairs lie on different branches", () => {
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    // θ4 from the open branch for the first two precision points, from the crossed for the last.
    const split = 0.6;
    const f = (t: number) => solveClosedForm(l, t, t < split ? 'open' : 'crossed')!.theta4;
    const x: [number, number] = [-0.5, 0.7];
    const out = functionGenerator({ f, x, theta2: x, theta4: [f(x[0]), f(x[1])], points: 3, r1: 6 });
    expect(out.precision.filter((p) => p.theta2 >= split)).toHaveLength(1);
    expect(linkError(out.links, l)).toBeLessThan(1e-10);
    expect(out.branch).toBe('open');
    expect(out.defects).toEqual(['branch']);
  });

  it('maps a range as wide as the doubles without overflow, and blames nothing (issue 31, 3)', () => {
    // x on [−1.7e308, 1.7e308] with f(x) = x/2 is the unit problem x' on [−1, 1], f(x') = x'/2, scaled: the same
    // design, precision angles and relative structural error.
    const big = 1.7e308;
    const unit = functionGenerator({
      f: (v) => v / 2,
      x: [-1, 1],
      theta2: [0.5, 1.9],
      theta4: [-0.9, -2.1],
      points: 3,
    });
    const out = functionGenerator({
      f: (v) => v / 2,
      x: [-big, big],
      theta2: [0.5, 1.9],
      theta4: [-0.9, -2.1],
      points: 3,
    });
    expect(linkError(out.links, unit.links)).toBeLessThan(1e-12);
    out.precision.forEach((p, i) => expect(p.theta2).toBeCloseTo(unit.precision[i].theta2, 14));
    expect(out.structuralError.every((s) => Number.isFinite(s.x) && Number.isFinite(s.error))).toBe(true);
    expect(out.maxError / big).toBeCloseTo(unit.maxError, 12);
  });

  it('reports no limit for a non-monotone f whose wiggle the fit does not follow, as the docs say (issue 31, 12)', () => {
    // log10 x + 0.003 sin 20x turns back (f' < 0 where 0.06 cos 20x < −1/(x ln 10), x > 7.3): the design does not.
    const out = functionGenerator({ ...log10Task, f: (x) => Math.log10(x) + 0.003 * Math.sin(20 * x), points: 3 });
    expect(out.defects).toEqual([]);
    expect(out.maxError).toBeGreaterThan(0.003);
  });

  it('throws for bad tasks, naming the parameter and the value', () => {
    const base = { ...log10Task, points: 3 };
    expect(() => functionGenerator({ ...base, f: 3 as never })).toThrow('f must be a function of one number, got 3');
    expect(() => functionGenerator({ ...base, points: 2 })).toThrow('points must be an integer from 3 to 50, got 2');
    expect(() => functionGenerator({ ...base, points: 3.5 })).toThrow('got 3.5');
    expect(() => functionGenerator({ ...base, points: 51 })).toThrow('got 51');
    expect(() => functionGenerator({ ...base, x: [1, 1] })).toThrow('x must have start ≠ end, got [1,1]');
    expect(() => functionGenerator({ ...base, theta2: [0, NaN] })).toThrow(
      'theta2[1] must be a finite angle in radians, got NaN',
    );
    expect(() => functionGenerator({ ...base, theta4: [0] as never })).toThrow('theta4 must be [start, end], got [0]');
    expect(() => functionGenerator({ ...base, f: (v: number) => (v > 5 ? NaN : v) })).toThrow(
      /f\(10\) must be a finite number, got NaN/,
    );
    expect(() => functionGenerator({ ...base, f: () => 1 })).toThrow('f(x0) and f(x1) must differ');
    expect(() => functionGenerator({ ...base, samples: 10 })).toThrow(
      'samples must be an integer from 50 to 10001, got 10',
    );
  });
});
