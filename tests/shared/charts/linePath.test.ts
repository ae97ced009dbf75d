import { line } from 'd3-shape';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { linePath } from '../../../src/shared/charts/linePath';

// Oracle: d3-shape's line() (the lab's charts still use it), which linePath stands in for on the first load.

const value = fc.oneof(
  fc.double({ min: -1e4, max: 1e4, noNaN: true }),
  fc.constant(Number.NaN),
  fc.constant(0),
  fc.constant(-0.004999),
);

describe('linePath', () => {
  it('writes the path d3 line() writes: runs, gaps, lone points, rounding', () => {
    fc.assert(
      fc.property(
        fc.array(fc.tuple(value, value), { maxLength: 40 }),
        fc.option(fc.integer({ min: 0, max: 6 }), { nil: undefined }), // undefined: the default, 3
        (points, digits) => {
          const defined = (d: [number, number]) => Number.isFinite(d[0]) && Number.isFinite(d[1]);
          const gen = line<[number, number]>()
            .defined(defined)
            .x((d) => d[0] * 1.5)
            .y((d) => 100 - d[1]);
          if (digits !== undefined) gen.digits(digits);
          expect(
            linePath(
              points,
              (d) => d[0] * 1.5,
              (d) => 100 - d[1],
              defined,
              digits,
            ),
          ).toBe(gen(points) ?? '');
        },
      ),
      { numRuns: 1000 },
    );
  });

  it('draws every point when no defined() is given', () => {
    expect(
      linePath(
        [0, 1, 2],
        (i) => i * 10,
        (i) => i * i,
      ),
    ).toBe('M0,0L10,1L20,4');
  });
});
