import type { Point } from '../solver';
import { checkFinite, describe } from '../solver/validate';
import type { Pose } from './types';

/** A value as it should appear in an error message (the solver's describe: strings quoted, objects as JSON). */
export const show = describe;

/** Throws unless v is a finite number: `${name} must be a finite ${what}, got …` (the solver's checkFinite). */
export const checkFiniteNumber: (name: string, v: unknown, what?: string) => asserts v is number = checkFinite;

/** Throws unless v is a positive finite number. */
export function checkPositive(name: string, v: unknown, what = 'number'): asserts v is number {
  if (typeof v !== 'number' || !Number.isFinite(v) || v <= 0) {
    throw new Error(`${name} must be a positive finite ${what}, got ${show(v)}`);
  }
}

/** Throws unless v is an object with finite x and y. */
export function checkPoint(name: string, v: unknown): asserts v is Point {
  if (typeof v !== 'object' || v === null || Array.isArray(v))
    throw new Error(`${name} must be a point {x, y}, got ${show(v)}`);
  const r = v as Record<string, unknown>;
  checkFiniteNumber(`${name}.x`, r.x, 'coordinate');
  checkFiniteNumber(`${name}.y`, r.y, 'coordinate');
}

/** Throws unless v is an object with finite x, y and angle (radians). */
export function checkPose(name: string, v: unknown): asserts v is Pose {
  checkPoint(name, v);
  checkFiniteNumber(`${name}.angle`, (v as unknown as Record<string, unknown>).angle, 'angle in radians');
}

/** Throws unless v is an array whose length is within [min, max]. */
export function checkArray(name: string, v: unknown, min: number, max = Infinity): asserts v is unknown[] {
  if (!Array.isArray(v)) throw new Error(`${name} must be an array, got ${show(v)}`);
  if (v.length < min || v.length > max) {
    const want = max === Infinity ? `at least ${min}` : min === max ? `exactly ${min}` : `${min} to ${max}`;
    throw new Error(`${name} must hold ${want} entries, got ${v.length}`);
  }
}
