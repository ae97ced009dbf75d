import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import { ribbonIndex, ribbonInto } from '../../../src/features/spatial/screenRibbon';
import type { RibbonView } from '../../../src/features/spatial/screenRibbon';
import { seeded } from '../../spatial/random';

Decimal.set({ precision: 40 });
const FOV_DEG = 32;
const HEIGHT_PX = 600;
/** tan(fov/2) in high precision (the oracle's own, not the code's Math.tan). */
const TAN_HALF = new Decimal(FOV_DEG).div(2).times(Decimal.acos(-1)).div(180).tan();
const UNITS_PER_PX = TAN_HALF.times(2).div(HEIGHT_PX).toNumber();
/** Pixels from the centre of a pinhole camera at the origin looking along −z, for a point at (x, y, z). */
const projectPx = (x: number, y: number, z: number): [number, number] => {
  const f = new Decimal(HEIGHT_PX).div(2).div(TAN_HALF);
  return [f.times(x).div(-z).toNumber(), f.times(y).div(-z).toNumber()];
};

const VIEW: RibbonView = { eye: [0, 0, 0], forward: [0, 0, -1], perspective: true, unitsPerPx: UNITS_PER_PX };

describe('ribbonInto', () => {
  it('spans widthPx on screen across a line face-on at the centre of a perspective view, at any depth', () => {
    // Off the axis it grows a little towards the view's edge (Line2 keeps it exact): the look needs no more.
    for (const depth of [0.5, 3, 40]) {
      const e = 1e-3 * depth;
      const points = new Float32Array([-e, 0, -depth, 0, 0, -depth, e, 0, -depth]);
      const out = new Float32Array(18);
      ribbonInto(out, points, 3, VIEW, 7);
      for (let i = 0; i < 3; i++) {
        const top = projectPx(out[6 * i], out[6 * i + 1], out[6 * i + 2]);
        const bottom = projectPx(out[6 * i + 3], out[6 * i + 4], out[6 * i + 5]);
        // Float32 buffers: about 1e-7 relative on each coordinate.
        expect(Math.abs(top[1] - bottom[1])).toBeCloseTo(7, 4);
        expect(top[0]).toBeCloseTo(bottom[0], 4);
      }
    }
  });

  it('spans widthPx·unitsPerPx scene units in an orthographic view, whatever the depth', () => {
    const ortho: RibbonView = { eye: [0, 0, 10], forward: [0, 0, -1], perspective: false, unitsPerPx: 0.01 };
    const points = new Float32Array([0, 0, -3, 1, 0, 2]);
    const out = new Float32Array(12);
    ribbonInto(out, points, 2, ortho, 4);
    for (let i = 0; i < 2; i++) expect(Math.abs(out[6 * i + 1] - out[6 * i + 4])).toBeCloseTo(0.04, 6);
  });

  it('offsets each point across the line and across the view (seeded random arcs)', () => {
    const random = seeded(32);
    for (let trial = 0; trial < 50; trial++) {
      const n = 12;
      const points = new Float32Array(3 * n);
      const c = [random() - 0.5, random() - 0.5, -3 - 4 * random()];
      for (let i = 0; i < n; i++) {
        const t = (i / (n - 1)) * 2;
        points.set(
          [c[0] + Math.cos(t), c[1] + Math.sin(t) * random() * 0.1 + Math.sin(t), c[2] + 0.5 * Math.sin(t)],
          3 * i,
        );
      }
      const out = new Float32Array(6 * n);
      ribbonInto(out, points, n, VIEW, 5);
      for (let i = 1; i + 1 < n; i++) {
        const side = [0, 1, 2].map((k) => out[6 * i + k] - out[6 * i + 3 + k]);
        const tangent = [0, 1, 2].map((k) => points[3 * (i + 1) + k] - points[3 * (i - 1) + k]);
        const toEye = [0, 1, 2].map((k) => -points[3 * i + k]);
        const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        const unit = (a: number[]) => Math.sqrt(dot(a, a));
        // Float32 buffers: the side's direction to about 1e-5 of the width (a width of 1e-3 units on points of size 5).
        expect(Math.abs(dot(side, tangent)) / (unit(side) * unit(tangent))).toBeLessThan(1e-4);
        expect(Math.abs(dot(side, toEye)) / (unit(side) * unit(toEye))).toBeLessThan(1e-4);
        // Its length: 5 px at the point's depth.
        expect(unit(side) / (5 * UNITS_PER_PX * -points[3 * i + 2])).toBeCloseTo(1, 3);
      }
    }
  });

  it('keeps the side before it where the line runs along the view', () => {
    const points = new Float32Array([0, 0, -2, 0, 0, -3, 0, 0, -4]);
    const out = new Float32Array(18).fill(Number.NaN);
    ribbonInto(out, points, 3, VIEW, 3);
    expect(out.every(Number.isFinite)).toBe(true);
  });

  it('names a bad width and buffers too short', () => {
    expect(() => ribbonInto(new Float32Array(6), new Float32Array(3), 1, VIEW, 0)).toThrow(
      'widthPx must be a positive finite number, got 0',
    );
    expect(() => ribbonInto(new Float32Array(6), new Float32Array(3), 2, VIEW, 1)).toThrow('for count 2');
  });
});

describe('ribbonIndex', () => {
  it('makes two triangles per segment over the two sides of its points', () => {
    expect(ribbonIndex(3)).toEqual([0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4]);
    expect(ribbonIndex(1)).toEqual([]);
  });
});
