/**
 * Shared test helpers: the hard-case linkages (copied from docs/hard-cases.md so nothing is read at run
 * time), branch <-> sigma, the oracle comparison with conditioning-based tolerances, and a few
 * floating-point utilities.
 */
import { expect } from 'vitest';
import type { Branch, Linkage } from '../../src/solver';
import type { ReferenceOutcome, ReferencePose, Sigma } from '../oracle/reference';
import { angleDiff, referenceSolve, toDeg } from '../oracle/reference';
import { angleTolerance } from '../oracle/tolerance';

/** The linkages of docs/hard-cases.md (r1 ground, r2 crank, r3 coupler, r4 rocker). */
export const CASES = {
  1: { r1: 6, r2: 2, r3: 5, r4: 5 },
  2: { r1: 4, r2: 1, r3: 3, r4: 2 + 1e-9 },
  3: { r1: 5, r2: 1, r3: 6, r4: 2 + 1e-9 },
  4: { r1: 4, r2: 1, r3: 3, r4: 2 },
  5: { r1: 4, r2: 1, r3: 3, r4: 2 + 1e-12 },
  6: { r1: 4, r2: 1, r3: 3, r4: 2 - 1e-12 },
  7: { r1: 4, r2: 2, r3: 4, r4: 2 },
  8: { r1: 2, r2: 2, r3: 4, r4: 4 },
  9: { r1: 4, r2: 2, r3: 2, r4: 4 },
  10: { r1: 4, r2: 3, r3: 3.5, r4: 3 },
  11: { r1: 3, r2: 2.5, r3: 4.2, r4: 1.5 },
  12: { r1: 4, r2: 3, r3: 1, r4: 3.5 },
  13: { r1: 4, r2: 3, r3: 2.5, r4: 2.5 },
  14: { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 },
  15: { r1: 1, r2: 1e-6, r3: 1, r4: 1 },
  16: { r1: 1e6, r2: 1, r3: 1e6 + 0.5, r4: 2 },
  19: { r1: 6, r2: 1e-300, r3: 5, r4: 5 },
  20: { r1: 1, r2: 1, r3: 1e-9, r4: 1 },
  21: { r1: 10, r2: 1, r3: 2, r4: 3 },
  22: { r1: 6, r2: 1, r3: 2, r4: 3 },
} satisfies Record<number, Linkage>;

export const BRANCHES: readonly Branch[] = ['open', 'crossed'];

export function sigmaOf(branch: Branch): Sigma {
  return branch === 'open' ? 1 : -1;
}

/** A linkage multiplied by k (each length rounded once: the oracle takes the rounded doubles as exact). */
export function scaled(l: Linkage, k: number): Linkage {
  return { r1: l.r1 * k, r2: l.r2 * k, r3: l.r3 * k, r4: l.r4 * k };
}

/** r1 + r2 + r3 + r4, the length scale residuals are judged against. */
export function size(l: Linkage): number {
  return l.r1 + l.r2 + l.r3 + l.r4;
}

/** Next double above x. */
export function nextUp(x: number): number {
  if (x === 0) return Number.MIN_VALUE;
  const f = new Float64Array([x]);
  const b = new BigInt64Array(f.buffer);
  b[0] += x > 0 ? 1n : -1n;
  return f[0];
}

/** Next double below x. */
export function nextDown(x: number): number {
  return -nextUp(-x);
}

/** Evenly spaced degrees lo..hi inclusive, as radians. */
export function degGrid(lo: number, hi: number, step: number): number[] {
  const out: number[] = [];
  const n = Math.round((hi - lo) / step);
  for (let i = 0; i <= n; i++) out.push(((lo + i * step) * Math.PI) / 180);
  return out;
}

/** Loop-closure residual norm in double precision (length unit); normalised so squares cannot overflow. */
export function loopResidual(l: Linkage, theta2: number, theta3: number, theta4: number): number {
  const m = Math.max(l.r1, l.r2, l.r3, l.r4);
  const [r1, r2, r3, r4] = [l.r1 / m, l.r2 / m, l.r3 / m, l.r4 / m];
  const f1 = r2 * Math.cos(theta2) + r3 * Math.cos(theta3) - r4 * Math.cos(theta4) - r1;
  const f2 = r2 * Math.sin(theta2) + r3 * Math.sin(theta3) - r4 * Math.sin(theta4);
  return Math.hypot(f1, f2) * m;
}

/** Human-readable description of a point for failure messages. */
export function where(l: Linkage, theta2: number, branch: Branch | string): string {
  return `linkage (${l.r1}, ${l.r2}, ${l.r3}, ${l.r4}), theta2 = ${theta2} rad (${toDeg(theta2)} deg), ${branch}`;
}

const memo = new Map<string, ReferenceOutcome>();

/** The oracle's outcome, memoised (60-digit trigonometry costs about a millisecond). */
export function oracleOutcome(l: Linkage, theta2: number, branch: Branch): ReferenceOutcome {
  const key = `${l.r1},${l.r2},${l.r3},${l.r4},${theta2},${branch}`;
  let out = memo.get(key);
  if (!out) {
    out = referenceSolve(l, theta2, sigmaOf(branch));
    memo.set(key, out);
  }
  return out;
}

/** The oracle's unique pose; fails the test if the oracle has none. */
export function oracle(l: Linkage, theta2: number, branch: Branch): ReferencePose {
  const out = oracleOutcome(l, theta2, branch);
  if (out.kind !== 'unique') throw new Error(`oracle has no unique pose (${out.kind}) at ${where(l, theta2, branch)}`);
  return out.pose;
}

/**
 * Asserts (theta3, theta4) match the oracle within the conditioning tolerance (tests/oracle/tolerance.ts)
 * or an explicit override, and that both are finite and wrapped to (-pi, pi].
 */
export function expectPose(
  l: Linkage,
  theta2: number,
  branch: Branch,
  got: { theta3: number; theta4: number } | null,
  label: string,
  override?: { theta3: number; theta4: number },
): void {
  const ref = oracle(l, theta2, branch);
  const ctx = `${label} at ${where(l, theta2, branch)}`;
  expect(got, `${ctx}: expected a pose, got null`).not.toBeNull();
  const { theta3, theta4 } = got!;
  expect(Number.isFinite(theta3) && Number.isFinite(theta4), `${ctx}: non-finite angles ${theta3}, ${theta4}`).toBe(
    true,
  );
  expect(theta3 > -Math.PI && theta3 <= Math.PI, `${ctx}: theta3 = ${theta3} not wrapped to (-pi, pi]`).toBe(true);
  expect(theta4 > -Math.PI && theta4 <= Math.PI, `${ctx}: theta4 = ${theta4} not wrapped to (-pi, pi]`).toBe(true);
  const tol = override ?? angleTolerance(l, ref);
  const e3 = Math.abs(angleDiff(theta3, ref.theta3));
  const e4 = Math.abs(angleDiff(theta4, ref.theta4));
  expect(
    e3,
    `${ctx}: theta3 expected ${ref.theta3} got ${theta3} (error ${e3} rad > tol ${tol.theta3})`,
  ).toBeLessThanOrEqual(tol.theta3);
  expect(
    e4,
    `${ctx}: theta4 expected ${ref.theta4} got ${theta4} (error ${e4} rad > tol ${tol.theta4})`,
  ).toBeLessThanOrEqual(tol.theta4);
}

/** Angle error (max of theta3, theta4) against the oracle. */
export function poseError(l: Linkage, theta2: number, branch: Branch, got: { theta3: number; theta4: number }): number {
  const ref = oracle(l, theta2, branch);
  return Math.max(Math.abs(angleDiff(got.theta3, ref.theta3)), Math.abs(angleDiff(got.theta4, ref.theta4)));
}
