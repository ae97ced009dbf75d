import { describe, expect, it } from 'vitest';
import { sceneBounds, sceneCurves, scenePose } from '../../../src/shared/linkage/scene';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };

describe('scenePose', () => {
  it('places the joints from the angles, with the rocker closing the loop', () => {
    // Hard case 1 at theta2 = 90 deg, open branch: (32.3335306935, 110.7965716607) deg.
    const d = Math.PI / 180;
    const p = scenePose(
      L,
      { theta2: 90 * d, theta3: 32.3335306935 * d, theta4: 110.7965716607 * d, mu: 0 },
      { distance: 0, angleRad: 0 },
    );
    if (!p) throw new Error('expected a pose');
    expect(Math.hypot(p.B.x - p.O4.x, p.B.y - p.O4.y)).toBeCloseTo(5, 8);
    expect(p.P).toEqual(p.A);
  });
  it('gives no pose (never a torn one) for missing or non-finite angles', () => {
    expect(scenePose(L, null, { distance: 1, angleRad: 0 })).toBeNull();
    expect(scenePose(L, { theta2: 0, theta3: Number.NaN, theta4: 0, mu: 0 }, { distance: 1, angleRad: 0 })).toBeNull();
  });
});

describe('sceneCurves', () => {
  it('marks the current branch curve of a crank and the circuit holding theta2 of a rocker', () => {
    const xs = new Float64Array(2);
    const full = [
      { x: xs, y: xs, branch: 'open' as const, rocking: false, loRad: Number.NaN, hiRad: Number.NaN },
      { x: xs, y: xs, branch: 'crossed' as const, rocking: false, loRad: Number.NaN, hiRad: Number.NaN },
    ];
    expect(sceneCurves(full, 'crossed', 0).map((c) => c.current)).toEqual([false, true]);
    const rocking = [
      { x: xs, y: xs, branch: 'open' as const, rocking: true, loRad: 0.6, hiRad: 1.4 },
      { x: xs, y: xs, branch: 'open' as const, rocking: true, loRad: -1.4, hiRad: -0.6 },
    ];
    expect(sceneCurves(rocking, 'open', 1).map((c) => c.current)).toEqual([true, false]);
    expect(sceneCurves(rocking, 'open', 2 * Math.PI - 1).map((c) => c.current)).toEqual([false, true]);
  });
});

describe('sceneBounds', () => {
  it('covers the crank circle, both pivots and the rocker reach before a cycle exists', () => {
    const b = sceneBounds(L, [], [], []);
    expect(b.minX).toBeLessThanOrEqual(-2);
    expect(b.maxX).toBeGreaterThanOrEqual(11);
  });
  it('ignores NaN samples (gaps)', () => {
    const b = sceneBounds(L, [{ theta4: [Number.NaN, Math.PI / 2], px: [Number.NaN, 1], py: [Number.NaN, 7] }], [], []);
    expect(b.maxY).toBe(7);
    expect(Number.isFinite(b.minX)).toBe(true);
  });
});
