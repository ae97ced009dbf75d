import { describe, expect, it } from 'vitest';
import { classify, designMetrics, linkRates, solveClosedForm } from '../../src/solver';
import type { Linkage } from '../../src/solver';
import { classifyRSSR, classifySpherical, outputMotion, solveRSSR, solveSpherical } from '../../src/spatial';
import { angleGap } from './oracle';

/** Planar cases of docs/hard-cases.md: crank-rocker, triple rockers, a double rocker, a drag link, a long ground. */
const CASES: Linkage[] = [
  { r1: 6, r2: 2, r3: 5, r4: 5 },
  { r1: 4, r2: 3, r3: 3.5, r4: 3 },
  { r1: 3, r2: 2.5, r3: 4.2, r4: 1.5 },
  { r1: 4, r2: 3, r3: 1, r4: 3.5 },
  { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 },
  { r1: 1e6, r2: 1, r3: 1e6 + 0.5, r4: 2 },
];
const rssrOf = (l: Linkage) => ({ r2: l.r2, r3: l.r3, r4: l.r4, a: l.r1, beta: 0, h2: 0, h4: 0 });
const GRID = Array.from({ length: 73 }, (_, i) => -Math.PI + (i * 2 * Math.PI) / 72 + 0.001);

describe('solveRSSR in the planar limit (beta = h2 = h4 = 0)', () => {
  it("is src/solver's solveClosedForm: same reach, same theta4 on the same branch", () => {
    for (const l of CASES) {
      for (const t2 of GRID) {
        for (const branch of ['open', 'crossed'] as const) {
          const planar = solveClosedForm(l, t2, branch);
          const s = solveRSSR(rssrOf(l), t2, branch);
          expect(s === null, `${JSON.stringify(l)} ${t2}`).toBe(planar === null);
          if (!s || !planar) continue;
          // Both are stable closed forms of well-conditioned points. The long ground (1e6 against 1) has an inherent error
          // of 1.7e-10 rad (docs/hard-cases.md case 16): src/spatial is backward stable, src/solver does better there.
          const tol = l.r1 === 1e6 ? 2e-10 : 1e-13;
          expect(Math.abs(angleGap(s.theta4, planar.theta4))).toBeLessThan(tol);
          expect(s.B.z).toBe(0);
        }
      }
    }
  });

  it("has src/solver's rates (linkRates) with omega2 = 2, alpha2 = 0.5", () => {
    const l = CASES[0];
    for (const t2 of GRID) {
      const planar = solveClosedForm(l, t2, 'open')!;
      const r = linkRates(l, t2, planar, { omega2: 2, alpha2: 0.5 });
      const s = solveRSSR(rssrOf(l), t2, 'open', { omega2: 2, alpha2: 0.5 })!;
      expect(Math.abs(s.omega4 - r.omega4)).toBeLessThan(1e-13);
      expect(Math.abs(s.alpha4 - r.alpha4)).toBeLessThan(1e-12);
    }
  });

  it("classifies and ranges as src/solver's classify, and its swing and dead centres are designMetrics'", () => {
    for (const l of CASES.slice(0, 5)) {
      const planar = classify(l).inputRange;
      const c = classifyRSSR(rssrOf(l));
      expect(c.inputIsCrank).toBe(planar.full);
      expect(c.inputRange.intervals.length).toBe(planar.intervals.length);
      const sortLo = (a: { lo: number }, b: { lo: number }) => a.lo - b.lo;
      const want = [...planar.intervals].sort(sortLo);
      c.inputRange.intervals.forEach((iv, i) => {
        // Bisected to the double on the solver's own test; classify rounds its closed form inward.
        expect(Math.abs(iv.lo - want[i].lo)).toBeLessThan(1e-12);
        expect(Math.abs(iv.hi - want[i].hi)).toBeLessThan(1e-12);
      });
    }
    const m = designMetrics(CASES[0], 'open');
    const motion = outputMotion({ kind: 'rssr', linkage: rssrOf(CASES[0]) }, 'open');
    expect(Math.abs(motion.swings[0].swing - m.output!.swing!)).toBeLessThan(1e-12);
    const byTheta2 = [...motion.deadCentres].sort((a, b) => a.theta2 - b.theta2);
    expect(Math.abs(byTheta2[0].theta2 - m.output!.folded!.theta2)).toBeLessThan(1e-9);
    expect(Math.abs(byTheta2[1].theta2 - m.output!.extended!.theta2)).toBeLessThan(1e-9);
    expect(Math.abs(byTheta2[0].theta4 - m.output!.folded!.theta4)).toBeLessThan(1e-12);
    expect(Math.abs(motion.transmission!.min - m.transmission.min)).toBeLessThan(1e-9);
    expect(Math.abs(motion.transmission!.max - m.transmission.max)).toBeLessThan(1e-9);
  });
});

describe('solveSpherical in the planar limit (arcs scaled to 1e-6 rad)', () => {
  const E = 1e-6;
  const arcsOf = (l: Linkage) => ({ a1: E * l.r1, a2: E * l.r2, a3: E * l.r3, a4: E * l.r4 });

  it('is the planar four-bar to O(arc^2): same reach, same theta4 on the same branch', () => {
    for (const l of CASES.slice(0, 5)) {
      for (const t2 of GRID) {
        for (const branch of ['open', 'crossed'] as const) {
          const planar = solveClosedForm(l, t2, branch);
          const s = solveSpherical(arcsOf(l), t2, branch);
          if (planar && Math.abs(Math.sin(planar.theta4 - planar.theta3)) < 0.05) continue; // O(E^2)/sin(mu) near a limit
          expect(s === null, `${JSON.stringify(l)} ${t2}`).toBe(planar === null);
          if (!s || !planar) continue;
          // The sphere departs from the plane by relative O(arc^2) = 1e-12; the conditioning adds up to 1 / 0.05.
          expect(Math.abs(angleGap(s.theta4, planar.theta4))).toBeLessThan(1e-10);
        }
      }
    }
  });

  it('classifies as the planar four-bar and reaches the same input range', () => {
    for (const l of CASES.slice(0, 5)) {
      const planar = classify(l);
      const c = classifySpherical(arcsOf(l));
      expect(c.inputIsCrank).toBe(planar.inputRange.full);
      expect(c.grashof).toBe(planar.grashof);
      const want = [...planar.inputRange.intervals].sort((a, b) => a.lo - b.lo);
      c.inputRange.intervals.forEach((iv, i) => {
        expect(Math.abs(iv.lo - want[i].lo)).toBeLessThan(1e-9);
        expect(Math.abs(iv.hi - want[i].hi)).toBeLessThan(1e-9);
      });
    }
  });
});
