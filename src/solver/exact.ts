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

/** Fixed-point scale of exactSumOfProducts: every double is an integer times 2^-1074, a product times 2^-2148. */
const PRODUCT_SCALE = 2148n;
const exactView = new DataView(new ArrayBuffer(8));

/** The finite double x as the exact integer x * 2^(1074 + extra). */
function toScaledBigInt(x: number, extra: bigint): bigint {
  if (x === 0) return 0n;
  exactView.setFloat64(0, x);
  const hiWord = exactView.getUint32(0);
  const biased = (hiWord >>> 20) & 0x7ff;
  const mant = (BigInt(hiWord & 0xfffff) << 32n) | BigInt(exactView.getUint32(4));
  const m = biased === 0 ? mant : mant | (1n << 52n);
  const shifted = m << (BigInt(biased === 0 ? 0 : biased - 1) + extra);
  return hiWord >>> 31 ? -shifted : shifted;
}

/** A double within an ulp of x / 2^scale (its sign always right, 0 only for x = 0). */
function scaledToDouble(x: bigint, scale: bigint): number {
  if (x === 0n) return 0;
  const neg = x < 0n;
  const a = neg ? -x : x;
  const len = BigInt(a.toString(2).length);
  const shift = len > 64n ? len - 64n : 0n;
  let v = Number(a >> shift);
  let e = Number(shift - scale);
  // Apply 2^e in steps that neither overflow nor lose bits before the last one.
  while (e < -1000) {
    v *= 2 ** -1000;
    e += 1000;
  }
  v *= 2 ** e;
  if (v === 0) v = Number.MIN_VALUE; // below the subnormal range: keep the sign information
  return neg ? -v : v;
}

/**
 * Sum of the terms and products given, exactly (BigInt fixed point), rounded to a double-double:
 * hi is within an ulp of the sum and lo within an ulp of the remainder, so the sign of hi + lo is the
 * exact sign. Slower than sumOfProducts (tens of microseconds): for ties that Sum2 cannot decide.
 */
export function exactSumOfProducts(terms: ReadonlyArray<number | readonly [number, number]>): DD {
  let acc = 0n;
  for (const term of terms) {
    if (typeof term === 'number') acc += toScaledBigInt(term, 1074n);
    else acc += toScaledBigInt(term[0], 0n) * toScaledBigInt(term[1], 0n);
  }
  const hi = scaledToDouble(acc, PRODUCT_SCALE);
  // The remainder acc - hi, exactly; hi may be rounded to a subnormal, whose value we take as it is.
  const rest = acc - (hi === Number.MIN_VALUE || hi === -Number.MIN_VALUE ? 0n : toScaledBigInt(hi, 1074n));
  const lo = hi === Number.MIN_VALUE || hi === -Number.MIN_VALUE ? 0 : scaledToDouble(rest, PRODUCT_SCALE);
  return { hi, lo };
}

/** Half the spacing of the doubles at x (the rounding radius of x), exactly; finite x. */
export function halfUlp(x: number): number {
  exactView.setFloat64(0, x);
  const biased = (exactView.getUint32(0) >>> 20) & 0x7ff;
  return biased <= 1 ? Number.MIN_VALUE / 2 : 2 ** (biased - 1076);
}
