import { describe, expect, it } from 'vitest';
import { classify } from '../../src/solver';
import { robertsCognates } from '../../src/synthesis/cognates';
import { placedCouplerPoint } from '../../src/synthesis/placed';
import { createRandom } from '../../src/synthesis/random';
import type { PlacedFourBar } from '../../src/synthesis/types';

type Pt = { x: number; y: number };

/** The two intersections of the circles |X − c1| = r1 and |X − c2| = r2 (none when they do not meet). */
function circles(c1: Pt, r1: number, c2: Pt, r2: number): Pt[] {
  const dx = c2.x - c1.x;
  const dy = c2.y - c1.y;
  const d = Math.hypot(dx, dy);
  if (!(d > 0)) return [];
  const a = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
  const h2 = r1 * r1 - a * a;
  // A tangency rounded to a slightly negative h² still meets: clamp within rounding of the radii.
  if (h2 < -1e-9 * Math.max(r1, r2) ** 2) return [];
  const h = Math.sqrt(Math.max(0, h2));
  const mx = c1.x + (a * dx) / d;
  const my = c1.y + (a * dy) / d;
  return [
    { x: mx - (h * dy) / d, y: my + (h * dx) / d },
    { x: mx + (h * dy) / d, y: my - (h * dx) / d },
  ];
}

/**
 * Independent check that P lies on a design's coupler curve: some pin A on the crank circle at |AP| = pDist and
 * some pin B on the rocker circle at |BP| = |BP| of the coupler triangle are r3 apart, with the triangle A B P
 * turning the same way as the design's (the sign of sin pAngle). Returns the smallest | |AB| − r3 | / r3 found.
 */
function couplerMiss(d: PlacedFourBar, P: Pt): number {
  const { r1, r2, r3, r4 } = d.links;
  const O4 = { x: d.O2.x + r1 * Math.cos(d.groundAngle), y: d.O2.y + r1 * Math.sin(d.groundAngle) };
  const bp = Math.sqrt(r3 * r3 + d.pDist * d.pDist - 2 * r3 * d.pDist * Math.cos(d.pAngle));
  const side = Math.sign(Math.sin(d.pAngle));
  let best = Infinity;
  for (const A of circles(d.O2, r2, P, d.pDist)) {
    for (const B of circles(O4, r4, P, bp)) {
      const cross = (B.x - A.x) * (P.y - A.y) - (B.y - A.y) * (P.x - A.x);
      // P on the line AB (side 0) matches either way; otherwise the triangle must turn as the design's.
      if (side !== 0 && Math.sign(cross) !== side) continue;
      best = Math.min(best, Math.abs(Math.hypot(B.x - A.x, B.y - A.y) - r3) / r3);
    }
  }
  return best;
}

function randomDesign(rand: () => number): PlacedFourBar {
  const len = () => 0.5 + 4 * rand();
  return {
    links: { r1: len(), r2: len(), r3: len(), r4: len() },
    branch: rand() < 0.5 ? 'open' : 'crossed',
    O2: { x: 10 * rand() - 5, y: 10 * rand() - 5 },
    groundAngle: 6 * rand() - 3,
    pDist: 0.2 + 3 * rand(),
    pAngle: 6 * rand() - 3,
  };
}

const CRANK_ROCKER: PlacedFourBar = {
  links: { r1: 6, r2: 2, r3: 5, r4: 5 },
  branch: 'open',
  O2: { x: 1, y: -2 },
  groundAngle: 0.4,
  pDist: 2.5,
  pAngle: 0.5,
};

describe('robertsCognates', () => {
  it('gives two four-bars whose coupler point passes through the original curve at sampled inputs', () => {
    const rand = createRandom(2024);
    let checked = 0;
    for (let k = 0; k < 60; k++) {
      const d = k === 0 ? CRANK_ROCKER : randomDesign(rand);
      let cognates;
      try {
        cognates = robertsCognates(d);
      } catch {
        continue; // designs that cannot assemble anywhere have no cognates to check
      }
      for (let i = 0; i < 72; i++) {
        const P = placedCouplerPoint(d, (i * 2 * Math.PI) / 72);
        if (!P) continue;
        // The oracle solves two circle intersections of lengths of order 1 to 10: 1e-9 relative is rounding x 1e6.
        for (const c of cognates) expect(couplerMiss(c.design, P)).toBeLessThan(1e-9);
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(1000);
  });

  it('obeys Roberts’ law: link ratios |z| and |1 − z|, and the fixed pivots make a triangle like ABP', () => {
    const d = CRANK_ROCKER;
    const z = d.pDist / d.links.r3;
    const w = Math.hypot(1 - z * Math.cos(d.pAngle), z * Math.sin(d.pAngle));
    const [c1, c2] = robertsCognates(d);
    const sorted = (l: PlacedFourBar['links']) => [l.r1, l.r2, l.r3, l.r4].sort((a, b) => a - b);
    const { r1, r2, r3, r4 } = d.links;
    expect(sorted(c1.design.links)).toEqual(
      sorted({ r1: z * r1, r2: z * r3, r3: z * r2, r4: z * r4 }).map((x) => expect.closeTo(x, 12)),
    );
    expect(sorted(c2.design.links)).toEqual(
      sorted({ r1: w * r1, r2: w * r3, r3: w * r4, r4: w * r2 }).map((x) => expect.closeTo(x, 12)),
    );
    // The three fixed pivots: O_A, O_B and the new one O_C; |O_A O_C| / |O_A O_B| = |AP| / |AB|.
    const pivots = [c1.design, c2.design].flatMap((c) => [
      c.O2,
      { x: c.O2.x + c.links.r1 * Math.cos(c.groundAngle), y: c.O2.y + c.links.r1 * Math.sin(c.groundAngle) },
    ]);
    const OA = d.O2;
    const OB = { x: OA.x + r1 * Math.cos(d.groundAngle), y: OA.y + r1 * Math.sin(d.groundAngle) };
    const far = (p: Pt) => Math.min(Math.hypot(p.x - OA.x, p.y - OA.y), Math.hypot(p.x - OB.x, p.y - OB.y)) > 1e-9;
    const OC = pivots.find(far)!;
    expect(Math.hypot(OC.x - OA.x, OC.y - OA.y) / r1).toBeCloseTo(z, 12);
  });

  it('drives a cognate from the pivot that makes its input a crank when one does', () => {
    // Grashof's rule written here: the input turns fully when S + L < P + Q and the input or the ground is shortest.
    const crankInput = (r1: number, r2: number, r3: number, r4: number) => {
      const s = [r1, r2, r3, r4].sort((a, b) => a - b);
      return s[0] + s[3] < s[1] + s[2] && (r2 === s[0] || r1 === s[0]);
    };
    const rand = createRandom(7);
    let either = 0;
    for (let k = 0; k < 80; k++) {
      const d = k === 0 ? CRANK_ROCKER : randomDesign(rand);
      let cognates;
      try {
        cognates = robertsCognates(d);
      } catch {
        continue;
      }
      for (const c of cognates) {
        const { r1, r2, r3, r4 } = c.design.links;
        // The other driver swaps the links at the two pivots.
        const can = crankInput(r1, r2, r3, r4) || crankInput(r1, r4, r3, r2);
        if (can) either++;
        expect(classify(c.design.links).inputIsCrank).toBe(can);
      }
    }
    expect(either).toBeGreaterThan(5);
  });

  it('throws for a design that is not a placed four-bar', () => {
    expect(() => robertsCognates({ ...CRANK_ROCKER, pDist: NaN })).toThrow(/pDist/);
  });
});
