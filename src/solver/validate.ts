import type { Linkage } from './types';

const FIELDS = ['r1', 'r2', 'r3', 'r4'] as const;

/** A value as it should appear in an error message: strings quoted, numbers as written, objects as JSON. */
export function describe(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (value === undefined) return 'undefined (missing)';
  if (typeof value === 'number' || typeof value === 'bigint') return String(value);
  if (typeof value === 'function') return 'a function';
  if (value instanceof Set) return `a Set of ${value.size}`;
  if (value instanceof Map) return `a Map of ${value.size}`;
  try {
    return JSON.stringify(value) ?? String(value);
  } catch {
    return String(value);
  }
}

/** Checks that l is four positive finite numbers; throws an Error naming the field and value otherwise. */
export function validateLinkage(l: unknown): asserts l is Linkage {
  if (typeof l !== 'object' || l === null) {
    throw new Error(`linkage must be an object with r1, r2, r3, r4, got ${describe(l)}`);
  }
  const rec = l as Record<string, unknown>;
  for (const f of FIELDS) {
    const v = rec[f];
    if (typeof v !== 'number' || !Number.isFinite(v) || v <= 0) {
      throw new Error(`${f} must be a positive finite length, got ${describe(v)}`);
    }
  }
}

/** Throws unless v is a finite number: `${name} must be a finite ${what}, got ${v}`. */
export function checkFinite(name: string, v: unknown, what = 'number'): asserts v is number {
  if (typeof v !== 'number' || !Number.isFinite(v))
    throw new Error(`${name} must be a finite ${what}, got ${describe(v)}`);
}

/** Throws unless v is undefined or a positive finite number. */
export function checkOptionalPositive(name: string, v: unknown): asserts v is number | undefined {
  if (v === undefined) return;
  if (typeof v !== 'number' || !Number.isFinite(v) || v <= 0) {
    throw new Error(`${name} must be a positive finite number, got ${describe(v)}`);
  }
}

/** Throws unless v is undefined or a boolean. */
export function checkOptionalBoolean(name: string, v: unknown): asserts v is boolean | undefined {
  if (v !== undefined && typeof v !== 'boolean') throw new Error(`${name} must be true or false, got ${describe(v)}`);
}

/** Throws unless v is a plain options object (not null, an array or a primitive). */
export function checkObject(name: string, v: unknown): asserts v is Record<string, unknown> {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) {
    throw new Error(`${name} must be an object, got ${describe(v)}`);
  }
}

/** Throws unless a is an object with finite theta3 and theta4 (radians). */
export function checkAngles(name: string, a: unknown): void {
  checkObject(name, a);
  checkFinite(`${name}.theta3`, a.theta3, 'angle in radians');
  checkFinite(`${name}.theta4`, a.theta4, 'angle in radians');
}

/** Throws unless v is a number (NaN and infinities allowed: they mean "no value" and propagate). */
export function checkNumber(name: string, v: unknown): asserts v is number {
  if (typeof v !== 'number') throw new Error(`${name} must be a number, got ${describe(v)}`);
}

/** Multiplies x by 2^k exactly (k may exceed the exponent range of a single power of two). */
export function scaleByPow2(x: number, k: number): number {
  let y = x;
  let e = k;
  while (e > 1000) {
    y *= 2 ** 1000;
    e -= 1000;
  }
  while (e < -1000) {
    y *= 2 ** -1000;
    e += 1000;
  }
  return y * 2 ** e;
}

/** A linkage rescaled by an exact power of two so its longest link lies in [0.5, 1). */
export interface NormalizedLinkage extends Linkage {
  /** Multiply a normalised length by 2^exponent to get the user's unit back. */
  exponent: number;
}

/**
 * Rescales by a power of two so the longest link lies in [0.5, 1); angles are unchanged and squares
 * cannot overflow. Exact unless a link is below 2^-1074 of the longest after scaling: such a link
 * keeps the smallest positive double (it stays a link; the change is far below an ulp of the longest).
 */
export function normalizeLinkage(l: Linkage): NormalizedLinkage {
  const max = Math.max(l.r1, l.r2, l.r3, l.r4);
  let e = Math.ceil(Math.log2(max));
  if (scaleByPow2(max, -e) >= 1) e += 1;
  if (scaleByPow2(max, -e) < 0.5) e -= 1;
  const scale = (x: number) => scaleByPow2(x, -e) || Number.MIN_VALUE;
  return { r1: scale(l.r1), r2: scale(l.r2), r3: scale(l.r3), r4: scale(l.r4), exponent: e };
}
