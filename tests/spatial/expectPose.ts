import { expect } from 'vitest';
import type { SpatialPose, Vec3 } from '../../src/spatial';
import { angleGap } from './oracle';
import type { OraclePose } from './oracle';

export const EPS = Number.EPSILON;
export const INPUT = { omega2: 1.3, alpha2: -0.7 };

export const gap = (u: Vec3, w: { x: number; y: number; z: number }) => Math.hypot(u.x - w.x, u.y - w.y, u.z - w.z);
export const size = (w: { x: number; y: number; z: number }) => Math.hypot(w.x, w.y, w.z);

/**
 * Tolerances from conditioning: theta4 = phi +- psi with cos psi from rounded terms, so an error of a few eps in the
 * terms moves theta4 by about eps / sin(psi); each derivative divides by F4 (proportional to sin psi) once more. The
 * factors 32 and 64 are about four times the worst seen over the seeded cases below.
 */
export function expectPose(s: SpatialPose | null, o: OraclePose | null, lengthScale: number): void {
  expect(s === null).toBe(o === null);
  if (s === null || o === null) return;
  const k = 1 / o.sinPsi;
  expect(Math.abs(angleGap(s.theta4, o.theta4))).toBeLessThanOrEqual(32 * EPS * k);
  expect(gap(s.A, o.A)).toBeLessThanOrEqual(8 * EPS * lengthScale);
  expect(gap(s.B, o.B)).toBeLessThanOrEqual(32 * EPS * k * lengthScale);
  const w = Math.abs(INPUT.omega2);
  expect(Math.abs(s.omega4 - o.omega4)).toBeLessThanOrEqual(32 * EPS * (Math.abs(o.omega4) + w) * k * k);
  const accScale = Math.abs(o.alpha4) + w * w + Math.abs(INPUT.alpha2);
  expect(Math.abs(s.alpha4 - o.alpha4)).toBeLessThanOrEqual(64 * EPS * accScale * k * k * k);
  expect(gap(s.velocity.B, o.vB)).toBeLessThanOrEqual(64 * EPS * (size(o.vB) + w * lengthScale) * k * k);
  expect(gap(s.acceleration.B, o.aB)).toBeLessThanOrEqual(128 * EPS * (size(o.aB) + accScale * lengthScale) * k ** 3);
  if (o.P) {
    expect(gap(s.P!, o.P)).toBeLessThanOrEqual(64 * EPS * k);
    expect(gap(s.velocity.P!, o.vP!)).toBeLessThanOrEqual(128 * EPS * (size(o.vP!) + w) * k * k);
    expect(gap(s.acceleration.P!, o.aP!)).toBeLessThanOrEqual(256 * EPS * (size(o.aP!) + accScale) * k ** 3);
  }
}
