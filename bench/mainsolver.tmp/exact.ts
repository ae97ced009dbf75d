/**
 * Error-free transformations (Knuth's TwoSum, Dekker's TwoProduct) and a compensated
 * sum, used where a cancellation would otherwise decide reachability or lose digits.
 */

const SPLITTER = 134217729; // 2^27 + 1, Dekker's splitting constant for binary64

/** Double-double value hi + lo with |lo| <= ulp(hi) / 2. */
export interface DD {
  hi: number;
  lo: number;
}

/** Exact a + b as (sum, error). */
export function twoSum(a: number, b: number): DD {
  const s = a + b;
  const bb = s - a;
  const err = a - (s - bb) + (b - bb);
  return { hi: s, lo: err };
}

/** Exact a * b as (product, error); valid while a * b neither overflows nor underflows. */
export function twoProd(a: number, b: number): DD {
  const p = a * b;
  let t = SPLITTER * a;
  const ah = t - (t - a);
  const al = a - ah;
  t = SPLITTER * b;
  const bh = t - (t - b);
  const bl = b - bh;
  const err = ah * bh - p + ah * bl + al * bh + al * bl;
  return { hi: p, lo: err };
}

/**
 * Sum of the terms and products given, to about double-double accuracy (Ogita-Rump-Oishi Sum2).
 * Each product is expanded exactly first, so sums of squares cancel without loss.
 */
export function sumOfProducts(terms: ReadonlyArray<number | readonly [number, number]>): DD {
  let s = 0;
  let c = 0;
  const add = (x: number): void => {
    const t = twoSum(s, x);
    s = t.hi;
    c += t.lo;
  };
  for (const term of terms) {
    if (typeof term === 'number') {
      add(term);
    } else {
      const p = twoProd(term[0], term[1]);
      add(p.hi);
      add(p.lo);
    }
  }
  return twoSum(s, c);
}
