import { describe, expect, it } from 'vitest';
import { couplerAt, crankAngleAt, grabRadiusPx, hitHandle, pinchView } from '../../../src/shared/canvas/canvasGestures';
import { couplerPoint } from '../../../src/solver/kinematics';
import type { LinkageScene } from '../../../src/shared/linkage/scene';
import { scenePose } from '../../../src/shared/linkage/scene';
import { fitView, toScreenX, toScreenY, toWorld } from '../../../src/shared/canvas/view';

const L = { r1: 6, r2: 2, r3: 5, r4: 5 };
const D = Math.PI / 180;
// Hard case 1 at theta2 = 90°, open branch: (32.3335306935°, 110.7965716607°).
const ANGLES = { theta2: 90 * D, theta3: 32.3335306935 * D, theta4: 110.7965716607 * D, mu: 0 };
const COUPLER = { distance: 2.5, angleRad: 30 * D };
const BOUNDS = { minX: -2, minY: -2, maxX: 11, maxY: 7 };
const VIEW = fitView(BOUNDS, 800, 500, { zoom: 1.5, panX: 0.1, panY: -0.05 });

function scene(): LinkageScene {
  const pose = scenePose(L, ANGLES, COUPLER);
  if (!pose) throw new Error('expected a pose');
  return { pose, bounds: BOUNDS } as unknown as LinkageScene;
}
const screen = (p: { x: number; y: number }) => ({ x: toScreenX(VIEW, p.x), y: toScreenY(VIEW, p.y) });

describe('crankAngleAt', () => {
  it('points the crank at the pointer, in degrees [0, 360) to 0.01°', () => {
    for (const deg of [0, 12.34, 90, 179.99, 180, 200.5, 270, 359.99]) {
      // Any radius along the ray gives the same angle: the crank pin follows the direction from O2.
      for (const r of [0.5, 2, 7]) {
        const at = screen({ x: r * Math.cos(deg * D), y: r * Math.sin(deg * D) });
        expect(crankAngleAt(VIEW, at)).toBeCloseTo(deg, 2);
      }
    }
  });
  it('never gives 360 (a pointer just below the ground line gives 359.99 or 0)', () => {
    const at = screen({ x: 3, y: -1e-9 });
    expect(crankAngleAt(VIEW, at)).toBe(0);
  });
});

describe('couplerAt', () => {
  it('inverts couplerPoint: the coupler point put under the pointer lands there', () => {
    const s = scene();
    for (const [d, aDeg] of [
      [2.5, 30],
      [1, -150],
      [6.25, 179],
      [0.75, -90],
    ]) {
      const P = couplerPoint(L, ANGLES.theta2, ANGLES.theta3, d, aDeg * D);
      const c = couplerAt(s, VIEW, screen(P));
      if (!c) throw new Error('expected a coupler point');
      // The screen round trip and 4 significant digits leave about 1e-4 relative; angles to 0.01°.
      expect(c.distance).toBeCloseTo(d, 3);
      expect(c.angleDeg).toBeCloseTo(aDeg, 1);
    }
  });
  it('gives the angle in (-180, 180] and distance 0 on A itself', () => {
    const s = scene();
    const c = couplerAt(s, VIEW, screen(s.pose!.A));
    expect(c?.distance).toBeLessThan(1e-3);
    const behind = couplerPoint(L, ANGLES.theta2, ANGLES.theta3, 2, 180 * D);
    expect(couplerAt(s, VIEW, screen(behind))?.angleDeg).toBeCloseTo(180, 1);
  });
  it('gives nothing without a pose', () => {
    expect(couplerAt({ pose: null } as unknown as LinkageScene, VIEW, { x: 1, y: 1 })).toBeNull();
  });
});

describe('hitHandle', () => {
  const all = { A: true, P: true };
  it('grabs A or P within the radius and nothing elsewhere', () => {
    const s = scene();
    const a = screen(s.pose!.A);
    const p = screen(s.pose!.P);
    expect(hitHandle(s, VIEW, { x: a.x + 8, y: a.y }, 12, all)).toBe('A');
    expect(hitHandle(s, VIEW, { x: p.x, y: p.y - 8 }, 12, all)).toBe('P');
    expect(hitHandle(s, VIEW, { x: a.x + 13, y: a.y }, 12, all)).toBeNull();
  });
  it('leaves a locked handle alone and picks the nearer of two', () => {
    const s = scene();
    const a = screen(s.pose!.A);
    const p = screen(s.pose!.P);
    expect(hitHandle(s, VIEW, a, 12, { A: false, P: true })).toBeNull();
    const nearP = { x: p.x + 0.25 * (a.x - p.x), y: p.y + 0.25 * (a.y - p.y) };
    expect(hitHandle(s, VIEW, nearP, 1e6, all)).toBe('P');
  });
  it('gives a finger more room than a mouse', () => {
    expect(grabRadiusPx('touch')).toBeGreaterThan(grabRadiusPx('mouse'));
  });
});

describe('pinchView', () => {
  it('zooms by the ratio of finger distances and keeps the world point under the fingers under them', () => {
    const start = { zoom: 1.5, panX: 0.1, panY: -0.05 };
    const a0 = { x: 300, y: 200 };
    const b0 = { x: 400, y: 260 };
    // Spread to twice the distance and move the midpoint by (40, -25).
    const m0 = { x: 350, y: 230 };
    const a1 = { x: m0.x + 40 - 100, y: m0.y - 25 - 60 };
    const b1 = { x: m0.x + 40 + 100, y: m0.y - 25 + 60 };
    const v = pinchView(start, a0, b0, a1, b1, 800, 500);
    expect(v.zoom).toBeCloseTo(3, 12);
    const before = toWorld(fitView(BOUNDS, 800, 500, start), m0.x, m0.y);
    const after = toWorld(fitView(BOUNDS, 800, 500, v), m0.x + 40, m0.y - 25);
    expect(after.x).toBeCloseTo(before.x, 9);
    expect(after.y).toBeCloseTo(before.y, 9);
  });
  it('only pans when the fingers keep their distance', () => {
    const start = { zoom: 1, panX: 0, panY: 0 };
    const v = pinchView(start, { x: 0, y: 0 }, { x: 100, y: 0 }, { x: 80, y: 50 }, { x: 180, y: 50 }, 800, 500);
    expect(v).toEqual({ zoom: 1, panX: 0.1, panY: 0.1 });
  });
});
