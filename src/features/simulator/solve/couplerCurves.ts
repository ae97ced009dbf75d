import { couplerPoint, sweep } from '../../../solver';
import { PI, TWO_PI } from '../../../solver/angles';
import type { Branch, Classification, Linkage } from '../../../solver/types';
import type { CouplerCurve, CouplerSpec } from '../../../shared/solution';

/** Inset from an input limit when sampling a rocking circuit (radians): the exact limit may miss by an ulp. */
const LIMIT_INSET_RAD = 1e-9;

/** P (length unit) at each input angle (radians) on a branch, from one closed-form sweep; NaN where it cannot assemble. */
function couplerTrace(l: Linkage, coupler: CouplerSpec, theta2Rad: Float64Array, branch: Branch) {
  const r = sweep(l, theta2Rad, { branch, method: 'closed-form' });
  const x = new Float64Array(theta2Rad.length).fill(Number.NaN);
  const y = new Float64Array(theta2Rad.length).fill(Number.NaN);
  for (let i = 0; i < theta2Rad.length; i++) {
    if (r.status[i] !== 'ok') continue;
    const p = couplerPoint(l, theta2Rad[i], r.theta3[i], coupler.distance, coupler.angleRad);
    x[i] = p.x;
    y[i] = p.y;
  }
  return { x, y };
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
    const turn = Float64Array.from({ length: samplesPerTurn + 1 }, (_, k) => (TWO_PI * k) / samplesPerTurn);
    return (['open', 'crossed'] as const).map((branch) => ({
      ...couplerTrace(l, coupler, turn, branch),
      branch,
      rocking: false,
      loRad: Number.NaN,
      hiRad: Number.NaN,
    }));
  }
  return c.inputRange.intervals.map((iv) => {
    const width = iv.hi - iv.lo;
    const lo = width > 2 * LIMIT_INSET_RAD ? iv.lo + LIMIT_INSET_RAD : (iv.lo + iv.hi) / 2;
    const hi = width > 2 * LIMIT_INSET_RAD ? iv.hi - LIMIT_INSET_RAD : lo;
    // Cluster samples toward the limits (cosine spacing): P moves fastest there.
    const m = Math.max(32, Math.ceil((samplesPerTurn * width) / TWO_PI));
    const out = Float64Array.from({ length: m + 1 }, (_, k) => lo + ((hi - lo) * (1 - Math.cos((PI * k) / m))) / 2);
    const forward = couplerTrace(l, coupler, out, 'open');
    const back = couplerTrace(l, coupler, out.reverse(), 'crossed');
    const xs: number[] = [];
    const ys: number[] = [];
    for (const half of [forward, back]) {
      for (let i = 0; i < half.x.length; i++) {
        if (Number.isFinite(half.x[i]) && Number.isFinite(half.y[i])) {
          xs.push(half.x[i]);
          ys.push(half.y[i]);
        }
      }
    }
    if (xs.length > 0) {
      xs.push(xs[0]);
      ys.push(ys[0]);
    }
    return {
      x: Float64Array.from(xs),
      y: Float64Array.from(ys),
      branch: 'open',
      rocking: true,
      loRad: iv.lo,
      hiRad: iv.hi,
    };
  });
}
