import { A, AH, B, BH, NV, X, XH, Y, YH } from './equations';

/**
 * The order-6 group acting on the roots: relabelling the two dyads, and the Roberts cognate maps (WMS 1992, eq. 17).
 * With μ = x / (x − y) (the coupler point as an affine combination of the moving pivots) and c = a + μ (b − a) (the
 * third ground pivot of Roberts' diagram), one cognate is (a − x, a, (1 − μ)(a − x), c), the other (μ (b − y), c,
 * b − y, b); the hatted unknowns map by the same formulas in hatted values. See docs/synthesis.md.
 */

function get(z: Float64Array, k: number): [number, number] {
  return [z[2 * k], z[2 * k + 1]];
}
function put(z: Float64Array, k: number, v: [number, number]): void {
  z[2 * k] = v[0];
  z[2 * k + 1] = v[1];
}
const mul = (u: [number, number], v: [number, number]): [number, number] => [
  u[0] * v[0] - u[1] * v[1],
  u[0] * v[1] + u[1] * v[0],
];
const sub = (u: [number, number], v: [number, number]): [number, number] => [u[0] - v[0], u[1] - v[1]];
const add = (u: [number, number], v: [number, number]): [number, number] => [u[0] + v[0], u[1] + v[1]];
const div = (u: [number, number], v: [number, number]): [number, number] => {
  const m = v[0] * v[0] + v[1] * v[1];
  return [(u[0] * v[0] + u[1] * v[1]) / m, (u[1] * v[0] - u[0] * v[1]) / m];
};

/** The root with the two dyads swapped. */
export function swapDyads(z: Float64Array): Float64Array {
  const w = new Float64Array(2 * NV);
  const map: [number, number][] = [
    [X, Y],
    [A, B],
    [XH, YH],
    [AH, BH],
  ];
  for (const [i, j] of map) {
    put(w, i, get(z, j));
    put(w, j, get(z, i));
  }
  return w;
}

/** The two Roberts cognates of a root (NaN entries when the moving pivots coincide). */
export function cognateRoots(z: Float64Array): [Float64Array, Float64Array] {
  const u = new Float64Array(2 * NV);
  const v = new Float64Array(2 * NV);
  for (const [x, a, y, b] of [
    [X, A, Y, B],
    [XH, AH, YH, BH],
  ]) {
    const zx = get(z, x),
      za = get(z, a),
      zy = get(z, y),
      zb = get(z, b);
    const mu = div(zx, sub(zx, zy));
    const oneMinusMu = div(zy, sub(zy, zx));
    const c = add(za, mul(mu, sub(zb, za)));
    const ax = sub(za, zx);
    put(u, x, ax);
    put(u, a, za);
    put(u, y, mul(oneMinusMu, ax));
    put(u, b, c);
    const by = sub(zb, zy);
    put(v, x, mul(mu, by));
    put(v, a, c);
    put(v, y, by);
    put(v, b, zb);
  }
  return [u, v];
}

/** The six images of a root under the group: itself, its two cognates, and the three with dyads swapped. */
export function orbit(z: Float64Array): Float64Array[] {
  const [u, v] = cognateRoots(z);
  return [z, u, v, swapDyads(z), swapDyads(u), swapDyads(v)];
}

/**
 * A key that every root of one orbit shares: the elementary symmetric functions of the three ground pivots a, b, c
 * and of their hatted twins (complex; 8 floats). Roots of different orbits differ in it for generic data.
 */
export function orbitKey(z: Float64Array): Float64Array {
  const key = new Float64Array(8);
  let o = 0;
  for (const [x, a, y, b] of [
    [X, A, Y, B],
    [XH, AH, YH, BH],
  ]) {
    const zx = get(z, x),
      za = get(z, a),
      zy = get(z, y),
      zb = get(z, b);
    const mu = div(zx, sub(zx, zy));
    const c = add(za, mul(mu, sub(zb, za)));
    const s1 = add(add(za, zb), c);
    const s2 = add(add(mul(za, zb), mul(zb, c)), mul(c, za));
    key[o++] = s1[0];
    key[o++] = s1[1];
    key[o++] = s2[0];
    key[o++] = s2[1];
  }
  return key;
}

/** Whether two orbit keys agree to tol relative to their size. */
export function sameKey(k1: ArrayLike<number>, k2: ArrayLike<number>, tol: number): boolean {
  let d = 0;
  let m = 0;
  for (let i = 0; i < k1.length; i++) {
    d = Math.max(d, Math.abs(k1[i] - k2[i]));
    m = Math.max(m, Math.abs(k1[i]), Math.abs(k2[i]));
  }
  return d <= tol * (1 + m);
}
