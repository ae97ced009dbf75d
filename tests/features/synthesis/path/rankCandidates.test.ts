import { describe, expect, it } from 'vitest';
import { grashofGap } from '../../../../src/features/synthesis/path/candidateFacts';
import { rankCandidates } from '../../../../src/features/synthesis/path/rankCandidates';
import type { PathSolution, PlacedFourBar } from '../../../../src/synthesis';
import { robertsCognates, sameDesign } from '../../../../src/synthesis';
import { oraclePoint } from '../../../synthesis/couplerOracle';

/** A crank-rocker with a coupler point off AB (the e2e's known design). */
const crankRocker: PlacedFourBar = {
  links: { r1: 5, r2: 1.5, r3: 4.5, r4: 4 },
  branch: 'open',
  O2: { x: 2, y: 1 },
  groundAngle: 0.35,
  pDist: 3,
  pAngle: 0.7,
};
/** A change-point linkage: 2 + 5 = 3 + 4 (S + L = P + Q exactly) with the input the shortest link. */
const changePoint: PlacedFourBar = { ...crankRocker, links: { r1: 4, r2: 2, r3: 5, r4: 3 } };
const sol = (design: PlacedFourBar, error: number, theta2 = 0.4): PathSolution => ({
  design,
  theta2: [theta2],
  error,
  maxDistance: Math.sqrt(error),
});

describe('rankCandidates', () => {
  it('lists a near-change-point design last, below worse fits, with the defect named (issue 34, 2)', () => {
    expect(grashofGap(changePoint)).toBe(0);
    // 2e-7 of the longest link off a change point (the straight line): still near one.
    const near = { ...changePoint, links: { ...changePoint.links, r3: 5 + 1e-6 } };
    const r = rankCandidates([sol(changePoint, 1e-9), sol(near, 1e-8), sol(crankRocker, 1e-3)], 10);
    expect(r.solutions.map((s) => s.design)).toEqual([crankRocker, changePoint, near]);
    expect(r.facts[0].defects.map((d) => d.kind)).not.toContain('change-point');
    expect(r.facts[1].defects.map((d) => d.kind)).toContain('change-point');
    expect(r.facts[2].defects.find((d) => d.kind === 'change-point')?.value).toBeCloseTo(1e-6 / (5 + 1e-6), 12);
  });

  it('marks a Roberts cognate of a candidate listed above it', () => {
    const [c1, c2] = robertsCognates(crankRocker, 0.4);
    // The fixture is a cognate indeed: its coupler point at its θ2 is the design's at 0.4 (independent 50 digits).
    const o = (d: PlacedFourBar, th: number) =>
      oraclePoint(
        {
          r1: d.links.r1,
          r2: d.links.r2,
          r3: d.links.r3,
          r4: d.links.r4,
          u: d.pDist * Math.cos(d.pAngle),
          v: d.pDist * Math.sin(d.pAngle),
          O2x: d.O2.x,
          O2y: d.O2.y,
          g: d.groundAngle,
          sigma: d.branch === 'open' ? 1 : -1,
        },
        th,
      )!;
    const P = o(crankRocker, 0.4);
    const Q = o(c1.design, c1.theta2);
    expect(Math.hypot(P.x - Q.x, P.y - Q.y)).toBeLessThan(1e-12);
    const other = { ...crankRocker, O2: { x: 9, y: 9 } };
    const r = rankCandidates([sol(crankRocker, 1e-4), sol(other, 2e-4), sol(c1.design, 3e-4, c1.theta2)], 10);
    const at = r.solutions.findIndex((s) => s.design === c1.design);
    expect(r.cognateOf[at]).toBe(1);
    expect(r.cognateOf[r.solutions.findIndex((s) => s.design === other)]).toBe(null);
    expect(r.cognateOf[0]).toBe(null);
    expect(sameDesign(c2.design, crankRocker, 10)).toBe(false);
  });
});

describe('sameDesign', () => {
  it('takes copies within a thousandth of the targets’ size as one linkage, and cognates and mirrors as others', () => {
    const nudge = (k: number): PlacedFourBar => ({
      ...crankRocker,
      links: { r1: 5 + k, r2: 1.5 - k, r3: 4.5 + k, r4: 4 },
      O2: { x: 2 + k, y: 1 },
      pAngle: 0.7 + k / 3,
    });
    // Size 10: a tolerance of 0.01; copies 1e-4 apart (the flat valley of an overdetermined fit) are one.
    expect(sameDesign(crankRocker, nudge(1e-4), 10)).toBe(true);
    expect(sameDesign(crankRocker, nudge(3e-2), 10)).toBe(false);
    expect(sameDesign(crankRocker, { ...crankRocker, branch: 'crossed' }, 10)).toBe(false);
    expect(sameDesign(crankRocker, { ...crankRocker, pAngle: -0.7 }, 10)).toBe(false);
    const [c1] = robertsCognates(crankRocker, 0.4);
    expect(sameDesign(crankRocker, c1.design, 10)).toBe(false);
  });
});
