/**
 * pathSynthesis as a specification: oracles by construction (targets on a known coupler curve, computed at 50
 * digits in couplerOracle.ts), the guarantees of every answer, determinism, budget, abort, progress, bad input.
 * The exact criterion is the issue's: Σd² ≤ 1e-20 · size², with size the targets' largest distance from their
 * centroid (a fit to rounding leaves ~1e-30 · size²; 1e-20 is the acceptance line, not the expected value).
 */
import { describe, expect, it } from 'vitest';
import { PI, classify } from '../../src/solver';
import type { PathProgress, PathSolution, PathTask } from '../../src/synthesis';
import {
  PROGRESS_CANDIDATES,
  mergePathCandidates,
  pathSynthesis,
  pathSynthesisPart,
  placedCouplerPoint,
} from '../../src/synthesis';
import { EXACT_DESIGN, exactTargets, targetSize } from './benchmarkCases';

const EXACT_REL = 1e-20;

/** Checks every guarantee of the answers to task; returns them. */
function expectHonest(task: PathTask, sols: PathSolution[]): PathSolution[] {
  expect(sols.length).toBeGreaterThan(0);
  expect(sols.length).toBeLessThanOrEqual(10);
  const size = targetSize(task.targets);
  for (let s = 0; s < sols.length; s++) {
    const sol = sols[s];
    if (s > 0) expect(sol.error).toBeGreaterThanOrEqual(sols[s - 1].error);
    expect(sol.theta2.length).toBe(task.targets.length);
    let err = 0;
    let maxD = 0;
    sol.theta2.forEach((t, i) => {
      const P = placedCouplerPoint(sol.design, t);
      expect(P, `assembles at θ2[${i}]`).not.toBeNull();
      const d = Math.hypot(P!.x - task.targets[i].x, P!.y - task.targets[i].y);
      err += d * d;
      maxD = Math.max(maxD, d);
    });
    // Recomputed from the design: equal to rounding of the sum (relative 1e-12, absolute 1e-28 size²).
    expect(Math.abs(sol.error - err)).toBeLessThanOrEqual(1e-12 * err + 1e-28 * size * size);
    expect(Math.abs(sol.maxDistance - maxD)).toBeLessThanOrEqual(1e-12 * maxD + 1e-14 * size);
    const b = task.bounds;
    const { r1, r2, r3, r4 } = sol.design.links;
    if (b?.length)
      for (const r of [r1, r2, r3, r4]) expect(r >= b.length[0] && r <= b.length[1], `length ${r}`).toBe(true);
    if (b?.coupler !== undefined) expect(sol.design.pDist).toBeLessThanOrEqual(b.coupler);
    if (b?.pivot) {
      expect(sol.design.O2.x).toBeGreaterThanOrEqual(b.pivot.min.x);
      expect(sol.design.O2.x).toBeLessThanOrEqual(b.pivot.max.x);
      expect(sol.design.O2.y).toBeGreaterThanOrEqual(b.pivot.min.y);
      expect(sol.design.O2.y).toBeLessThanOrEqual(b.pivot.max.y);
    }
    if ((task.input ?? 'crank') === 'crank') expect(classify(sol.design.links).inputIsCrank).toBe(true);
    if (task.placement) {
      expect(sol.design.O2).toEqual(task.placement.O2);
      expect(sol.design.groundAngle).toBe(task.placement.groundAngle);
    }
    for (let q = 0; q < s; q++) {
      const a = sols[q].design;
      const d = sol.design;
      const same =
        a.branch === d.branch &&
        [
          a.links.r1 - d.links.r1,
          a.links.r2 - d.links.r2,
          a.links.r3 - d.links.r3,
          a.links.r4 - d.links.r4,
          a.O2.x - d.O2.x,
          a.O2.y - d.O2.y,
          a.pDist - d.pDist,
        ].every((x) => Math.abs(x) < 1e-9 * size);
      expect(same, `answers ${q} and ${s} are the same linkage`).toBe(false);
    }
  }
  return sols;
}

/** Free timing: the θ2 advance (radians, in (0, 2π]) from target i to i+1 in the turning direction. */
function advances(theta2: number[], dir: number): number[] {
  return theta2.slice(1).map((t, i) => {
    let d = dir * (t - theta2[i]);
    d = ((d % (2 * PI)) + 2 * PI) % (2 * PI);
    return d;
  });
}

describe('pathSynthesis', () => {
  it('finds a linkage through nine points of a known coupler curve (free timing) to rounding', async () => {
    const task: PathTask = {
      targets: exactTargets(EXACT_DESIGN, [0.3, 0.9, 1.4, 2.2, 2.9, 3.6, 4.3, 5.0, 5.7]),
      timing: { kind: 'free' },
    };
    const sols = expectHonest(task, await pathSynthesis(task, { seed: 1, budgetMs: 8000 }));
    const size = targetSize(task.targets);
    expect(sols[0].error).toBeLessThanOrEqual(EXACT_REL * size * size);
    // In order within one turn, turning one way.
    const ok = [1, -1].some((dir) => advances(sols[0].theta2, dir).reduce((a, b) => a + b, 0) <= 2 * PI + 1e-12);
    expect(ok).toBe(true);
  });

  it('finds a linkage through twelve points of a known coupler curve at a fixed step to rounding', async () => {
    const step = (25 * PI) / 180;
    const th = Array.from({ length: 12 }, (_, i) => -0.5 + i * step);
    const task: PathTask = { targets: exactTargets(EXACT_DESIGN, th), timing: { kind: 'step', step } };
    const sols = expectHonest(task, await pathSynthesis(task, { seed: 2, budgetMs: 8000 }));
    const size = targetSize(task.targets);
    expect(sols[0].error).toBeLessThanOrEqual(EXACT_REL * size * size);
    for (let i = 1; i < 12; i++) {
      const d = sols[0].theta2[i] - sols[0].theta2[i - 1] - step;
      expect(Math.abs(Math.atan2(Math.sin(d), Math.cos(d)))).toBeLessThan(1e-12);
    }
  });

  it('gives the known linkage back for given timing with a fixed placement', async () => {
    const th = [0.2, 1.1, 2.0, 3.1, 4.0, 5.2];
    const task: PathTask = {
      targets: exactTargets(EXACT_DESIGN, th),
      timing: { kind: 'given', theta2: th },
      placement: { O2: { x: EXACT_DESIGN.O2x, y: EXACT_DESIGN.O2y }, groundAngle: EXACT_DESIGN.g },
    };
    const sols = expectHonest(task, await pathSynthesis(task, { seed: 3, budgetMs: 8000 }));
    const size = targetSize(task.targets);
    expect(sols[0].error).toBeLessThanOrEqual(EXACT_REL * size * size);
    const d = sols[0].design;
    // 12 equations in 6 unknowns: the fit is the design itself (well conditioned here: 1e-9 of the size).
    for (const k of ['r1', 'r2', 'r3', 'r4'] as const)
      expect(Math.abs(d.links[k] - EXACT_DESIGN[k])).toBeLessThan(1e-9 * size);
    expect(Math.abs(d.pDist - Math.hypot(EXACT_DESIGN.u, EXACT_DESIGN.v))).toBeLessThan(1e-9 * size);
    expect(d.branch).toBe('open');
    sols[0].theta2.forEach((t, i) => expect(Math.abs(Math.sin((t - th[i]) / 2))).toBeLessThan(1e-12));
  });

  it('holds every answer to the bounds, the crank and the order', async () => {
    const task: PathTask = {
      targets: [20, 25, 30, 35, 40, 45].map((y) => ({ x: 20, y })),
      timing: { kind: 'free' },
      bounds: { length: [5, 30], coupler: 25, pivot: { min: { x: 0, y: 0 }, max: { x: 20, y: 20 } } },
    };
    expectHonest(task, await pathSynthesis(task, { seed: 4, budgetMs: 3000 }));
  });

  it("lets the input rock with input 'any', never passing a limit between targets", async () => {
    const th = [0.4, 0.6, 0.8, 1.0, 1.2];
    // A triple rocker: its input reaches only part of a turn.
    const rocker = { ...EXACT_DESIGN, r1: 4, r2: 3, r3: 3.5, r4: 3 };
    const task: PathTask = { targets: exactTargets(rocker, th), timing: { kind: 'given', theta2: th }, input: 'any' };
    const sols = expectHonest(task, await pathSynthesis(task, { seed: 5, budgetMs: 4000 }));
    const size = targetSize(task.targets);
    expect(sols[0].error).toBeLessThanOrEqual(EXACT_REL * size * size);
  });

  it('is deterministic for a seed', async () => {
    const task: PathTask = {
      targets: [1, 2, 3, 4, 5].map((v) => ({ x: v, y: v * v * 0.3 })),
      timing: { kind: 'free' },
    };
    const a = await pathSynthesis(task, { seed: 9, rounds: 6, budgetMs: 60000 });
    const b = await pathSynthesis(task, { seed: 9, rounds: 6, budgetMs: 60000 });
    expect(b).toEqual(a);
  });

  it('splits its global stage into parts that merge to the same answers as one run', async () => {
    // Twelve points of a spiral with given timing: no exact fit, so no part stops early.
    const th = Array.from({ length: 12 }, (_, i) => 0.4 * i);
    const targets = th.map((a, i) => ({ x: (1 + 0.2 * i) * Math.cos(a), y: (1 + 0.2 * i) * Math.sin(a) }));
    const task: PathTask = { targets, timing: { kind: 'given', theta2: th } };
    const whole = await pathSynthesisPart(task, { seed: 11, rounds: 6, budgetMs: 60000 });
    const p0 = await pathSynthesisPart(task, { seed: 11, rounds: 6, budgetMs: 60000, part: 0, parts: 2 });
    const p1 = await pathSynthesisPart(task, { seed: 11, rounds: 6, budgetMs: 60000, part: 1, parts: 2 });
    expect(p0.rounds + p1.rounds).toBe(whole.rounds);
    expect(mergePathCandidates(task, [p0.candidates, p1.candidates])).toEqual(
      mergePathCandidates(task, [whole.candidates]),
    );
  });

  it('returns the best so far soon after an abort', async () => {
    const task: PathTask = {
      targets: [0, 1, 2, 3, 4, 5, 6].map((v) => ({ x: v, y: Math.cos(v) })),
      timing: { kind: 'free' },
    };
    const controller = new AbortController();
    setTimeout(() => controller.abort(), 150);
    const t0 = Date.now();
    const sols = await pathSynthesis(task, { seed: 1, budgetMs: 20000, signal: controller.signal });
    // The search checks the signal every ~25 ms of work; the merge then polishes at most 24 candidates.
    expect(Date.now() - t0).toBeLessThan(1500);
    expect(sols.length).toBeGreaterThan(0);
  });

  it('reports a part’s best candidates after each round: merged after a stop they are honest answers (issue 34, 4)', async () => {
    // Twelve points on a figure eight: no exact fit, so the part would run its rounds; it is stopped after three.
    const task: PathTask = {
      targets: Array.from({ length: 12 }, (_, k) => {
        const t = (2 * PI * k) / 12;
        return { x: 3 * Math.sin(t), y: 1.5 * Math.sin(2 * t) };
      }),
      timing: { kind: 'free' },
    };
    const controller = new AbortController();
    const seen: PathProgress[] = [];
    const run = await pathSynthesisPart(task, {
      seed: 3,
      budgetMs: 60_000,
      signal: controller.signal,
      onProgress: (p) => {
        seen.push(p);
        if (seen.length === 3) controller.abort();
      },
    });
    expect(run.complete).toBe(false);
    const last = seen[seen.length - 1];
    // The report is the part's own list, best first, cut to PROGRESS_CANDIDATES: what a stopped part had found.
    expect(last.candidates!.length).toBeGreaterThan(0);
    expect(last.candidates).toEqual(run.candidates.slice(0, PROGRESS_CANDIDATES));
    const sols = expectHonest(task, mergePathCandidates(task, [last.candidates!]));
    // The merge polishes them: its best is no worse than the best the part reported (1e-12 relative: rounding).
    expect(sols[0].error).toBeLessThanOrEqual(last.best * (1 + 1e-12));
  });

  it('honours budgetMs and reports progress in [0, 1] with a non-increasing best', async () => {
    const task: PathTask = {
      targets: [0, 1, 2, 3, 4, 5, 6].map((v) => ({ x: v, y: Math.cos(v) })),
      timing: { kind: 'free' },
    };
    const seen: Array<{ fraction: number; best: number }> = [];
    const t0 = Date.now();
    await pathSynthesis(task, { seed: 1, budgetMs: 300, onProgress: (p) => seen.push(p) });
    expect(Date.now() - t0).toBeLessThan(1500);
    expect(seen.length).toBeGreaterThan(1);
    for (let i = 0; i < seen.length; i++) {
      expect(seen[i].fraction).toBeGreaterThanOrEqual(0);
      expect(seen[i].fraction).toBeLessThanOrEqual(1);
      if (i > 0) expect(seen[i].best).toBeLessThanOrEqual(seen[i - 1].best);
    }
    expect(seen[seen.length - 1].fraction).toBe(1);
  });

  it('rejects bad input with an error naming the parameter and the value', async () => {
    const ok = { targets: [{ x: 0, y: 0 }], timing: { kind: 'free' } } as PathTask;
    const bad: Array<[unknown, RegExp]> = [
      [{ ...ok, targets: 'abc' }, /task\.targets must be an array, got "abc"/],
      [{ ...ok, targets: [{ x: NaN, y: 0 }] }, /task\.targets\[0\]\.x must be a finite coordinate, got NaN/],
      [{ ...ok, timing: { kind: 'step', step: 0 } }, /task\.timing\.step must be a nonzero angle in radians, got 0/],
      [{ ...ok, timing: { kind: 'given', theta2: [1, 2] } }, /task\.timing\.theta2 must hold exactly 1 entries, got 2/],
      [{ ...ok, timing: { kind: 'later' } }, /task\.timing\.kind must be 'free', 'step' or 'given', got "later"/],
      [{ ...ok, bounds: { length: [5, 1] } }, /task\.bounds\.length must have min < max, got \[5, 1\]/],
      [{ ...ok, bounds: { coupler: -1 } }, /task\.bounds\.coupler must be a length >= 0, got -1/],
      [{ ...ok, input: 'rocker' }, /task\.input must be 'crank' or 'any', got "rocker"/],
      [
        { ...ok, placement: { O2: { x: 0, y: 0 }, groundAngle: Infinity } },
        /task\.placement\.groundAngle must be a finite angle in radians, got Infinity/,
      ],
    ];
    for (const [task, msg] of bad) await expect(pathSynthesis(task as PathTask)).rejects.toThrow(msg);
    await expect(pathSynthesis(ok, { budgetMs: -5 })).rejects.toThrow(
      /options\.budgetMs must be >= 0 milliseconds, got -5/,
    );
    await expect(pathSynthesis(ok, { rounds: 1.5 })).rejects.toThrow(
      /options\.rounds must be a positive integer, got 1\.5/,
    );
  });
});
