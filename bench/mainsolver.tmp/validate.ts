import type { Linkage } from './types';

const FIELDS = ['r1', 'r2', 'r3', 'r4'] as const;

function describe(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (value === undefined) return 'undefined (missing)';
  if (typeof value === 'number') return String(value);
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

/** Rescales exactly by a power of two; angles are unchanged and squares can neither overflow nor underflow. */
export function normalizeLinkage(l: Linkage): NormalizedLinkage {
  const max = Math.max(l.r1, l.r2, l.r3, l.r4);
  let e = Math.ceil(Math.log2(max));
  if (scaleByPow2(max, -e) >= 1) e += 1;
  return {
    r1: scaleByPow2(l.r1, -e),
    r2: scaleByPow2(l.r2, -e),
    r3: scaleByPow2(l.r3, -e),
    r4: scaleByPow2(l.r4, -e),
    exponent: e,
  };
}
