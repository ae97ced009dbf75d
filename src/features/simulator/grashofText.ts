import { sumOfProducts } from '../../solver/exact';
import type { Classification } from '../../solver/types';
import { formatNumber } from '../../shared/format';

/** The Grashof line's parts: both sums as shown, the relation the classification decided, and the exact excess when needed. */
export interface GrashofSums {
  left: string;
  relation: '<' | '=' | '>';
  right: string;
  /** S + L − P − Q, shown only when the two sums are the same double although the relation is strict. */
  excess: string | null;
}

/** Fewest significant digits tried for the sums (the app's usual), and the most (enough for any double). */
const MIN_DIGITS = 6;
const MAX_DIGITS = 17;

/**
 * The Grashof comparison as shown: the relation comes from the classification (exact-sign, so '=' exactly for
 * a change point), and the sums get as many significant digits as it takes for the shown numbers to differ
 * in that direction ("S + L = 5 < P + Q = 5.0000001", never "5 < 5").
 */
export function grashofSums(c: Pick<Classification, 'S' | 'L' | 'P' | 'Q' | 'type' | 'grashof'>): GrashofSums {
  const sl = c.S + c.L;
  const pq = c.P + c.Q;
  if (c.type === 'change-point') {
    const shown = formatNumber(sl, MIN_DIGITS);
    return { left: shown, relation: '=', right: shown, excess: null };
  }
  const relation = c.grashof ? '<' : '>';
  for (let digits = MIN_DIGITS; digits <= MAX_DIGITS; digits++) {
    const left = formatNumber(sl, digits);
    const right = formatNumber(pq, digits);
    // Rounding is monotone, so different texts are ordered as the sums are, and the sums as the exact ones.
    if (left !== right) return { left, relation, right, excess: null };
  }
  const e = sumOfProducts([c.S, c.L, -c.P, -c.Q]);
  return {
    left: formatNumber(sl, MAX_DIGITS),
    relation,
    right: formatNumber(pq, MAX_DIGITS),
    excess: formatNumber(e.hi + e.lo, 2),
  };
}

/** The Grashof line "S + L = 8 < P + Q = 10", with the exact excess in parentheses when the sums round alike. */
export function grashofSumsText(c: Pick<Classification, 'S' | 'L' | 'P' | 'Q' | 'type' | 'grashof'>): string {
  const g = grashofSums(c);
  const line = `S + L = ${g.left} ${g.relation} P + Q = ${g.right}`;
  return g.excess === null ? line : `${line} (S + L − P − Q = ${g.excess})`;
}
