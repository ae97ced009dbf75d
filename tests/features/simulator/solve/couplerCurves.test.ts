import { describe, expect, it } from 'vitest';
import type { Linkage } from '../../../../src/solver';
import { computeCycle } from '../../../../src/features/simulator/solve/compute';
import type { CouplerSpec } from '../../../../src/shared/solution';

/** The report's coupler point: 2.5 from A at 30 degrees from AB. */
const C: CouplerSpec = { distance: 2.5, angleRad: Math.PI / 6 };
const NEEDS = {
  solver: { method: 'closed-form' as const, tol: null },
  branch: 'open' as const,
  otherBranch: false,
  curves: true,
};

/** Below this |sin(theta4 - theta3)| a pose is at a limit, where the two branches meet: either sign is right. */
const AT_LIMIT = 1e-6;

/**
 * The oracle, from the lengths alone: the branch signs (sign of sin(theta4 - theta3), src/solver/types.ts)
 * of every pose that puts the coupler point at (x, y). A lies on the crank circle and at distance d from P
 * (two circle intersections); each A gives theta3 from AP, then B; a pose counts when |B - O4| = r4.
 * Returns [] when no pose closes, [0] at a limit, and both signs when two poses close.
 */
function branchSignsAt(l: Linkage, c: CouplerSpec, x: number, y: number): number[] {
  const D = Math.hypot(x, y);
  const a = (l.r2 * l.r2 - c.distance * c.distance + D * D) / (2 * D);
  const h = Math.sqrt(Math.max(0, l.r2 * l.r2 - a * a));
  const signs = new Set<number>();
  for (const s of [1, -1]) {
    const ax = (a * x - s * h * y) / D;
    const ay = (a * y + s * h * x) / D;
    const theta3 = Math.atan2(y - ay, x - ax) - c.angleRad;
    const bx = ax + l.r3 * Math.cos(theta3);
    const by = ay + l.r3 * Math.sin(theta3);
    // Loop closure to 1e-9 of the lengths: the curve points are double-precision closed-form poses (error ~1e-15).
    if (Math.abs(Math.hypot(bx - l.r1, by) - l.r4) > 1e-9 * (l.r1 + l.r2 + l.r3 + l.r4)) continue;
    const theta4 = Math.atan2(by, bx - l.r1);
    const sin = Math.sin(theta4 - theta3);
    signs.add(Math.abs(sin) < AT_LIMIT ? 0 : Math.sign(sin));
  }
  return [...signs];
}

/** The branch sign of each curve point: +1 open, -1 crossed, 0 at a limit or where both branches pass. */
function curveSigns(l: Linkage, x: Float64Array, y: Float64Array): number[] {
  return Array.from(x, (xi, i) => {
    const s = branchSignsAt(l, C, xi, y[i]);
    expect(s.length, `curve point ${i} (${xi}, ${y[i]}) is reached by no pose`).toBeGreaterThan(0);
    return s.length === 1 ? s[0] : 0;
  });
}

describe('couplerCurves of a rocking input', () => {
  // Hard case 10 (triple rocker, one circuit) and hard case 12 (Grashof double rocker, two circuits).
  const cases: [string, Linkage][] = [
    ['triple rocker', { r1: 4, r2: 3, r3: 3.5, r4: 3 }],
    ['Grashof double rocker', { r1: 4, r2: 3, r3: 1, r4: 3.5 }],
  ];
  for (const [name, l] of cases) {
    it(`goes out on the open branch and back on the crossed one, each half on its branch (${name})`, () => {
      const r = computeCycle({ linkage: l, samples: 360, coupler: C, ...NEEDS });
      const rocking = r.curves.filter((c) => c.rocking);
      expect(rocking.length).toBe(r.classification.inputRange.intervals.length);
      for (const curve of rocking) {
        expect(curve.branch).toBe('open');
        const signs = curveSigns(l, curve.x, curve.y);
        const n = signs.length;
        // The first pose is on the declared branch; then one run of open poses, one of crossed, and the
        // closing point back on the first pose's branch. Limit poses (0) may sit anywhere.
        expect(signs[0]).toBe(1);
        const definite = signs.slice(0, n - 1).filter((s) => s !== 0);
        const switches = definite.filter((s, i) => i > 0 && s !== definite[i - 1]).length;
        expect(switches).toBe(1);
        expect(definite.filter((s) => s === 1).length).toBeGreaterThan(0.4 * n);
        expect(definite.filter((s) => s === -1).length).toBeGreaterThan(0.4 * n);
        expect([1, 0]).toContain(signs[n - 1]);
      }
    });
  }
});

describe('couplerCurves of a full-turn input', () => {
  it('gives one curve per branch, every point on its own branch (hard case 1)', () => {
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    const r = computeCycle({ linkage: l, samples: 360, coupler: C, ...NEEDS, otherBranch: true });
    expect(r.curves.map((c) => [c.branch, c.rocking])).toEqual([
      ['open', false],
      ['crossed', false],
    ]);
    for (const curve of r.curves) {
      const want = curve.branch === 'open' ? 1 : -1;
      expect(curveSigns(l, curve.x, curve.y).every((s) => s === want)).toBe(true);
    }
  });
});

describe('couplerCurves resolution', () => {
  /** Longest step between consecutive curve points, over the diagonal of the curve's bounding box. */
  function longestChord(x: Float64Array, y: Float64Array): number {
    let chord = 0;
    for (let i = 1; i < x.length; i++) chord = Math.max(chord, Math.hypot(x[i] - x[i - 1], y[i] - y[i - 1]));
    const span = (a: Float64Array) => Math.max(...a) - Math.min(...a);
    return chord / Math.hypot(span(x), span(y));
  }

  it('follows the screen, not the samples chosen: no step longer than 3% of the curve, even at 36 samples', () => {
    for (const l of [
      { r1: 6, r2: 2, r3: 5, r4: 5 },
      { r1: 4, r2: 3, r3: 3.5, r4: 3 },
      { r1: 4, r2: 3, r3: 1, r4: 3.5 },
    ]) {
      for (const samples of [36, 360, 3600]) {
        const r = computeCycle({ linkage: l, samples, coupler: C, ...NEEDS });
        expect(r.curves.length).toBeGreaterThan(0);
        for (const c of r.curves) expect(longestChord(c.x, c.y)).toBeLessThan(0.03);
      }
    }
  });
});
