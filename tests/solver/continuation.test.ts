/**
 * NR continuation ('newton', 'newton-no-predictor') against the 60-digit oracle and the error bound
 * 1e-12 + 50 u (L / min(r3, r4)) / |sin mu| (tests/oracle/tolerance.ts errorBound), on the classes of
 * issue 7, item 2: sweeps that start at or next to a fold (an input limit), at a change point or a
 * parallelogram's crossing, and sweeps over 100 turns or far from zero. Each point must be within the
 * bound wherever the closed form is (checked alongside), with the reachability verdict of the exact
 * geometry (tests/oracle/tolerance.ts slackTolerance), and ordinary 1-degree sweeps must take at most
 * 2 iterations a point. Fixed seeds.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Branch, Linkage, SweepMethod } from '../../src/solver';
import { classify, sweep } from '../../src/solver';
import { angleDiff, referenceSlack } from '../oracle/reference';
import { errorBound, slackTolerance } from '../oracle/tolerance';
import { oracleOutcome, where } from './helpers';

const NR: readonly SweepMethod[] = ['newton', 'newton-no-predictor'];
const DEG = Math.PI / 180;

/** Worst error / bound over a sweep, after asserting every verdict and every 'ok' pose. */
function checkSweep(l: Linkage, t2s: number[], branch: Branch, method: SweepMethod, label: string): number {
  const r = sweep(l, t2s, { branch, method });
  let worst = 0;
  for (let i = 0; i < t2s.length; i++) {
    const t2 = t2s[i];
    const ctx = `${label} ${method} point ${i} at ${where(l, t2, branch)}`;
    const ref = oracleOutcome(l, t2, branch);
    const ok = r.status[i] === 'ok';
    if (ref.kind === 'continuum') continue;
    if ((ref.kind === 'unique') !== ok) {
      // Either verdict is right only within a few ulps of a limit (the exact geometry decides beyond).
      const slack = referenceSlack(l, t2);
      const s = ref.kind === 'unique' ? ref.pose.s : Math.hypot(l.r1 - l.r2 * Math.cos(t2), l.r2 * Math.sin(t2));
      expect(Math.abs(slack), `${ctx}: status ${r.status[i]} but oracle ${ref.kind}`).toBeLessThanOrEqual(
        slackTolerance(l, t2, s),
      );
      continue;
    }
    if (ref.kind !== 'unique') continue;
    const e = Math.max(
      Math.abs(angleDiff(r.theta3[i], ref.pose.theta3)),
      Math.abs(angleDiff(r.theta4[i], ref.pose.theta4)),
    );
    const bound = errorBound(l, ref.pose);
    expect(e, `${ctx}: error ${e} rad above the bound ${bound}`).toBeLessThanOrEqual(bound);
    expect(r.theta3[i] > -Math.PI && r.theta3[i] <= Math.PI, `${ctx}: theta3 not wrapped`).toBe(true);
    worst = Math.max(worst, e / bound);
  }
  return worst;
}

/** Every NR method and the closed form on the same sweep. */
function checkAll(l: Linkage, t2s: number[], branch: Branch, label: string): void {
  for (const m of [...NR, 'closed-form' as const]) checkSweep(l, t2s, branch, m, label);
}

const length = fc.double({ min: -1.5, max: 1.5, noNaN: true }).map((u) => 10 ** u);
const linkageArb = fc.record({ r1: length, r2: length, r3: length, r4: length });
const branchArb = fc.constantFrom<Branch>('open', 'crossed');

/** A linkage whose input stops at limits, with one limit angle (an exact fold of the sweep). */
const foldArb = fc
  .record({ l: linkageArb, pick: fc.nat(3) })
  .map(({ l, pick }) => {
    const range = classify(l).inputRange;
    if (range.full || range.intervals.length === 0) return null;
    const iv = range.intervals[pick % range.intervals.length];
    if (iv.hi - iv.lo < 1e-3) return null;
    const atLo = pick >= 2;
    return { l, t0: atLo ? iv.lo : iv.hi, dir: atLo ? 1 : -1, span: iv.hi - iv.lo };
  })
  .filter((x): x is { l: Linkage; t0: number; dir: number; span: number } => x !== null);

describe('NR continuation sweeps', () => {
  it('stay within the bound from a start exactly at a fold or within 1e-12..1e-3 rad of it', () => {
    fc.assert(
      fc.property(
        foldArb,
        fc.constantFrom(0, 1e-12, 1e-8, 1e-3),
        fc.constantFrom(0.1, 1, 3),
        branchArb,
        ({ l, t0, dir, span }, offset, stepDeg, branch) => {
          const step = Math.min(stepDeg * DEG, span / 30);
          const start = t0 + dir * Math.min(offset, span / 4);
          const t2s = Array.from({ length: 25 }, (_, i) => start + dir * i * step);
          checkAll(l, t2s, branch, 'fold start');
        },
      ),
      { seed: 7001, numRuns: 30 },
    );
  });

  it('stay within the bound from a change point, a parallelogram crossing or a kite fold, both ways', () => {
    const small = fc.integer({ min: 1, max: 12 });
    const changePoint = fc
      .record({
        a: small,
        b: small,
        c: small,
        order: fc.nat(23),
        kind: fc.constantFrom('any', 'parallelogram', 'kite'),
      })
      .map(({ a, b, c, order, kind }) => {
        // S + L = P + Q exactly: {a, b, c, a + b - c} in integers, or the two-pair families.
        const set =
          kind === 'parallelogram'
            ? [a + 1, b, a + 1, b]
            : kind === 'kite'
              ? [a, a, b + 1, b + 1]
              : [a + 1, b + 1, c, a + b + 2 - c];
        if (set.some((x) => x <= 0)) return null;
        const perm = permutation(order);
        const [r1, r2, r3, r4] = perm.map((k) => set[k]);
        return kind === 'any' ? { r1, r2, r3, r4 } : { r1: set[0], r2: set[1], r3: set[2], r4: set[3] };
      })
      .filter((x): x is Linkage => x !== null);
    fc.assert(
      fc.property(
        changePoint,
        fc.constantFrom(0, Math.PI),
        fc.constantFrom(1, -1),
        fc.constantFrom(0.5, 1, 5),
        branchArb,
        (l, t0, dir, stepDeg, branch) => {
          const t2s = Array.from({ length: 25 }, (_, i) => t0 + dir * i * stepDeg * DEG);
          checkAll(l, t2s, branch, 'change-point start');
        },
      ),
      { seed: 7002, numRuns: 30 },
    );
  });

  it('stay within the bound over 100 turns and at 1.3e5 rad, at most 2 iterations a point at 1 deg steps', () => {
    const crank = fc
      .record({ l: linkageArb, t0: fc.double({ min: -2e5, max: 2e5, noNaN: true }), branch: branchArb })
      .filter(({ l }) => classify(l).inputRange.full);
    fc.assert(
      fc.property(crank, ({ l, t0, branch }) => {
        const n = 36001;
        const grid = new Float64Array(n);
        for (let i = 0; i < n; i++) grid[i] = t0 + i * DEG;
        // Ordinary sweeps: the transmission angle stays away from 0 and 180 deg.
        const cf = sweep(l, grid, { branch });
        let minSin = 1;
        for (let i = 0; i < n; i++) minSin = Math.min(minSin, Math.abs(Math.sin(cf.theta4[i] - cf.theta3[i])));
        for (const m of NR) {
          const r = sweep(l, grid, { branch, method: m });
          expect(
            r.status.every((s) => s === 'ok'),
            `${m} at ${where(l, t0, branch)}`,
          ).toBe(true);
          if (minSin >= 0.2) {
            expect(r.totalIterations / n, `${m} iterations a point`).toBeLessThanOrEqual(m === 'newton' ? 1.2 : 2.05);
          }
        }
        // The oracle on every 250th point, the last turn included (the error must not grow with the distance).
        for (const m of NR) {
          const r = sweep(l, grid, { branch, method: m });
          for (let i = 0; i < n; i += 250) expectClose(l, grid[i], branch, r.theta3[i], r.theta4[i], `${m} point ${i}`);
          for (let i = n - 40; i < n; i++) expectClose(l, grid[i], branch, r.theta3[i], r.theta4[i], `${m} point ${i}`);
        }
      }),
      { seed: 7003, numRuns: 6 },
    );
  });

  it('follow the double crank (1, 2, sqrt(5.25), 1.5) from 130 000 rad as accurately as from 0', () => {
    const l = { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 };
    for (const branch of ['open', 'crossed'] as const) {
      checkAll(
        l,
        Array.from({ length: 200 }, (_, i) => 130000 + i * DEG),
        branch,
        '130000 rad',
      );
      const far = sweep(
        l,
        Array.from({ length: 3601 }, (_, i) => i * 10 * DEG),
        { branch, method: 'newton' },
      );
      expect(far.totalIterations / 3601).toBeLessThanOrEqual(2.5);
    }
  });

  it('keep a double crank within the bound after 130 000 rad of travel (20 700 turns), at about 1 iteration a point', () => {
    const l = { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 };
    const n = 745_000; // 10 deg steps
    const grid = new Float64Array(n).map((_, i) => i * 10 * DEG);
    for (const m of NR) {
      const r = sweep(l, grid, { branch: 'open', method: m });
      expect(r.totalIterations / n, `${m} iterations a point`).toBeLessThanOrEqual(m === 'newton' ? 2.5 : 3.5);
      for (let i = n - 30; i < n; i++) expectClose(l, grid[i], 'open', r.theta3[i], r.theta4[i], `${m} point ${i}`);
    }
  });

  it('start at the triple rocker 4-3-3.5-3 limit (hard case 10) and leave it at 1 deg steps within the bound', () => {
    const l = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
    const lim = classify(l).inputRange.intervals[0].hi;
    for (const branch of ['open', 'crossed'] as const) {
      checkAll(
        l,
        Array.from({ length: 60 }, (_, i) => lim - i * DEG),
        branch,
        'limit start',
      );
    }
  });
});

function expectClose(l: Linkage, t2: number, branch: Branch, t3: number, t4: number, label: string): void {
  const ref = oracleOutcome(l, t2, branch);
  if (ref.kind !== 'unique') return;
  const e = Math.max(Math.abs(angleDiff(t3, ref.pose.theta3)), Math.abs(angleDiff(t4, ref.pose.theta4)));
  expect(e, `${label} at ${where(l, t2, branch)}`).toBeLessThanOrEqual(errorBound(l, ref.pose));
}

/** The k-th permutation of [0, 1, 2, 3] (k in 0..23). */
function permutation(k: number): number[] {
  const pool = [0, 1, 2, 3];
  const out: number[] = [];
  let r = k;
  for (let n = 4; n > 0; n--) {
    const f = [1, 1, 2, 6][n - 1];
    out.push(pool.splice(Math.floor(r / f), 1)[0]);
    r %= f;
  }
  return out;
}
