import { scaleLinear, scaleLog } from 'd3-scale';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { linearScale, logScale, niceLinearDomain } from '../../../src/shared/charts/scales';
import { niceLogDomain, oneTwoFiveTicks } from '../../../src/shared/charts/ticks';

// Oracle: d3-scale itself (the lab's charts still use it), which shared/charts/scales.ts stands in for on the first load.

/** d3-format writes a typographic minus; the charts add their own, so compare with a hyphen. */
const hyphen = (s: string) => s.replace(/\u2212/g, '-');

const finite = (lo: number, hi: number) => fc.double({ min: lo, max: hi, noNaN: true, noDefaultInfinity: true });

/** A non-degenerate interval of moderate magnitude, either orientation. */
const interval = fc
  .tuple(finite(-1e6, 1e6), finite(1e-3, 1e6), fc.boolean())
  .map(([a, w, flip]) => (flip ? [a + w, a] : [a, a + w]) as [number, number]);

function close(a: number, b: number, scale: number): void {
  expect(Math.abs(a - b)).toBeLessThanOrEqual(1e-9 * Math.max(1, Math.abs(scale)));
}

describe('linearScale', () => {
  it('maps, inverts, ticks and formats as d3 scaleLinear does', () => {
    fc.assert(
      fc.property(interval, interval, finite(-2e6, 2e6), fc.integer({ min: 1, max: 20 }), (d, r, v, count) => {
        const ours = linearScale(d, r);
        const d3 = scaleLinear().domain(d).range(r);
        close(ours(v), d3(v), Math.abs(r[0]) + Math.abs(r[1]) + Math.abs(d3(v)));
        close(
          ours.invert(r[0] + (r[1] - r[0]) / 3),
          d3.invert(r[0] + (r[1] - r[0]) / 3),
          Math.abs(d[0]) + Math.abs(d[1]),
        );
        expect(ours.domain()).toEqual(d3.domain());
        expect(ours.range()).toEqual(d3.range());
        expect(ours.ticks(count)).toEqual(d3.ticks(count));
        const f = ours.tickFormat(count);
        const g = d3.tickFormat(count);
        for (const t of d3.ticks(count)) expect(f(t)).toBe(hyphen(g(t)));
      }),
      { numRuns: 500 },
    );
  });

  it('formats thousands grouped, tenths on a 0.5 step, and no sign on a value that rounds to zero', () => {
    expect(linearScale([0, 5000], [0, 1]).tickFormat(5)(-3000)).toBe('-3,000');
    expect(linearScale([0, 3], [0, 1]).tickFormat(6)(1.5)).toBe('1.5');
    expect(linearScale([-1, 1], [0, 1]).tickFormat(4)(-1e-17)).toBe('0.0');
  });

  it('maps a one-point domain to the middle of the range, and its copy is independent and equal', () => {
    expect(linearScale([2, 2], [0, 10])(2)).toBe(scaleLinear().domain([2, 2]).range([0, 10])(2));
    const s = linearScale([0, 360], [0, 720]);
    const c = s.copy();
    expect(c(90)).toBe(180);
    expect(c).not.toBe(s);
  });
});

describe('logScale', () => {
  const decades = fc
    .tuple(fc.integer({ min: -17, max: 3 }), fc.integer({ min: 1, max: 12 }))
    .map(([e, n]) => [10 ** e, 10 ** (e + n)] as [number, number]);

  it('maps and inverts as d3 scaleLog().clamp(true), zero and out-of-domain values on the ends', () => {
    fc.assert(
      fc.property(decades, interval, finite(0, 1e20), (d, r, v) => {
        const ours = logScale(d, r);
        const d3 = scaleLog().domain(d).range(r).clamp(true);
        const span = Math.abs(r[0]) + Math.abs(r[1]);
        close(ours(v), d3(v), span);
        close(ours(0), d3(0), span);
        const px = r[0] + (r[1] - r[0]) * 0.37;
        expect(Math.abs(ours.invert(px) / d3.invert(px) - 1)).toBeLessThan(1e-9);
        close(ours.copy()(d[1]), r[1], span);
      }),
      { numRuns: 500 },
    );
  });
});

describe('nice domains and the 1-2-5 lattice', () => {
  it('niceLinearDomain is d3 scaleLinear().nice(count)', () => {
    fc.assert(
      fc.property(interval, fc.integer({ min: 1, max: 20 }), (d, count) => {
        const [lo, hi] = [Math.min(...d), Math.max(...d)];
        expect(niceLinearDomain(lo, hi, count)).toEqual(scaleLinear().domain([lo, hi]).nice(count).domain());
      }),
      { numRuns: 500 },
    );
  });

  it('niceLogDomain is d3 scaleLog().nice() and oneTwoFiveTicks the 1, 2, 5 members of d3 log ticks', () => {
    fc.assert(
      fc.property(finite(-15, 5), finite(0.01, 4), (e, span) => {
        const lo = 10 ** e;
        const hi = 10 ** (e + span);
        expect(niceLogDomain(lo, hi)).toEqual(scaleLog().domain([lo, hi]).nice().domain());
        const d3 = scaleLog()
          .domain([lo, hi])
          .ticks(Math.ceil(span) + 2)
          .filter((t) => [1, 2, 5].some((m) => Math.abs(t / (m * 10 ** Math.floor(Math.log10(t) + 1e-9)) - 1) < 1e-9));
        expect(oneTwoFiveTicks(lo, hi)).toEqual(d3);
      }),
      { numRuns: 500 },
    );
  });
});
