/**
 * wrapAngle and angleDiff against an exact reduction (tests/oracle/reference.ts referenceWrap: the
 * doubles taken as exact, 420 digits, so any finite double reduces exactly). Issue 7, item 4: the
 * result is within an ulp of the true x - 2 pi k and always in (-pi, pi] (-pi itself maps to pi).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { angleDiff, wrapAngle } from '../../src/solver';
import { referenceWrap } from '../oracle/reference';

const RUNS = { seed: 20261130, numRuns: 1500 } as const;

/** One ulp of the reference (at least the smallest subnormal): the reduction is faithful, not always rounded to nearest. */
function ulpOf(x: number): number {
  return Math.max(Math.abs(x) * Number.EPSILON, Number.MIN_VALUE);
}

/** |got - ref| modulo the seam at +-pi, where a value just above -pi is reported as pi. */
function seamError(got: number, ref: number): number {
  const direct = Math.abs(got - ref);
  return Math.min(direct, Math.abs(got - 2 * Math.PI - ref), Math.abs(got + 2 * Math.PI - ref));
}

function expectWrapped(got: number, ref: number, ctx: string): void {
  expect(got > -Math.PI && got <= Math.PI, `${ctx}: ${got} outside (-pi, pi]`).toBe(true);
  expect(seamError(got, ref), `${ctx}: got ${got}, exact ${ref}`).toBeLessThanOrEqual(ulpOf(ref));
}

/** Doubles of every magnitude, both signs. */
const anyDouble = fc.double({ noNaN: true, noDefaultInfinity: true });
/** Near multiples of 2 pi and pi, where the reduction cancels most: k 2 pi + tiny, k up to 2^60. */
const nearTurns = fc
  .record({
    k: fc.bigInt({ min: -(2n ** 60n), max: 2n ** 60n }),
    half: fc.boolean(),
    d: fc.double({ min: -1e-6, max: 1e-6, noNaN: true }),
  })
  .map(({ k, half, d }) => Number(k) * (half ? Math.PI : 2 * Math.PI) + d);

describe('wrapAngle', () => {
  it('gives the values the issue names: 1e15 -> 2.1097 (not 2.125), 1e22 -> not 0', () => {
    expect(wrapAngle(1e15)).toBeCloseTo(2.1097, 4);
    expectWrapped(wrapAngle(1e15), referenceWrap(1e15), '1e15');
    expectWrapped(wrapAngle(1e22), referenceWrap(1e22), '1e22');
    expect(wrapAngle(1e22)).not.toBe(0);
    expectWrapped(wrapAngle(3e299), referenceWrap(3e299), '3e299');
    expectWrapped(wrapAngle(Number.MAX_VALUE), referenceWrap(Number.MAX_VALUE), 'MAX_VALUE');
  });

  it('reduces every finite double exactly (within an ulp) into (-pi, pi]', () => {
    fc.assert(
      fc.property(anyDouble, (x) => expectWrapped(wrapAngle(x), referenceWrap(x), `wrapAngle(${x})`)),
      RUNS,
    );
  });

  it('keeps full relative accuracy next to multiples of pi and 2 pi', () => {
    fc.assert(
      fc.property(nearTurns, (x) => expectWrapped(wrapAngle(x), referenceWrap(x), `wrapAngle(${x})`)),
      RUNS,
    );
  });

  it('maps -pi to pi, leaves (-pi, pi] alone and gives NaN for non-finite input', () => {
    expect(wrapAngle(-Math.PI)).toBe(Math.PI);
    expect(wrapAngle(Math.PI)).toBe(Math.PI);
    expect(wrapAngle(-0.5)).toBe(-0.5);
    expect(wrapAngle(3 * Math.PI)).toBeLessThanOrEqual(Math.PI);
    expect(wrapAngle(-3 * Math.PI)).toBeLessThanOrEqual(Math.PI);
    expect(wrapAngle(Infinity)).toBeNaN();
    expect(wrapAngle(-Infinity)).toBeNaN();
    expect(wrapAngle(NaN)).toBeNaN();
  });
});

describe('angleDiff', () => {
  it('reduces the exact difference of any two doubles (within an ulp) into (-pi, pi]', () => {
    fc.assert(
      fc.property(fc.oneof(anyDouble, nearTurns), fc.oneof(anyDouble, nearTurns), (a, b) =>
        expectWrapped(angleDiff(a, b), referenceWrap(a, b), `angleDiff(${a}, ${b})`),
      ),
      RUNS,
    );
  });

  it('does not lose the difference of nearby huge angles or overflow on opposite ones', () => {
    expectWrapped(angleDiff(1e20 + 16384, 1e20), referenceWrap(1e20 + 16384, 1e20), 'near 1e20');
    expectWrapped(angleDiff(1.7e308, -1.7e308), referenceWrap(1.7e308, -1.7e308), '+-1.7e308');
    expectWrapped(angleDiff(1e20, 1), referenceWrap(1e20, 1), '1e20 - 1');
    expect(angleDiff(Infinity, 0)).toBeNaN();
  });
});
