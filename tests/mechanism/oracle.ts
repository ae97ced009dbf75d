/**
 * A 50-digit oracle for the mechanism tests: every double of a drawn configuration is taken as exact (so the
 * link lengths are the drawn ones, with no rounding of their own), and poses are constructed from them with
 * decimal.js by the textbook geometry of each linkage (rotation of the crank pin, circle–line and circle–circle
 * intersections), a different route from the solver's Newton iteration.
 */
import Decimal from 'decimal.js';
import { exact } from '../oracle/reference';

export const D = Decimal.clone({ precision: 50, rounding: Decimal.ROUND_HALF_EVEN });
export type Dec = InstanceType<typeof D>;
export { exact };

/** A point in 50 digits. */
export type DPt = [Dec, Dec];

export const dpt = (x: number, y: number): DPt => [exact(x), exact(y)];

/** p rotated by angle t (50-digit) about c. */
export function rotate(p: DPt, c: DPt, t: Dec): DPt {
  const cs = D.cos(t);
  const sn = D.sin(t);
  const dx = p[0].minus(c[0]);
  const dy = p[1].minus(c[1]);
  return [c[0].plus(cs.times(dx)).minus(sn.times(dy)), c[1].plus(sn.times(dx)).plus(cs.times(dy))];
}

export const dist = (p: DPt, q: DPt): Dec => p[0].minus(q[0]).pow(2).plus(p[1].minus(q[1]).pow(2)).sqrt();

/** Intersection of circles (p, rp) and (q, rq), left (+1) or right (-1) of p → q; null when they miss. */
export function circles(p: DPt, rp: Dec, q: DPt, rq: Dec, side: 1 | -1): DPt | null {
  const dx = q[0].minus(p[0]);
  const dy = q[1].minus(p[1]);
  const d2 = dx.pow(2).plus(dy.pow(2));
  const d = d2.sqrt();
  const a = rp.pow(2).minus(rq.pow(2)).plus(d2).div(d.times(2));
  const h2 = rp.pow(2).minus(a.pow(2));
  if (h2.isNegative()) return null;
  const h = h2.sqrt().times(side);
  return [p[0].plus(a.times(dx).minus(h.times(dy)).div(d)), p[1].plus(a.times(dy).plus(h.times(dx)).div(d))];
}

/** Which side of p → q the point x lies (+1 left, -1 right). */
export function sideOf(p: DPt, q: DPt, x: DPt): 1 | -1 {
  const c = q[0]
    .minus(p[0])
    .times(x[1].minus(p[1]))
    .minus(q[1].minus(p[1]).times(x[0].minus(p[0])));
  return c.isNegative() ? -1 : 1;
}

/** Largest |a - b| relative to scale over two arrays, NaN-safe (a NaN counts as Infinity). */
export function maxRelError(a: ArrayLike<number>, b: ArrayLike<number>, scale: number): number {
  let m = 0;
  for (let i = 0; i < a.length; i++) {
    const e = Math.abs(a[i] - b[i]) / scale;
    m = Math.max(m, Number.isNaN(e) ? Infinity : e);
  }
  return m;
}

/** n inputs from a to b inclusive (radians or length). */
export function grid(a: number, b: number, n: number): Float64Array {
  return Float64Array.from({ length: n }, (_, i) => a + ((b - a) * i) / (n - 1));
}
