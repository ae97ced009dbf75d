/**
 * Path synthesis at the literature's level (issue 34 item 6): the prescribed-timing semicircle, whose best fit with a
 * crank input lies on the Grashof face (a crank at its change point), and the pieces that let the local solve reach
 * it: the projection onto the cones of full-turning inputs and the faces held as equalities by Levenberg–Marquardt.
 * Every Σd² asserted is recomputed here by the 50-digit oracle (couplerOracle.ts), not read from the code.
 */
import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import { classify } from '../../src/solver';
import { mergePathCandidates, pathSynthesis, pathSynthesisPart } from '../../src/synthesis';
import type { PathTask, PlacedFourBar } from '../../src/synthesis';
import { levenbergMarquardt } from '../../src/synthesis/levenbergMarquardt';
import type { LeastSquaresProblem } from '../../src/synthesis/levenbergMarquardt';
import { projectCrank, turnsFully } from '../../src/synthesis/pathProblem';
import { BENCHMARK_CASES } from './benchmarkCases';
import { oracleError } from './couplerOracle';

const D = Decimal.clone({ precision: 50 });

const timed = BENCHMARK_CASES.find((c) => c.id === 'semicircle-6-timed')!;
const cabrera = BENCHMARK_CASES.find((c) => c.id === 'cabrera-5-timed')!;

/**
 * The best design this search finds for cabrera-5-timed (seed 1, 20 rounds; seeds 1 to 5 agree to ten digits): no
 * published design could be checked (benchmarkCases.ts), so it is the reference, its Σd² recomputed by the oracle.
 * Its lengths sit on the Grashof face (r2 + r3 = r1 + r4 to 3e-9) and |AP| on its bound 50.
 */
const CABRERA_BEST: PlacedFourBar = {
  links: { r1: 9.23152317676933, r2: 0.7735064128313157, r3: 15.95165542875874, r4: 7.497612518766188 },
  branch: 'open',
  O2: { x: -31.887441018279638, y: 37.72957826467321 },
  groundAngle: 1.329839471157847,
  pDist: 49.99999999999999,
  pAngle: -2.2445060360176874,
};

/** Holds the design to the task's bounds and crank input (what the papers ask of theirs). */
function expectWithinTask(design: PlacedFourBar, task: PathTask): void {
  const b = task.bounds!;
  for (const r of Object.values(design.links)) expect(r >= b.length![0] && r <= b.length![1]).toBe(true);
  expect(design.pDist).toBeLessThanOrEqual(b.coupler!);
  expect(design.O2.x >= b.pivot!.min.x && design.O2.x <= b.pivot!.max.x).toBe(true);
  expect(design.O2.y >= b.pivot!.min.y && design.O2.y <= b.pivot!.max.y).toBe(true);
  expect(classify(design.links).inputIsCrank).toBe(true);
}

describe('pathSynthesis on the prescribed-timing semicircle (issue 34, 6)', () => {
  it('reaches the best published Σd² 1.21622 within three rounds, by the oracle’s count', async () => {
    // Before the crank cone was projected and held, every seed stopped at 1.2191 on the Grashof face.
    for (const seed of [1, 2, 3, 4, 5]) {
      const sols = await pathSynthesis(timed.task, { seed, rounds: 3, budgetMs: 60_000 });
      const best = sols[0];
      expectWithinTask(best.design, timed.task);
      const f = oracleError(best.design, best.theta2, timed.task.targets);
      // The reported error is the design's own (relative 1e-12: sums of six squares of doubles).
      expect(Math.abs(f - best.error)).toBeLessThan(1e-12 * f);
      expect(f).toBeLessThanOrEqual(timed.published.claim!);
    }
  });
});

describe('pathSynthesis on the prescribed-timing five points of Cabrera et al. (issue 34, 6)', () => {
  it('reaches the reference design’s Σd² in the global stage alone, from every seed', async () => {
    const theta2 = (cabrera.task.timing as { theta2: number[] }).theta2;
    const reference = oracleError(CABRERA_BEST, theta2, cabrera.task.targets);
    // The reference, recomputed at 50 digits: the value the bench's table shows for every seed.
    expect(reference).toBeGreaterThan(2.46586e-7);
    expect(reference).toBeLessThan(2.46587e-7);
    for (const seed of [1, 2, 3, 4, 5]) {
      // 24 rounds: the first round that reaches the reference is 3, 2, 2, 19 and 3 for seeds 1 to 5 (0 to 7 for
      // seeds 6 to 12); a 10 s run does hundreds on an idle core and ~14 at a load of 30 on two cores.
      const part = await pathSynthesisPart(cabrera.task, { seed, rounds: 24, budgetMs: 60_000 });
      // A merge with no time to polish (deadline 0): what a run on a busy machine gets when its budget is spent.
      // Before the rounds went on with their best start, 12 rounds of seeds 1 to 3 stopped at 7.8e-7, 9.2e-7 and
      // 2.1e-6 here.
      const best = mergePathCandidates(cabrera.task, [part.candidates], 0)[0];
      const f = oracleError(best.design, best.theta2, cabrera.task.targets);
      // At the reference to 1e-9 relative: the residuals are ~2e-4, so their squares' sum is good to ~1e-11.
      expect(f, `seed ${seed}`).toBeLessThanOrEqual(reference * (1 + 1e-9));
    }
  });
});

describe('projectCrank', () => {
  it('leaves lengths that turn fully alone and moves others a little inside the nearer cone', () => {
    const inside = Float64Array.from([9, 2, 7, 6, 7, 0]);
    projectCrank(inside, 0, 0.01, 50);
    expect(Array.from(inside)).toEqual([9, 2, 7, 6, 7, 0]);
    // r2 = 1.4 shortest, but 1.4 + 50 > 49.9 + 1.45: just past the change point of a crank-rocker.
    const x = Float64Array.from([0, 0, 0, 49.9, 1.4, 1.45, 50]);
    projectCrank(x, 3, 1e-6, 50);
    const [r1, r2, r3, r4] = Array.from(x.subarray(3));
    expect(turnsFully(r1, r2, r3, r4)).toBe(true);
    expect(r1 + r2 + r3 + r4).toBeGreaterThan(0);
    for (const r of [r1, r2, r3, r4]) expect(r <= 50 && r >= 1e-6).toBe(true);
    // The Euclidean distance to the face r1 + r3 − r2 − r4 = 0 is 0.05 / 2: the projection moves that far, plus
    // the margin it keeps inside (4e-9 of the perimeter, 4e-7 here, over |a| = 2), not more.
    const moved = Math.hypot(r1 - 49.9, r2 - 1.4, r3 - 1.45, r4 - 50);
    expect(moved).toBeGreaterThan(0.025);
    expect(moved).toBeLessThan(0.025 + 3e-7);
    expect(x[0] + x[1] + x[2]).toBe(0);
  });
});

describe('levenbergMarquardt with faces', () => {
  /** min (x − 3)² + (10 y)² subject to x + y ≤ 2: on the face, x = 406/202, y = 2 − x (f = 100 y² + (x − 3)²). */
  function faced(withFaces: boolean): LeastSquaresProblem {
    return {
      m: 2,
      k: 2,
      lo: Float64Array.from([-Infinity, -Infinity]),
      hi: Float64Array.from([Infinity, Infinity]),
      evaluate(x, r, J) {
        r[0] = x[0] - 3;
        r[1] = 10 * x[1];
        if (J) {
          J[0] = 1;
          J[1] = 0;
          J[2] = 0;
          J[3] = 10;
        }
        return true;
      },
      project(x) {
        const g = 2 - x[0] - x[1];
        if (g < 0) {
          x[0] += g / 2;
          x[1] += g / 2;
        }
      },
      feasible: (x) => x[0] + x[1] <= 2,
      faces: withFaces ? () => [{ a: Float64Array.from([-1, -1]), c: -2 }] : undefined,
    };
  }

  it('slides along an active linear face to the constrained minimum in a few iterations', () => {
    const r = levenbergMarquardt(faced(true), Float64Array.from([0, 0]), { maxIterations: 8 });
    const x = new D(406).div(202);
    const y = new D(2).minus(x);
    const f = x.minus(3).pow(2).plus(y.times(10).pow(2)).toNumber();
    expect(Math.abs(r.x[0] - x.toNumber())).toBeLessThan(1e-12);
    expect(Math.abs(r.x[1] - y.toNumber())).toBeLessThan(1e-12);
    expect(Math.abs(r.f - f)).toBeLessThan(1e-12 * f);
  });
});
