import { describe, expect, it } from 'vitest';
import {
  FIT_MIN_PAD_PX,
  fitView,
  niceStep,
  toScreenX,
  toScreenY,
  toWorld,
  zoomAbout,
} from '../../../src/shared/canvas/view';

const NO_OFFSET = { zoom: 1, panX: 0, panY: 0 };

describe('fitView', () => {
  it('draws the same picture whatever the unit (1e-7, 1, 1e7)', () => {
    const pics = [1e-7, 1, 1e7].map((k) => {
      const v = fitView({ minX: -2 * k, minY: -1 * k, maxX: 8 * k, maxY: 5 * k }, 800, 500, NO_OFFSET);
      return [toScreenX(v, 6 * k), toScreenY(v, 2 * k), toScreenX(v, -2 * k), toScreenY(v, 5 * k)];
    });
    for (const p of pics.slice(1)) for (let i = 0; i < 4; i++) expect(p[i]).toBeCloseTo(pics[0][i], 6);
  });

  it('keeps the bounds inside the view with a margin and y pointing up', () => {
    const v = fitView({ minX: 0, minY: 0, maxX: 10, maxY: 10 }, 400, 200, NO_OFFSET);
    expect(toScreenY(v, 10)).toBeLessThan(toScreenY(v, 0));
    for (const [x, y] of [
      [0, 0],
      [10, 10],
    ]) {
      expect(toScreenX(v, x)).toBeGreaterThan(0);
      expect(toScreenX(v, x)).toBeLessThan(400);
      expect(toScreenY(v, y)).toBeGreaterThanOrEqual(200 * 0.08 - 1e-9);
      expect(toScreenY(v, y)).toBeLessThanOrEqual(200 * 0.92 + 1e-9);
    }
  });

  it('leaves at least FIT_MIN_PAD_PX around the bounds for the angle arcs, a quarter side in a tiny view', () => {
    for (const [w, h, pad] of [
      [342, 392, FIT_MIN_PAD_PX],
      [1000, 300, FIT_MIN_PAD_PX],
      [100, 80, 20],
    ]) {
      const v = fitView({ minX: -2, minY: -2, maxX: 9, maxY: 7 }, w, h, NO_OFFSET);
      const xs = [toScreenX(v, -2), toScreenX(v, 9)];
      const ys = [toScreenY(v, 7), toScreenY(v, -2)];
      // One axis is tight (touches the pad within rounding), the other has room to spare.
      const gaps = [xs[0], w - xs[1], ys[0], h - ys[1]];
      expect(Math.min(...gaps)).toBeCloseTo(pad, 9);
    }
  });

  it('survives empty and single-point bounds', () => {
    const empty = fitView({ minX: Infinity, minY: Infinity, maxX: -Infinity, maxY: -Infinity }, 300, 300, NO_OFFSET);
    expect(Number.isFinite(empty.scale)).toBe(true);
    const point = fitView({ minX: 3, minY: 3, maxX: 3, maxY: 3 }, 300, 300, NO_OFFSET);
    expect(Number.isFinite(point.scale) && point.scale > 0).toBe(true);
  });

  it('inverts with toWorld', () => {
    const v = fitView({ minX: -1, minY: -1, maxX: 1, maxY: 1 }, 640, 480, { zoom: 2, panX: 0.1, panY: -0.2 });
    const w = toWorld(v, toScreenX(v, 0.3), toScreenY(v, -0.7));
    expect(w.x).toBeCloseTo(0.3, 12);
    expect(w.y).toBeCloseTo(-0.7, 12);
  });
});

describe('zoomAbout', () => {
  it('keeps the world point under the cursor in place', () => {
    const bounds = { minX: -1, minY: -1, maxX: 5, maxY: 3 };
    const before = fitView(bounds, 600, 400, NO_OFFSET);
    const w = toWorld(before, 150, 120);
    const after = fitView(bounds, 600, 400, zoomAbout(NO_OFFSET, 2, 150, 120, 600, 400));
    expect(toScreenX(after, w.x)).toBeCloseTo(150, 9);
    expect(toScreenY(after, w.y)).toBeCloseTo(120, 9);
  });
});

describe('niceStep', () => {
  it('gives 1, 2 or 5 times a power of ten at any scale', () => {
    expect(niceStep(60, 60)).toBe(1);
    expect(niceStep(30, 60)).toBe(2);
    expect(niceStep(6e8, 60)).toBeCloseTo(1e-7, 20);
    expect(niceStep(1.2e-5, 60)).toBe(5e6);
  });
});
