/**
 * Every real root of a real polynomial of modest degree, by recursive isolation: the roots of p′ split the line into
 * intervals on which p is monotone, so each holds at most one root, found by bisection to the last bit. A root of
 * even multiplicity (p touches zero at a root of p′) is kept when |p| there is within rounding of zero.
 */

/** p(x) by Horner; coefficients in ascending powers. */
export function evalPoly(c: readonly number[], x: number): number {
  let v = 0;
  for (let i = c.length - 1; i >= 0; i--) v = v * x + c[i];
  return v;
}

/** Σ|c_i| |x|^i: the scale of p(x)'s rounding error. */
function evalAbs(c: readonly number[], x: number): number {
  let v = 0;
  const ax = Math.abs(x);
  for (let i = c.length - 1; i >= 0; i--) v = v * ax + Math.abs(c[i]);
  return v;
}

/**
 * The root of p in [lo, hi] where p(lo) and p(hi) differ in sign, bisected to 1e-15 of its size (or of 1 near zero):
 * the callers polish the roots they use, and a tighter bracket would only spend steps on denormals near zero.
 */
function bracketed(c: readonly number[], lo: number, hi: number, plo: number): number {
  for (let it = 0; it < 200; it++) {
    const mid = (lo + hi) / 2;
    if (hi - lo <= 1e-15 * Math.max(1, Math.abs(mid))) break;
    const pm = evalPoly(c, mid);
    if (pm === 0) return mid;
    if (pm < 0 === plo < 0) {
      lo = mid;
      plo = pm;
    } else hi = mid;
  }
  return (lo + hi) / 2;
}

/**
 * The real roots of the polynomial with coefficients c (ascending powers; trailing zeros are dropped) in the open
 * interval (lo, hi), ascending. The caller bounds the roots (e.g. by Cauchy's bound).
 */
export function realRoots(c: readonly number[], lo: number, hi: number): number[] {
  let n = c.length - 1;
  while (n > 0 && c[n] === 0) n--;
  const p = c.slice(0, n + 1);
  if (n <= 0) return [];
  if (n === 1) {
    const x = -p[0] / p[1];
    return x > lo && x < hi ? [x] : [];
  }
  const dp = p.slice(1).map((v, i) => v * (i + 1));
  const crit = realRoots(dp, lo, hi);
  const ends = [lo, ...crit, hi];
  const roots: number[] = [];
  for (let i = 0; i + 1 < ends.length; i++) {
    const a = ends[i];
    const b = ends[i + 1];
    const pa = evalPoly(p, a);
    const pb = evalPoly(p, b);
    if (pa !== 0 && pb !== 0 && pa < 0 !== pb < 0) roots.push(bracketed(p, a, b, pa));
    // A critical point where p is zero to rounding: a double root (or the meeting of two very close ones).
    if (i + 1 < ends.length - 1 && Math.abs(pb) <= 64 * Number.EPSILON * evalAbs(p, b)) roots.push(b);
  }
  return roots;
}

/** Cauchy's bound: every root x of p has |x| < 1 + max |c_i / c_n|. */
export function cauchyBound(c: readonly number[]): number {
  let n = c.length - 1;
  while (n > 0 && c[n] === 0) n--;
  let m = 0;
  for (let i = 0; i < n; i++) m = Math.max(m, Math.abs(c[i] / c[n]));
  return 1 + m;
}
