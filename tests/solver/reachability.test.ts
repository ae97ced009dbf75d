/**
 * The reachability verdict (issue 7, items 3 and 5): sweep, classify and inputRange must follow the
 * exact geometry of the double inputs to within a few ulps (tests/oracle/tolerance.ts slackTolerance)
 * and agree with each other on every input: the crank pin within ulps of O4 with |r3 - r4| of a few
 * ulps, flat chains (L = S + P + Q), change points, subnormal and extreme-ratio lengths. inputRange's
 * endpoints must be inputs sweep calls reachable (rounded inward). Fixed seeds.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { InputRange, Linkage, SweepMethod, SweepResult } from '../../src/solver';
import { classify, inputRange, sweep } from '../../src/solver';
import { referenceSlack, referenceSolve } from '../oracle/reference';
import { slackTolerance } from '../oracle/tolerance';
import { nextDown, nextUp, where } from './helpers';

/** The methods that decide reachability ('seed' is the report's NR, which has no such test). */
const DECIDING: readonly SweepMethod[] = ['closed-form', 'closed-form-polish', 'newton', 'newton-no-predictor'];

/** Whether sweep (every deciding method, both branches) calls theta2 reachable; they must all agree. */
function sweepReaches(l: Linkage, theta2: number): boolean {
  const verdicts = DECIDING.flatMap((method) =>
    (['open', 'crossed'] as const).map((branch) => reachable(sweep(l, [theta2], { branch, method }), 0)),
  );
  expect(new Set(verdicts).size, `methods disagree at ${where(l, theta2, '-')}`).toBe(1);
  return verdicts[0];
}

function reachable(r: SweepResult, i: number): boolean {
  return r.status[i] === 'ok' || r.status[i] === 'singular';
}

/** |A O4| for the tolerance (double precision is enough there). */
function pinDistance(l: Linkage, t2: number): number {
  return Math.hypot(l.r1 - l.r2 * Math.cos(t2), l.r2 * Math.sin(t2));
}

/** The verdict must be the exact one unless the true slack is within slackTolerance of zero. */
function expectExactVerdict(l: Linkage, t2: number, got: boolean, label: string): void {
  const slack = referenceSlack(l, t2);
  const tol = slackTolerance(l, t2, pinDistance(l, t2));
  if (Math.abs(slack) <= tol) return;
  expect(got, `${label} at ${where(l, t2, '-')}: slack ${slack} (tolerance ${tol})`).toBe(slack >= 0);
}

function inRange(range: InputRange, t2: number): boolean {
  if (range.full) return true;
  return range.intervals.some(({ lo, hi }) => {
    const x = lo + ((((t2 - lo) % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI));
    return x <= hi;
  });
}

/** The three functions agree: empty range iff 'cannot-assemble'; every endpoint reachable; the grid decided exactly. */
function expectAgreement(l: Linkage, label: string): void {
  const c = classify(l);
  const range = inputRange(l);
  expect(c.inputRange, `${label}: classify's range is inputRange's`).toEqual(range);
  expect(c.type === 'cannot-assemble', `${label}: cannot-assemble iff the range is empty`).toBe(
    range.intervals.length === 0,
  );
  for (const { lo, hi } of range.intervals) {
    expect(lo <= hi, `${label}: interval ${lo}..${hi}`).toBe(true);
    expect(sweepReaches(l, lo), `${label}: endpoint ${lo} must be reachable`).toBe(true);
    expect(sweepReaches(l, hi), `${label}: endpoint ${hi} must be reachable`).toBe(true);
  }
  const grid = [0, Math.PI, ...Array.from({ length: 24 }, (_, i) => -Math.PI + (i + 0.5) * (Math.PI / 12))];
  const probes = grid.concat(range.intervals.flatMap(({ lo, hi }) => [lo - 1e-6, hi + 1e-6, nextDown(lo), nextUp(hi)]));
  for (const t2 of probes) {
    const got = sweepReaches(l, t2);
    expectExactVerdict(l, t2, got, `${label}: sweep`);
    expectExactVerdict(l, t2, inRange(range, t2), `${label}: inputRange`);
  }
  if (range.intervals.length === 0) {
    for (const t2 of grid) expect(sweepReaches(l, t2), `${label}: cannot assemble, yet reachable at ${t2}`).toBe(false);
  }
}

const ulpsOf = (x: number, k: number) => x + k * x * Number.EPSILON;

describe('the reachability verdict', () => {
  it("is 'unreachable' for the issue's pin a few ulps from O4 with |r3 - r4| of 10-30 ulps", () => {
    // r1 = r2: the crank pin at theta2 = 2 ulps is 2 ulps from O4; r3 - r4 is 20 ulps.
    const l = { r1: 1, r2: 1, r3: 1, r4: ulpsOf(1, 20) };
    const t2 = 2 * Number.EPSILON;
    expect(referenceSlack(l, t2)).toBeLessThan(-10 * 2 ** -53);
    expect(sweepReaches(l, t2)).toBe(false);
  });

  it('follows the exact geometry with the crank pin within ulps of O4 and |r3 - r4| of a few ulps', () => {
    const base = fc.double({ min: 0.25, max: 4, noNaN: true });
    fc.assert(
      fc.property(
        base,
        fc.integer({ min: -4, max: 4 }),
        base,
        fc.integer({ min: -40, max: 40 }),
        fc.integer({ min: -12, max: 12 }),
        (r1, j, r3, d, m) => {
          const l = { r1, r2: ulpsOf(r1, j), r3, r4: ulpsOf(r3, d) };
          const t2 = m * Number.EPSILON;
          expectExactVerdict(l, t2, sweepReaches(l, t2), 'pin near O4');
          expectExactVerdict(l, t2, inRange(inputRange(l), t2), 'inputRange, pin near O4');
        },
      ),
      { seed: 7101, numRuns: 150 },
    );
  });

  it('agrees across classify, inputRange and sweep on flat chains L = S + P + Q (one reachable point)', () => {
    const small = fc.integer({ min: 1, max: 60 });
    fc.assert(
      fc.property(small, small, small, fc.nat(3), fc.integer({ min: -40, max: 40 }), (a, b, c, longest, e) => {
        const lengths = [a, b, c];
        lengths.splice(longest, 0, a + b + c);
        const [r1, r2, r3, r4] = lengths.map((x) => x * 2 ** e);
        const l = { r1, r2, r3, r4 };
        const c7 = classify(l);
        expect(c7.type, `flat chain ${where(l, 0, '-')}`).not.toBe('cannot-assemble');
        expect(c7.inputRange.intervals).toHaveLength(1);
        const { lo, hi } = c7.inputRange.intervals[0];
        expect(lo).toBe(hi);
        // Ground or crank longest: flat at theta2 = 0; coupler or rocker longest: at pi.
        expect(Math.abs(lo)).toBeCloseTo(longest < 2 ? 0 : Math.PI, 12);
        expectAgreement(l, 'flat chain');
      }),
      { seed: 7102, numRuns: 40 },
    );
  });

  it('agrees on hard case 22 (6, 1, 2, 3): only t2 = 0, flat at (0, 180 deg)', () => {
    const l = { r1: 6, r2: 1, r3: 2, r4: 3 };
    expectAgreement(l, 'case 22');
    const r = sweep(l, [0, 1e-8], { branch: 'open' });
    expect(r.status).toEqual(['ok', 'unreachable']);
    expect(Math.abs(r.theta3[0])).toBeLessThan(1e-12);
    expect(Math.abs(Math.abs(r.theta4[0]) - Math.PI)).toBeLessThan(1e-12);
  });

  it('agrees on subnormal lengths: (1, 1, 5e-324, 5e-324) can close, as can every such chain', () => {
    const l = { r1: 1, r2: 1, r3: 5e-324, r4: 5e-324 };
    expect(classify(l).type).not.toBe('cannot-assemble');
    expectAgreement(l, '(1, 1, 5e-324, 5e-324)');
    const tiny = fc.double({ min: 5e-324, max: 1e-300, noNaN: true });
    const normal = fc.double({ min: 0.1, max: 10, noNaN: true });
    fc.assert(
      fc.property(normal, normal, tiny, tiny, fc.nat(23), (a, b, c, d, k) => {
        const set = [a, b, c, d];
        const order = [k % 4, (k >> 2) % 4];
        [set[order[0]], set[order[1]]] = [set[order[1]], set[order[0]]];
        const l2 = { r1: set[0], r2: set[1], r3: set[2], r4: set[3] };
        expectAgreement(l2, 'subnormal links');
      }),
      { seed: 7103, numRuns: 40 },
    );
  });

  it('agrees on random and near-degenerate linkages (flat, change point, a few ulps either side)', () => {
    const len = fc.double({ min: -1.5, max: 1.5, noNaN: true }).map((u) => 10 ** u);
    const nearDegenerate = fc
      .record({ a: len, b: len, c: len, kind: fc.nat(3), ulps: fc.integer({ min: -4, max: 4 }), order: fc.nat(3) })
      .map(({ a, b, c, kind, ulps, order }) => {
        const d = [a + b + c, a + b - c, a - b + c, c][kind];
        if (!(d > 0)) return null;
        const set = [a, b, c, ulpsOf(d, ulps)];
        [set[3], set[order]] = [set[order], set[3]];
        return { r1: set[0], r2: set[1], r3: set[2], r4: set[3] };
      })
      .filter((x): x is Linkage => x !== null);
    fc.assert(
      fc.property(fc.oneof(fc.record({ r1: len, r2: len, r3: len, r4: len }), nearDegenerate), (l) =>
        expectAgreement(l, 'random'),
      ),
      { seed: 7104, numRuns: 60 },
    );
  });

  it('rounds ill-conditioned limits inward (near 0 and 180 deg, a coupler of 1e-9): sweep reaches every endpoint', () => {
    const cases: Linkage[] = [];
    for (let k = 1; k <= 30; k++) {
      cases.push({ r1: 4, r2: 1, r3: 3, r4: 2 - k * 1e-12 }); // hard case 6: limit near 180 deg
      cases.push({ r1: 1, r2: 1, r3: k * 1e-9, r4: 1 }); // hard case 20: a window 1.3e-7 rad wide
      cases.push({ r1: 6 + k * 1e-14, r2: 1, r3: 2, r4: 3 }); // just past flat: cannot assemble, empty range
      cases.push({ r1: 6 - k * 1e-14, r2: 1, r3: 2, r4: 3 }); // nearly flat, a window of 1e-7 rad around 0
    }
    // Near change points where the limit formula's own endpoint lies just outside (found by search).
    cases.push(
      { r1: 0.05788681828602587, r2: 0.06974167262634373, r3: 12.95727278095509, r4: 12.945417926614763 },
      { r1: 0.04706149133153012, r2: 0.04406964863120612, r3: 1.3574086296264811, r4: 1.3604004723268053 },
      { r1: 0.22901182983343774, r2: 0.14014681345413144, r3: 0.09228500999607983, r4: 0.18115002637538624 },
      { r1: 17.224350841320565, r2: 17.22330480749232, r3: 0.038759140504729256, r4: 0.037713106676483456 },
      { r1: 8.041871372842346, r2: 0.5770507606924712, r3: 8.35278596340239, r4: 0.266136170132431 },
      { r1: 25.007641182081695, r2: 24.951620123654013, r3: 0.1814051396963845, r4: 0.12538408126868278 },
      { r1: 4.2061172004974, r2: 4.764288651113628, r3: 0.7156278175206119, r4: 0.15745636690438322 },
    );
    for (const l of cases) {
      for (const { lo, hi } of inputRange(l).intervals) {
        expect(sweepReaches(l, lo), `lo ${lo} of ${where(l, lo, '-')}`).toBe(true);
        expect(sweepReaches(l, hi), `hi ${hi} of ${where(l, hi, '-')}`).toBe(true);
      }
    }
  });

  it('keeps hard case 13: fl(pi/2) reachable, the next double up not (0.86 ulp of slack)', () => {
    const l = { r1: 4, r2: 3, r3: 2.5, r4: 2.5 };
    expect(sweepReaches(l, Math.PI / 2)).toBe(true);
    expect(sweepReaches(l, nextUp(Math.PI / 2))).toBe(false);
    expect(referenceSolve(l, nextUp(Math.PI / 2), 1).kind).toBe('unreachable');
  });
});
