import { describe, expect, it } from 'vitest';
import { convertLength } from '../../../src/shared/state/slices/designSlice';
import type { LengthUnit } from '../../../src/shared/state/slices/designSlice';

const UNITS: LengthUnit[] = ['mm', 'cm', 'm', 'in'];

describe('convertLength', () => {
  it('gives the same typed length back after a round trip through any unit (6 m to in and back is 6)', () => {
    // Plain x · f / g leaves float noise here (6 cm → in → cm is 5.999999999999999): the snap to 12 digits removes it.
    for (const x of [6, 2, 5, 0.1, 1.3, 123.456])
      for (const from of UNITS)
        for (const to of UNITS) expect(convertLength(convertLength(x, from, to), to, from)).toBe(x);
  });

  it('converts exactly where the decimal is exact (6 m is 6000 mm, 1 in is 25.4 mm)', () => {
    expect(convertLength(6, 'm', 'mm')).toBe(6000);
    expect(convertLength(1, 'in', 'mm')).toBe(25.4);
    expect(convertLength(600, 'mm', 'm')).toBe(0.6);
  });

  it('keeps a length that is not a short decimal as computed (no snap beyond a few ulps)', () => {
    const x = Math.PI;
    expect(convertLength(x, 'm', 'mm')).toBeCloseTo(x * 1000, 12);
    expect(convertLength(x, 'm', 'mm')).not.toBe(Number((x * 1000).toPrecision(12)));
  });
});
