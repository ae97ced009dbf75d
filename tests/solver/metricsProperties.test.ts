/**
 * Property tests of the design metrics over random linkages (fast-check, fixed seed, reproducible):
 * lengths log-uniform over four decades, and random Grashof crank-rockers (r2 the strictly shortest
 * link, S + L < P + Q). Oracle and tolerances: tests/oracle/metrics.ts, metricsTolerance.ts and, for
 * poses, tolerance.ts.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Branch, Linkage } from '../../src/solver';
import {
  designMetrics,
  instantCenters,
  solveClosedForm,
  sweep,
  transmissionAngle,
  velocityRatios,
} from '../../src/solver';
import { angleTol, omega4AtDeadCentreTol } from '../oracle/metricsTolerance';
import { angleDiff, referenceLimits } from '../oracle/reference';
import type { ReferencePose } from '../oracle/reference';
import { angleTolerance, EPS } from '../oracle/tolerance';
import { oracle, oracleOutcome, sigmaOf, where } from './helpers';
import { expectCentersMatchOracle, expectMatchesOracle, expectNear } from './metricsHelpers';

const RUNS = { seed: 10, numRuns: 120 } as const;
/** Dense cycle: 0.1 deg steps over one turn. */
const DENSE = Array.from({ length: 3601 }, (_, i) => -Math.PI + (i * 2 * Math.PI) / 3600);

const length = fc.double({ min: -2, max: 2, noNaN: true }).map((u) => 10 ** u);
const linkageArb: fc.Arbitrary<Linkage> = fc.record({ r1: length, r2: length, r3: length, r4: length });
const branchArb = fc.constantFrom<Branch>('open', 'crossed');

/**
 * A Grashof crank-rocker: r1, r3, r4 random, r2 a fraction u of min(r1, r3, r4, P + Q - L) so that it is
 * the strictly shortest link and r2 + L < P + Q.
 */
const crankRockerArb: fc.Arbitrary<Linkage> = fc
  .record({ r1: length, r3: length, r4: length, u: fc.double({ min: 0.001, max: 0.999, noNaN: true }) })
  .map(({ r1, r3, r4, u }) => {
    const [p, q, big] = [r1, r3, r4].sort((a, b) => a - b);
    const room = Math.min(p, p + q - big);
    return room > 0 ? { r1, r2: u * room, r3, r4 } : null;
  })
  .filter((l): l is Linkage => l !== null);

/** The pose facts tolerance.ts needs, from a solved pose in double (no oracle call per sweep point). */
function poseFacts(l: Linkage, theta2: number, theta3: number, theta4: number): ReferencePose {
  const s = Math.hypot(l.r1 - l.r2 * Math.cos(theta2), l.r2 * Math.sin(theta2));
  return { theta3, theta4, sinMu: Math.sin(theta4 - theta3), s };
}

/** Bound on the error of mu = |theta4 - theta3| at a pose, from the pose's conditioning. */
function muTol(l: Linkage, facts: ReferencePose): number {
  const t = angleTolerance(l, facts);
  return t.theta3 + t.theta4 + 4 * EPS;
}

describe('designMetrics (properties)', () => {
  it('matches the oracle on random linkages of every class, both branches', () => {
    fc.assert(
      fc.property(linkageArb, branchArb, (l, b) => {
        expectMatchesOracle(l, b);
      }),
      RUNS,
    );
  });

  it('matches the oracle on random crank-rockers: dead centres, swing and time ratio', () => {
    fc.assert(
      fc.property(crankRockerArb, branchArb, (l, b) => {
        const m = expectMatchesOracle(l, b);
        expect(m.output, where(l, 0, b)).not.toBeNull();
      }),
      RUNS,
    );
  });

  it('bounds the transmission angle along a dense sweep, and reaches both extremes', () => {
    fc.assert(
      fc.property(fc.oneof(linkageArb, crankRockerArb), branchArb, (l, b) => {
        const { transmission: t } = designMetrics(l, b);
        if (referenceLimits(l).empty) return;
        const t2s = [...DENSE, t.theta2AtMin, -t.theta2AtMin, t.theta2AtMax, -t.theta2AtMax];
        const res = sweep(l, t2s, { branch: b });
        const outside: string[] = [];
        for (let i = 0; i < t2s.length; i++) {
          if (res.status[i] !== 'ok') continue;
          const pose = { theta3: res.theta3[i], theta4: res.theta4[i] };
          const mu = transmissionAngle(pose);
          const tol = muTol(l, poseFacts(l, t2s[i], pose.theta3, pose.theta4));
          if (mu < t.min - tol || mu > t.max + tol) outside.push(`mu = ${mu} at ${where(l, t2s[i], b)}`);
        }
        expect(outside, `mu outside [${t.min}, ${t.max}]`).toEqual([]);
        for (const [theta2, value, name] of [
          [t.theta2AtMin, t.min, 'min'],
          [t.theta2AtMax, t.max, 'max'],
        ] as const) {
          // A limit angle may round just outside the reachable range; then its neighbour is checked by the sweep.
          const pose = solveClosedForm(l, theta2, b);
          if (!pose) continue;
          const mu = transmissionAngle(pose);
          const tol = muTol(l, poseFacts(l, theta2, pose.theta3, pose.theta4));
          expectNear(mu, value, tol, `mu at theta2At${name} ${where(l, theta2, b)}`);
        }
      }),
      RUNS,
    );
  });

  it('has the rocker standing still (w4 = 0) and turning back at each dead centre', () => {
    fc.assert(
      fc.property(crankRockerArb, branchArb, (l, b) => {
        const { output } = designMetrics(l, b);
        const sigma = sigmaOf(b);
        for (const [name, dc, side] of [
          ['extended', output!.extended, 1], // rocker minimum on the open branch (mirror: maximum)
          ['folded', output!.folded, -1],
        ] as const) {
          const ctx = `${name} dead centre at ${where(l, dc.theta2, b)}`;
          const pose = solveClosedForm(l, dc.theta2, b);
          expect(pose, ctx).not.toBeNull();
          const ref = oracle(l, dc.theta2, b);
          const e3 = angleTolerance(l, ref).theta3;
          const w4 = velocityRatios(l, dc.theta2, pose!).dTheta4;
          const tol = omega4AtDeadCentreTol(l.r2, l.r4, ref.sinMu, e3, angleTol(dc.theta2));
          expect(Math.abs(w4), `${ctx}: w4 / w2 = ${w4} (tol ${tol})`).toBeLessThanOrEqual(tol);
          // theta4 on both sides lies on the same side of the dead-centre angle: it is a turning point.
          for (const h of [-1e-2, 1e-2]) {
            const near = solveClosedForm(l, dc.theta2 + h, b);
            if (!near) continue;
            const tol4 = angleTolerance(l, oracle(l, dc.theta2 + h, b)).theta4 + angleTol(dc.theta4);
            const offset = side * sigma * angleDiff(near.theta4, dc.theta4);
            expect(offset, `${ctx}: theta4 at theta2 ${h > 0 ? '+' : '-'} ${Math.abs(h)}`).toBeGreaterThanOrEqual(
              -tol4,
            );
          }
        }
      }),
      RUNS,
    );
  });

  it('keeps the rocker between its dead-centre angles over a dense sweep, reaching both', () => {
    fc.assert(
      fc.property(crankRockerArb, branchArb, (l, b) => {
        const { output } = designMetrics(l, b);
        const { extended, folded, swing } = output!;
        const t2s = [...DENSE, extended.theta2, folded.theta2];
        const res = sweep(l, t2s, { branch: b });
        const sigma = sigmaOf(b);
        let lo = Infinity;
        let hi = -Infinity;
        const outside: string[] = [];
        for (let i = 0; i < t2s.length; i++) {
          if (res.status[i] !== 'ok') {
            outside.push(`${res.status[i]} at ${where(l, t2s[i], b)}: a crank turns fully`);
            continue;
          }
          // Rocker angle measured from the extended dead centre toward the folded one.
          const x = sigma * angleDiff(res.theta4[i], extended.theta4);
          const facts = poseFacts(l, t2s[i], res.theta3[i], res.theta4[i]);
          const tol = angleTolerance(l, facts).theta4 + angleTol(extended.theta4) + angleTol(swing);
          if (x < -tol || x > swing + tol) outside.push(`rocker at ${x} of swing ${swing}, ${where(l, t2s[i], b)}`);
          lo = Math.min(lo, x);
          hi = Math.max(hi, x);
        }
        expect(outside).toEqual([]);
        const reach = 1e-9 * Math.max(1, swing);
        expect(lo, 'extended dead centre reached').toBeLessThanOrEqual(reach);
        expect(hi, 'folded dead centre reached').toBeGreaterThanOrEqual(swing - reach);
      }),
      RUNS,
    );
  });

  it('gives a time ratio of 1 (to rounding) when r1^2 + r2^2 = r3^2 + r4^2 exactly', () => {
    // Integer lengths from Brahmagupta-Fibonacci: (a^2 + b^2)(c^2 + d^2) = (ac - bd)^2 + (ad + bc)^2
    // = (ac + bd)^2 + (ad - bc)^2, so {r1, r2} and {r3, r4} from the two pairs satisfy it exactly
    // (and still exactly after a power-of-two scale).
    const equalSquaresArb = fc
      .record({
        a: fc.integer({ min: 1, max: 60 }),
        b: fc.integer({ min: 1, max: 60 }),
        c: fc.integer({ min: 1, max: 60 }),
        d: fc.integer({ min: 1, max: 60 }),
        swapFirst: fc.boolean(),
        swapSecond: fc.boolean(),
        k: fc.integer({ min: -60, max: 60 }),
      })
      .map(({ a, b, c, d, swapFirst, swapSecond, k }) => {
        const p = [Math.abs(a * c - b * d), a * d + b * c];
        const q = [a * c + b * d, Math.abs(a * d - b * c)];
        const [r1, r2] = swapFirst ? [p[1], p[0]] : p;
        const [r3, r4] = swapSecond ? [q[1], q[0]] : q;
        const s = 2 ** k;
        return { r1: r1 * s, r2: r2 * s, r3: r3 * s, r4: r4 * s };
      })
      .filter((l) => {
        if (!(l.r2 > 0 && l.r2 < l.r1 && l.r2 < l.r3 && l.r2 < l.r4)) return false;
        const [, p, q, big] = [l.r1, l.r2, l.r3, l.r4].sort((x, y) => x - y);
        return l.r2 + big <= p + q;
      });
    fc.assert(
      fc.property(equalSquaresArb, branchArb, (l, b) => {
        const { timeRatio } = designMetrics(l, b);
        expectNear(timeRatio!, 1, 2 * EPS, `time ratio of ${where(l, 0, b)}`);
      }),
      RUNS,
    );
  });

  it('gives a time ratio greater than 1 whenever r1^2 + r2^2 differs from r3^2 + r4^2', () => {
    fc.assert(
      fc.property(crankRockerArb, branchArb, (l, b) => {
        const sq = l.r1 ** 2 + l.r2 ** 2 + l.r3 ** 2 + l.r4 ** 2;
        // Judged in double: keep differences well above its rounding.
        fc.pre(Math.abs(l.r1 ** 2 + l.r2 ** 2 - l.r3 ** 2 - l.r4 ** 2) > 1e-9 * sq);
        expect(designMetrics(l, b).timeRatio!, where(l, 0, b)).toBeGreaterThan(1);
      }),
      RUNS,
    );
  });
});

describe('instantCenters (properties)', () => {
  it('matches the oracle at random reachable poses of random linkages', () => {
    const theta2Arb = fc.double({ min: -Math.PI, max: Math.PI, noNaN: true });
    fc.assert(
      fc.property(fc.oneof(linkageArb, crankRockerArb), theta2Arb, branchArb, (l, theta2, b) => {
        if (oracleOutcome(l, theta2, b).kind !== 'unique') return;
        const pose = solveClosedForm(l, theta2, b);
        if (!pose) return;
        expectCentersMatchOracle(l, theta2, pose, 'random');
        // Both centres are finite points or null, never NaN.
        const { I13, I24 } = instantCenters(l, theta2, pose);
        for (const p of [I13, I24]) if (p) expect(Number.isFinite(p.x) && Number.isFinite(p.y)).toBe(true);
      }),
      RUNS,
    );
  });
});
