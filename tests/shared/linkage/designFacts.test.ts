import { describe, expect, it } from 'vitest';
import { solveClosedForm } from '../../../src/solver/closedForm';
import { inputRange } from '../../../src/solver/classify';
import { designMetrics } from '../../../src/solver/metrics';
import type { Branch, Linkage } from '../../../src/solver/types';
import { deadCentreMarks, designFacts } from '../../../src/shared/linkage/designFacts';

const REPORT: Linkage = { r1: 6, r2: 2, r3: 5, r4: 5 };
const facts = (l: Linkage, b: Branch) => {
  const f = designFacts(designMetrics(l, b), inputRange(l));
  if (!f) throw new Error(`no facts for ${JSON.stringify(l)}`);
  return f;
};

/** Law of cosines in degrees, plain doubles: well conditioned for the lengths used here (oracle side). */
const acosDeg = (c: number) => (Math.acos(c) * 180) / Math.PI;

describe('designFacts', () => {
  it("shows the report's 6-2-5-5 values to three decimals, theta2 in [0, 360)", () => {
    const f = facts(REPORT, 'open');
    expect(f.muMinText).toBe('47.156°');
    expect(f.muMinAt.theta2Text).toBe('0.000');
    expect(f.muMaxText).toBe('106.260°');
    expect(f.muMaxAt.theta2Text).toBe('180.000');
    expect(f.deadCentres?.map((d) => [d.kind, d.theta2Text, d.theta4Text])).toEqual([
      ['extended', '44.415', '101.537'],
      ['folded', '236.251', '150.074'],
    ]);
    expect(f.swingText).toBe('48.537°');
    expect(f.timeRatioText).toBe('1.1408');
    expect(f.limits).toEqual([]);
  });

  it('agrees with the law of cosines at the dead centres (independent oracle, 1e-9 deg)', () => {
    const f = facts(REPORT, 'open');
    // Extended: triangle O2 O4 B with sides r1, r2 + r3, r4; folded: r1, r3 - r2, r4. Angle at O2.
    const ext = acosDeg((36 + 49 - 25) / (2 * 6 * 7));
    const fold = 360 - (180 - acosDeg((36 + 9 - 25) / (2 * 6 * 3)));
    expect(Math.abs(f.deadCentres![0].theta2Deg - ext)).toBeLessThan(1e-9);
    expect(Math.abs(f.deadCentres![1].theta2Deg - fold)).toBeLessThan(1e-9);
  });

  it('mirrors the dead centres on the crossed branch (theta2 negated, in the slider convention)', () => {
    const f = facts(REPORT, 'crossed');
    expect(f.deadCentres?.map((d) => d.theta2Text)).toEqual(['315.585', '123.749']);
    expect(f.deadCentres?.map((d) => d.theta4Text)).toEqual(['−101.537', '−150.074']);
    expect(f.timeRatioText).toBe('1.1408');
  });

  it('has no dead centres, swing or time ratio for a double crank', () => {
    const f = facts({ r1: 2, r2: 5, r3: 5, r4: 6 }, 'open');
    expect(f.deadCentres).toBeNull();
    expect(f.swingText).toBeNull();
    expect(f.timeRatioText).toBeNull();
  });

  it("lists a rocking input's limits, with go-to targets where the linkage assembles", () => {
    // Non-Grashof (2.5 + 5 > 3 + 4) with |r3 - r4| < |r1 - r2|: one interval through theta2 = 0, whose
    // limits are where s = |A O4| reaches r3 + r4 = 6.5.
    const l: Linkage = { r1: 5, r2: 3, r3: 2.5, r4: 4 };
    const f = facts(l, 'open');
    expect(f.deadCentres).toBeNull();
    const limit = acosDeg((25 + 9 - 6.5 * 6.5) / (2 * 5 * 3));
    expect(f.limits.map((s) => s.theta2Text)).toEqual([(360 - limit).toFixed(3), limit.toFixed(3)]);
    for (const s of f.limits) {
      // Targets lie within 1e-6 deg of the limit, on the reachable side: both branches assemble there.
      const shown = Number(s.theta2Text);
      expect(Math.abs(s.theta2Deg - shown)).toBeLessThan(1e-3);
      for (const b of ['open', 'crossed'] as const) {
        expect(solveClosedForm(l, (s.theta2Deg * Math.PI) / 180, b)).not.toBeNull();
      }
    }
  });
});

describe('designFacts of a linkage that assembles nowhere', () => {
  it('gives nothing to show (no μ with a dash, no θ2 = 0.000°), for 13-2-5-5 as for a far-too-long ground', () => {
    for (const l of [
      { r1: 13, r2: 2, r3: 5, r4: 5 },
      { r1: 100, r2: 1, r3: 1, r4: 1 },
    ])
      expect(designFacts(designMetrics(l, 'open'), inputRange(l))).toBeNull();
  });
});

describe('deadCentreMarks', () => {
  it('gives the dead-centre theta2 of a crank-rocker in [0, 360) and nothing otherwise', () => {
    const marks = deadCentreMarks(designMetrics(REPORT, 'open'));
    expect(marks.map((m) => m.kind)).toEqual(['extended', 'folded']);
    expect(marks[0].theta2Deg).toBeCloseTo(44.415, 3);
    expect(marks[1].theta2Deg).toBeCloseTo(236.251, 3);
    expect(deadCentreMarks(designMetrics({ r1: 2, r2: 5, r3: 5, r4: 6 }, 'open'))).toEqual([]);
    expect(deadCentreMarks(null)).toEqual([]);
  });
});
