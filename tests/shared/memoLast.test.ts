import { describe, expect, it } from 'vitest';
import { memoLast } from '../../src/shared/memoLast';

describe('memoLast', () => {
  it('returns the same result object for the same arguments and computes afresh when one changes', () => {
    let calls = 0;
    const f = memoLast((a: object, n: number) => ({ a, n, call: ++calls }));
    const key = {};
    const first = f(key, 1);
    expect(f(key, 1)).toBe(first);
    expect(calls).toBe(1);
    // A different object with the same contents is a change (identity, as React's dependencies).
    expect(f({}, 1)).not.toBe(first);
    expect(f({}, 1).call).toBe(3);
    expect(f(key, 2).n).toBe(2);
    // A cache of one: going back to earlier arguments computes again.
    expect(f(key, 1)).not.toBe(first);
    expect(calls).toBe(5);
  });

  it('treats NaN as the same argument (Object.is)', () => {
    let calls = 0;
    const f = memoLast((x: number) => ++calls + x * 0);
    f(Number.NaN);
    f(Number.NaN);
    expect(calls).toBe(1);
  });
});
