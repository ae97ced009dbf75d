import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { classify } from '../../../src/solver';
import type { Linkage } from '../../../src/solver';
import { grashofSums, grashofSumsText } from '../../../src/features/simulator/grashofText';
import { exact } from '../../oracle/reference';

/** The shown number read back (the display uses U+2212 for minus). */
function readBack(s: string): number {
  return Number(s.replace(/\u2212/g, '-'));
}

/** Sign of S + L − P − Q in exact arithmetic (decimal.js on the doubles' exact values). */
function exactRelation(l: Linkage): '<' | '=' | '>' {
  const [S, P, Q, L] = [l.r1, l.r2, l.r3, l.r4].sort((a, b) => a - b);
  const d = exact(S).plus(exact(L)).minus(exact(P)).minus(exact(Q));
  return d.isZero() ? '=' : d.isNegative() ? '<' : '>';
}

describe('grashofSumsText', () => {
  it('shows the default linkage as S + L = 8 < P + Q = 10', () => {
    expect(grashofSumsText(classify({ r1: 6, r2: 2, r3: 5, r4: 5 }))).toBe('S + L = 8 < P + Q = 10');
  });

  it('never reads "5 < 5": sums that round alike get more digits', () => {
    const l = { r1: 4, r2: 1, r3: 2, r4: 3.0000001 };
    expect(grashofSumsText(classify(l))).toBe('S + L = 5 < P + Q = 5.0000001');
    const far = { r1: 4, r2: 1, r3: 2, r4: 2.9999999 };
    expect(grashofSumsText(classify(far))).toBe('S + L = 5 > P + Q = 4.9999999');
  });

  it('says = for a change point, as the verdict does', () => {
    expect(grashofSumsText(classify({ r1: 4, r2: 2, r3: 4, r4: 2 }))).toBe('S + L = 6 = P + Q = 6');
    expect(grashofSums(classify({ r1: 0.1, r2: 0.2, r3: 0.3, r4: 0.4 })).relation).toBe('=');
  });

  it('shows the exact excess if the two sums were ever the same double under a strict relation', () => {
    // classify() calls sums within 4 ulps of the total a change point, so this is a guard for other callers:
    // S + L = 1 + 2^-60 rounds to 1 = P + Q, yet S + L − P − Q = 2^-60 exactly.
    const c = { S: 2 ** -60, L: 1, P: 0.5, Q: 0.5, type: 'triple-rocker' as const, grashof: false };
    expect(c.S + c.L).toBe(c.P + c.Q);
    expect(grashofSumsText(c)).toBe('S + L = 1 > P + Q = 1 (S + L − P − Q = 8.7e−19)');
  });

  it('agrees with the exact relation, and its numbers read back in that order (seeded property)', () => {
    // Near-change-point linkages: the fourth link is P + Q − S of the other three, nudged by a few ulps to 1e-6.
    const base = fc.double({ min: 0.5, max: 5, noNaN: true });
    const nudge = fc.oneof(
      fc.integer({ min: -8, max: 8 }).map((k) => k * 2 ** -50),
      fc.double({ min: -1e-6, max: 1e-6, noNaN: true }),
    );
    fc.assert(
      fc.property(base, base, base, nudge, (a, b, c, e) => {
        const [S, P, Q] = [a, b, c].sort((x, y) => x - y);
        const L = P + Q - S + e;
        if (!(L >= Q)) return;
        const l = { r1: S, r2: P, r3: Q, r4: L };
        const g = grashofSums(classify(l));
        const truth = exactRelation(l);
        if (g.relation === '=') {
          // Change point within the classification's few ulps of the total: the exact sign may be any.
          expect(g.left).toBe(g.right);
          return;
        }
        expect(g.relation).toBe(truth);
        if (g.excess === null) {
          const left = readBack(g.left);
          const right = readBack(g.right);
          expect(g.relation === '<' ? left < right : left > right).toBe(true);
        }
      }),
      { seed: 20251222, numRuns: 500 },
    );
  });
});
