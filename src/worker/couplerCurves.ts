import { couplerPoint, solveClosedForm } from '../solver';
import { PI, TWO_PI } from '../solver/angles';
import type { Branch, Classification, Linkage } from '../solver/types';
import type { CouplerCurve, CouplerSpec } from './protocol';

/** Inset from an input limit when sampling a rocking circuit (radians): the exact limit may miss by an ulp. */
const LIMIT_INSET_RAD = 1e-9;

/** The closed curve P traces on one branch over a full turn, at samplesPerTurn + 1 closed-form poses (first = last). */
function branchCurve(l: Linkage, coupler: CouplerSpec, branch: Branch, samplesPerTurn: number): CouplerCurve {
  const x = new Float64Array(samplesPerTurn + 1).fill(Number.NaN);
  const y = new Float64Array(samplesPerTurn + 1).fill(Number.NaN);
  for (let k = 0; k <= samplesPerTurn; k++) {
    const t2 = (TWO_PI * k) / samplesPerTurn;
    const a = solveClosedForm(l, t2, branch);
    if (!a) continue;
    const p = couplerPoint(l, t2, a.theta3, coupler.distance, coupler.angleRad);
    x[k] = p.x;
    y[k] = p.y;
  }
  return { x, y, branch, rocking: false, loRad: Number.NaN, hiRad: Number.NaN };
}

/**
 * The closed coupler curves P traces (length unit), from closed-form poses at about samplesPerTurn per
 * turn of the input. A full-turn input gives one closed curve per branch (its two circuits). A rocking
 * input gives one closed curve per reachable interval: forward on the open branch, back on the crossed
 * one, the two halves meeting at the limits where the branches join.
 */
export function couplerCurves(
  l: Linkage,
  c: Classification,
  coupler: CouplerSpec,
  samplesPerTurn: number,
): CouplerCurve[] {
  if (c.inputRange.full) {
    return [branchCurve(l, coupler, 'open', samplesPerTurn), branchCurve(l, coupler, 'crossed', samplesPerTurn)];
  }
  const curves: CouplerCurve[] = [];
  for (const iv of c.inputRange.intervals) {
    const width = iv.hi - iv.lo;
    const lo = width > 2 * LIMIT_INSET_RAD ? iv.lo + LIMIT_INSET_RAD : (iv.lo + iv.hi) / 2;
    const hi = width > 2 * LIMIT_INSET_RAD ? iv.hi - LIMIT_INSET_RAD : lo;
    // Cluster samples toward the limits (cosine spacing): P moves fastest there.
    const m = Math.max(32, Math.ceil((samplesPerTurn * width) / TWO_PI));
    const xs: number[] = [];
    const ys: number[] = [];
    const push = (t2: number, branch: Branch): void => {
      const a = solveClosedForm(l, t2, branch);
      if (!a) return;
      const p = couplerPoint(l, t2, a.theta3, coupler.distance, coupler.angleRad);
      if (Number.isFinite(p.x) && Number.isFinite(p.y)) {
        xs.push(p.x);
        ys.push(p.y);
      }
    };
    for (let k = 0; k <= m; k++) push(lo + ((hi - lo) * (1 - Math.cos((PI * k) / m))) / 2, 'open');
    for (let k = m; k >= 0; k--) push(lo + ((hi - lo) * (1 - Math.cos((PI * k) / m))) / 2, 'crossed');
    if (xs.length > 0) {
      xs.push(xs[0]);
      ys.push(ys[0]);
    }
    curves.push({
      x: Float64Array.from(xs),
      y: Float64Array.from(ys),
      branch: 'open',
      rocking: true,
      loRad: iv.lo,
      hiRad: iv.hi,
    });
  }
  return curves;
}
