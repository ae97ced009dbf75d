/**
 * Property tests over random linkages (fast-check, fixed seed, reproducible): lengths log-uniform
 * over four decades, any input angle, both branches. The oracle and the conditioning tolerances are
 * those of tests/oracle. Points within a margin of a limit position are excluded where a decision
 * (reachable or not) is asserted: there the answer legitimately depends on the last few ulps.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Branch, InputRange, Linkage } from '../../src/solver';
import { classify, solveClosedForm, solveNewton, sweep } from '../../src/solver';
import { angleDiff, referenceLimits, referenceSlack } from '../oracle/reference';
import { angleTolerance, limitTolerance } from '../oracle/tolerance';
import { expectPose, loopResidual, oracle, oracleOutcome, scaled, sigmaOf, size, where } from './helpers';

const RUNS = { seed: 42, numRuns: 300 } as const;
/** Loop closure accepted for any returned pose, relative to r1 + r2 + r3 + r4 (brief: 1e-12). */
const CLOSURE_REL = 1e-12;
/** A decision about reachability is asserted only if the slack is at least this fraction of the size. */
const SLACK_MARGIN = 1e-9;

const length = fc.double({ min: -2, max: 2, noNaN: true }).map((u) => 10 ** u);
const linkageArb: fc.Arbitrary<Linkage> = fc.record({ r1: length, r2: length, r3: length, r4: length });
const angleArb = fc.double({ min: -Math.PI, max: Math.PI, noNaN: true });
const branchArb = fc.constantFrom<Branch>('open', 'crossed');

/**
 * A linkage with a theta2 it can reach, drawn inside the oracle's reachable band of |theta2|
 * (so most runs exercise a real pose rather than an unreachable one).
 */
const reachableArb = fc
  .record({
    l: linkageArb,
    u: fc.double({ min: 0.001, max: 0.999, noNaN: true }),
    sign: fc.constantFrom(1, -1),
    branch: branchArb,
  })
  .map(({ l, u, sign, branch }) => {
    const lim = referenceLimits(l);
    if (lim.empty) return null;
    const theta2 = sign * (lim.lowerAbs + u * (lim.upperAbs - lim.lowerAbs));
    return { l, theta2, branch };
  })
  .filter((x): x is { l: Linkage; theta2: number; branch: Branch } => x !== null);

/** The pose must be the oracle's on this branch, finite, wrapped, closing the loop, with the branch's sign. */
function expectGoodPose(
  l: Linkage,
  theta2: number,
  branch: Branch,
  got: { theta3: number; theta4: number },
  label: string,
) {
  expectPose(l, theta2, branch, got, label);
  expect(
    loopResidual(l, theta2, got.theta3, got.theta4) / size(l),
    `${label}: loop closure at ${where(l, theta2, branch)}`,
  ).toBeLessThanOrEqual(CLOSURE_REL);
  const ref = oracle(l, theta2, branch);
  const tol = angleTolerance(l, ref);
  // The sign of sin(t4 - t3) is decided only where |sin mu| exceeds the angle error.
  if (Math.abs(ref.sinMu) > 10 * (tol.theta3 + tol.theta4)) {
    expect(Math.sign(Math.sin(got.theta4 - got.theta3)), `${label}: branch sign at ${where(l, theta2, branch)}`).toBe(
      sigmaOf(branch),
    );
  }
}

function inRange(range: InputRange, t2: number): boolean {
  if (range.full) return true;
  return range.intervals.some(({ lo, hi }) => {
    const x = lo + ((((t2 - lo) % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI));
    return x <= hi;
  });
}

describe('solveClosedForm', () => {
  it('returns the oracle pose exactly when the loop can close, and null when it cannot (away from limits)', () => {
    fc.assert(
      fc.property(linkageArb, angleArb, branchArb, (l, t2, branch) => {
        const slack = referenceSlack(l, t2) / size(l);
        const got = solveClosedForm(l, t2, branch);
        if (slack > SLACK_MARGIN) {
          expect(got, `reachable (slack ${slack}) at ${where(l, t2, branch)}`).not.toBeNull();
          expectGoodPose(l, t2, branch, got!, 'solveClosedForm');
        } else if (slack < -SLACK_MARGIN) {
          expect(got, `unreachable (slack ${slack}) at ${where(l, t2, branch)}`).toBeNull();
        } else if (got !== null) {
          // On the margin either answer is fine, but a returned pose must still close the loop.
          expect(Number.isFinite(got.theta3) && Number.isFinite(got.theta4)).toBe(true);
          expect(loopResidual(l, t2, got.theta3, got.theta4) / size(l)).toBeLessThanOrEqual(1e-9);
        }
      }),
      RUNS,
    );
  });

  it('matches the oracle on reachable inputs, including near limit positions', () => {
    fc.assert(
      fc.property(reachableArb, ({ l, theta2, branch }) => {
        if (oracleOutcome(l, theta2, branch).kind !== 'unique') return;
        const got = solveClosedForm(l, theta2, branch);
        expect(got, `reachable at ${where(l, theta2, branch)}`).not.toBeNull();
        expectGoodPose(l, theta2, branch, got!, 'solveClosedForm');
      }),
      RUNS,
    );
  });

  it('is invariant under scaling by 2^k (exact) and 10^k (rounded) ', () => {
    fc.assert(
      fc.property(
        reachableArb,
        fc.integer({ min: -900, max: 900 }),
        fc.integer({ min: -250, max: 250 }),
        ({ l, theta2, branch }, k2, k10) => {
          if (oracleOutcome(l, theta2, branch).kind !== 'unique') return;
          const base = solveClosedForm(l, theta2, branch)!;
          // 2^k scaling is exact, so the exact answer is unchanged: agree within the tolerance of each.
          const l2 = scaled(l, 2 ** k2);
          const got2 = solveClosedForm(l2, theta2, branch);
          expect(got2, `2^${k2} at ${where(l2, theta2, branch)}`).not.toBeNull();
          const tol = angleTolerance(l, oracle(l, theta2, branch));
          expect(Math.abs(angleDiff(got2!.theta3, base.theta3))).toBeLessThanOrEqual(2 * tol.theta3);
          expect(Math.abs(angleDiff(got2!.theta4, base.theta4))).toBeLessThanOrEqual(2 * tol.theta4);
          // 10^k rounds each length once: a different (nearby) linkage; compare with its own oracle.
          const l10 = scaled(l, 10 ** k10);
          if (referenceSlack(l10, theta2) / size(l10) <= SLACK_MARGIN) return;
          expectGoodPose(l10, theta2, branch, solveClosedForm(l10, theta2, branch)!, `solveClosedForm x 1e${k10}`);
        },
      ),
      RUNS,
    );
  });
});

describe('solveNewton', () => {
  it('from a nearby guess converges to the closed-form pose', () => {
    fc.assert(
      fc.property(
        reachableArb,
        fc.double({ min: -1, max: 1, noNaN: true }),
        fc.double({ min: -1, max: 1, noNaN: true }),
        ({ l, theta2, branch }, u3, u4) => {
          if (oracleOutcome(l, theta2, branch).kind !== 'unique') return;
          const ref = oracle(l, theta2, branch);
          if (Math.abs(ref.sinMu) < 0.05) return; // near a fold the mirror pose is closer than any useful kick
          // Well inside Newton's basin: 1e-2 of |sin mu| min(r3, r4) / max(r3, r4) rad.
          const kick = (1e-2 * Math.abs(ref.sinMu) * Math.min(l.r3, l.r4)) / Math.max(l.r3, l.r4);
          const r = solveNewton(l, theta2, { theta3: ref.theta3 + u3 * kick, theta4: ref.theta4 + u4 * kick });
          expect(r.status, where(l, theta2, branch)).toBe('converged');
          expectGoodPose(l, theta2, branch, r, 'solveNewton');
          const cf = solveClosedForm(l, theta2, branch)!;
          const tol = angleTolerance(l, ref);
          expect(Math.abs(angleDiff(r.theta3, cf.theta3))).toBeLessThanOrEqual(2 * tol.theta3);
          expect(Math.abs(angleDiff(r.theta4, cf.theta4))).toBeLessThanOrEqual(2 * tol.theta4);
          expect(r.residual / size(l)).toBeLessThanOrEqual(CLOSURE_REL);
        },
      ),
      RUNS,
    );
  });

  it('never reports NaN angles, and reports converged only on a closed loop, from any guess', () => {
    fc.assert(
      fc.property(linkageArb, angleArb, angleArb, angleArb, (l, t2, g3, g4) => {
        const r = solveNewton(l, t2, { theta3: g3, theta4: g4 });
        expect(Number.isFinite(r.theta3) && Number.isFinite(r.theta4), `${r.status} at ${where(l, t2, '-')}`).toBe(
          true,
        );
        if (r.status === 'converged') {
          expect(loopResidual(l, t2, r.theta3, r.theta4) / size(l)).toBeLessThanOrEqual(CLOSURE_REL);
        }
      }),
      RUNS,
    );
  });
});

describe('sweep', () => {
  const methods = [undefined, 'newton', 'closed-form-polish'] as const;

  it('reports ok exactly at reachable points, with the oracle pose on the requested branch and no NaN', () => {
    fc.assert(
      fc.property(
        linkageArb,
        fc.array(angleArb, { minLength: 1, maxLength: 6 }),
        branchArb,
        fc.constantFrom(...methods),
        (l, raw, branch, method) => {
          const t2s = [...raw].sort((a, b) => a - b);
          const res = sweep(l, t2s, { branch, method });
          expect(res.status.length).toBe(t2s.length);
          for (let i = 0; i < t2s.length; i++) {
            const t2 = t2s[i];
            const st = res.status[i];
            const slack = referenceSlack(l, t2) / size(l);
            const ctx = `sweep ${method ?? 'default'} at ${where(l, t2, branch)} (slack ${slack})`;
            if (st === 'ok') {
              expect(
                Number.isFinite(res.theta3[i]) && Number.isFinite(res.theta4[i]),
                `${ctx}: NaN reported as ok`,
              ).toBe(true);
              expect(loopResidual(l, t2, res.theta3[i], res.theta4[i]) / size(l), ctx).toBeLessThanOrEqual(
                slack > SLACK_MARGIN ? CLOSURE_REL : 1e-9,
              );
            } else {
              expect(Number.isNaN(res.theta3[i]) && Number.isNaN(res.theta4[i]), `${ctx}: ${st} must carry NaN`).toBe(
                true,
              );
            }
            if (slack > SLACK_MARGIN) {
              expect(st, ctx).toBe('ok');
              expectGoodPose(
                l,
                t2,
                branch,
                { theta3: res.theta3[i], theta4: res.theta4[i] },
                `sweep ${method ?? 'default'}`,
              );
            } else if (slack < -SLACK_MARGIN) {
              expect(st, ctx).toBe('unreachable');
            }
          }
        },
      ),
      RUNS,
    );
  });

  it('follows a dense reachable arc on the requested branch with the newton method', () => {
    fc.assert(
      fc.property(reachableArb, fc.double({ min: 0.01, max: 0.2, noNaN: true }), ({ l, theta2, branch }, width) => {
        const lim = referenceLimits(l);
        // An arc of 8 points inside the reachable band (inside by 1e-3 of its width).
        const lo = Math.max(lim.lowerAbs, Math.abs(theta2) - width);
        const hi = Math.min(lim.upperAbs, Math.abs(theta2) + width);
        const pad = 1e-3 * (hi - lo);
        const sgn = theta2 < 0 ? -1 : 1;
        const t2s = Array.from({ length: 8 }, (_, i) => sgn * (lo + pad + ((hi - lo - 2 * pad) * i) / 7));
        const res = sweep(l, t2s, { branch, method: 'newton' });
        for (let i = 0; i < t2s.length; i++) {
          if (referenceSlack(l, t2s[i]) / size(l) <= SLACK_MARGIN) continue;
          expect(res.status[i], where(l, t2s[i], branch)).toBe('ok');
          expectGoodPose(l, t2s[i], branch, { theta3: res.theta3[i], theta4: res.theta4[i] }, 'sweep newton');
        }
      }),
      { seed: 42, numRuns: 100 },
    );
  });
});

describe('classify', () => {
  it('has an input range that contains the reachable inputs and excludes the unreachable ones', () => {
    fc.assert(
      fc.property(linkageArb, angleArb, (l, t2) => {
        const lim = referenceLimits(l);
        const range = classify(l).inputRange;
        if (lim.empty) {
          expect(range.full).toBe(false);
          return;
        }
        // Keep away from the limits by their conditioning (plus 1e-9 rad).
        const near = (a: number, c: number) => Math.abs(Math.abs(t2) - a) <= limitTolerance(l, c) * 10 + 1e-9;
        if ((lim.hasLower && near(lim.lowerAbs, lim.cosLower)) || (lim.hasUpper && near(lim.upperAbs, lim.cosUpper)))
          return;
        const reachable = Math.abs(t2) >= lim.lowerAbs && Math.abs(t2) <= lim.upperAbs;
        expect(inRange(range, t2), `inputRange at ${where(l, t2, '-')}: ${JSON.stringify(range)}`).toBe(reachable);
        // And the solver agrees with its own range: inside it assembles on both branches, outside on neither.
        if (Math.abs(referenceSlack(l, t2)) > SLACK_MARGIN * size(l)) {
          for (const b of ['open', 'crossed'] as const) {
            expect(solveClosedForm(l, t2, b) !== null, `solveClosedForm vs inputRange at ${where(l, t2, b)}`).toBe(
              inRange(range, t2),
            );
          }
        }
        expect(range.full).toBe(!lim.hasLower && !lim.hasUpper);
        expect(classify(l).inputIsCrank).toBe(range.full);
      }),
      RUNS,
    );
  });

  it('rejects a linkage that is not four positive finite numbers, naming the field and the value', () => {
    const bad = fc.oneof(
      fc.double({ min: -1e6, max: -1e-6, noNaN: true }),
      fc.constantFrom<unknown>(0, -0, NaN, Infinity, -Infinity, '3', 'abc', null, undefined, true, [2]),
    );
    fc.assert(
      fc.property(linkageArb, fc.constantFrom('r1', 'r2', 'r3', 'r4'), bad, (good, field, value) => {
        const l = { ...good, [field]: value } as unknown as Linkage;
        if (value === undefined) delete (l as unknown as Record<string, unknown>)[field];
        const shown = value === undefined ? /undefined|missing/ : new RegExp(escape(String(value)));
        const calls: [string, () => unknown][] = [
          ['classify', () => classify(l)],
          ['solveClosedForm', () => solveClosedForm(l, 0.5, 'open')],
          ['solveNewton', () => solveNewton(l, 0.5, { theta3: 0.5, theta4: 1.5 })],
          ['sweep', () => sweep(l, [0, 0.5], { branch: 'open' })],
        ];
        for (const [name, call] of calls) {
          let message = '';
          try {
            call();
          } catch (e) {
            message = e instanceof Error ? e.message : String(e);
          }
          expect(message, `${name} with ${field} = ${String(value)}`).toMatch(new RegExp(`\\b${field}\\b`));
          expect(message, `${name} with ${field} = ${String(value)}`).toMatch(shown);
        }
      }),
      RUNS,
    );
  });
});

function escape(s: string): string {
  return s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}
