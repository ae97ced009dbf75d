/**
 * Shared checks of the design-metrics tests: every field of designMetrics and instantCenters against the
 * 60-digit oracle (tests/oracle/metrics.ts) with the tolerances of tests/oracle/metricsTolerance.ts.
 */
import { expect } from 'vitest';
import type { Angles, Branch, DesignMetrics, Linkage } from '../../src/solver';
import { designMetrics, instantCenters, PARALLEL_SIN, solveClosedForm } from '../../src/solver';
import { referenceInstantCenters, referenceStroke, referenceTransmission } from '../oracle/metrics';
import type { ReferenceCenter } from '../oracle/metrics';
import { angleTol, centerTol, differenceTol, sinDifferenceFloor, timeRatioTol } from '../oracle/metricsTolerance';
import { angleDiff } from '../oracle/reference';
import { angleTolerance, EPS, limitTolerance } from '../oracle/tolerance';
import { oracle, sigmaOf, where } from './helpers';

/** Short description of a linkage and branch for failure messages. */
export function describeLinkage(l: Linkage, branch: Branch): string {
  return `linkage (${l.r1}, ${l.r2}, ${l.r3}, ${l.r4}) ${branch}`;
}

/** |got - ref| <= tol, with both values in the message. */
export function expectNear(got: number, ref: number, tol: number, what: string): void {
  const err = Math.abs(got - ref);
  expect(err, `${what}: expected ${ref}, got ${got} (error ${err} > tol ${tol})`).toBeLessThanOrEqual(tol);
}

/** An angle wrapped to (-pi, pi] and within tol of ref (compared modulo 2 pi). */
export function expectAngle(got: number, ref: number, tol: number, what: string): void {
  expect(got > -Math.PI && got <= Math.PI, `${what}: ${got} not wrapped to (-pi, pi]`).toBe(true);
  const err = Math.abs(angleDiff(got, ref));
  expect(err, `${what}: expected ${ref}, got ${got} (error ${err} > tol ${tol})`).toBeLessThanOrEqual(tol);
}

/** Every field of designMetrics against the oracle. Returns the metrics for further checks. */
export function expectMatchesOracle(l: Linkage, branch: Branch): DesignMetrics {
  const m = designMetrics(l, branch);
  const ctx = describeLinkage(l, branch);
  const tr = referenceTransmission(l);
  if (!tr) {
    const t = m.transmission;
    expect([t.min, t.max, t.theta2AtMin, t.theta2AtMax].every(Number.isNaN), `${ctx}: NaN when nothing assembles`).toBe(
      true,
    );
  } else {
    expectNear(m.transmission.min, tr.min, angleTol(tr.min), `${ctx} transmission.min`);
    expectNear(m.transmission.max, tr.max, angleTol(tr.max), `${ctx} transmission.max`);
    // theta2 = 0 and pi are exact; a limit angle is as accurate as the limit itself (tolerance.ts).
    const atMin = tr.theta2AtMin === 0 ? 0 : limitTolerance(l, tr.cosAtMin);
    const atMax = tr.theta2AtMax === Math.PI ? 0 : limitTolerance(l, tr.cosAtMax);
    expectNear(m.transmission.theta2AtMin, tr.theta2AtMin, atMin, `${ctx} transmission.theta2AtMin`);
    expectNear(m.transmission.theta2AtMax, tr.theta2AtMax, atMax, `${ctx} transmission.theta2AtMax`);
  }
  const ref = referenceStroke(l, sigmaOf(branch));
  if (!ref) {
    expect(m.output, `${ctx}: output only for a crank-rocker`).toBeNull();
    expect(m.timeRatio, `${ctx}: time ratio only for a crank-rocker`).toBeNull();
    return m;
  }
  expect(m.output, `${ctx}: a crank-rocker has dead centres`).not.toBeNull();
  const o = m.output!;
  expectAngle(o.extended.theta2, ref.extended.theta2, angleTol(ref.extended.theta2), `${ctx} extended.theta2`);
  expectAngle(o.extended.theta4, ref.extended.theta4, angleTol(ref.extended.theta4), `${ctx} extended.theta4`);
  expectAngle(o.folded.theta2, ref.folded.theta2, angleTol(ref.folded.theta2), `${ctx} folded.theta2`);
  expectAngle(o.folded.theta4, ref.folded.theta4, angleTol(ref.folded.theta4), `${ctx} folded.theta4`);
  expectNear(o.swing, ref.swing, differenceTol(ref.swing), `${ctx} swing`);
  expectNear(m.timeRatio!, ref.timeRatio, timeRatioTol(ref.timeRatio), `${ctx} timeRatio`);
  expect(m.timeRatio!, `${ctx}: time ratio >= 1`).toBeGreaterThanOrEqual(1);
  return m;
}

/**
 * The dead-centre poses are real poses of the branch: the closed form at each dead-centre theta2 gives
 * the reported theta4, with theta3 = theta2 (extended) or theta2 + pi (folded), within the pose's
 * conditioning tolerance (tests/oracle/tolerance.ts) plus the dead-centre angle's own tolerance.
 */
export function expectDeadCentrePoses(l: Linkage, branch: Branch, m: DesignMetrics): void {
  const o = m.output!;
  for (const [name, dc, offset] of [
    ['extended', o.extended, 0],
    ['folded', o.folded, Math.PI],
  ] as const) {
    const ctx = `${name} dead centre at ${where(l, dc.theta2, branch)}`;
    const pose = solveClosedForm(l, dc.theta2, branch);
    expect(pose, `${ctx}: assembles`).not.toBeNull();
    const tol = angleTolerance(l, oracle(l, dc.theta2, branch));
    const slack = angleTol(dc.theta2);
    expectAngle(pose!.theta4, dc.theta4, tol.theta4 + angleTol(dc.theta4) + slack, `${ctx}: theta4`);
    expectAngle(pose!.theta3, dc.theta2 + offset, tol.theta3 + slack, `${ctx}: theta3 - theta2 - ${offset}`);
  }
}

/** Instant centres against the oracle (null only where the oracle's lines are parallel within PARALLEL_SIN). */
export function expectCentersMatchOracle(l: Linkage, theta2: number, pose: Angles, label: string): void {
  const got = instantCenters(l, theta2, pose);
  const ref = referenceInstantCenters(l, theta2, pose.theta3, pose.theta4);
  const check = (
    name: 'I13' | 'I24',
    p: { x: number; y: number } | null,
    r: ReferenceCenter | null,
    floor: (r: ReferenceCenter) => number,
  ) => {
    const ctx = `${label} ${name} at ${where(l, theta2, '')} pose (${pose.theta3}, ${pose.theta4})`;
    // Within a few eps of the threshold either answer is right (the threshold itself is rounded).
    if (r && Math.abs(Math.abs(r.sinBetween) - PARALLEL_SIN) < 4 * EPS) return;
    if (!r || Math.abs(r.sinBetween) <= PARALLEL_SIN) {
      expect(p, `${ctx}: lines parallel (sin ${r?.sinBetween ?? 0}), expected null`).toBeNull();
      return;
    }
    expect(p, `${ctx}: expected a point`).not.toBeNull();
    expectNear(p!.x, r.x, centerTol(r.x, floor(r)), `${ctx} x`);
    expectNear(p!.y, r.y, centerTol(r.y, floor(r)), `${ctx} y`);
  };
  check('I13', got.I13, ref.I13, () => 0);
  // I24 = r2 sin(theta3 - theta2) / sin(theta3): next to O2 the sine of the difference is far below an ulp.
  check('I24', got.I24, ref.I24, (r) => sinDifferenceFloor(l.r2, pose.theta3, theta2, r.sinBetween));
}
