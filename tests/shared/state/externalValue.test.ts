import { describe, expect, it } from 'vitest';
import { ExternalValue } from '../../../src/shared/state/externalValue';

describe('ExternalValue', () => {
  it('tells each subscriber once per change, not for the same value, and not after it unsubscribed', () => {
    const v = new ExternalValue<number | null>(null);
    const seen: (number | null)[] = [];
    const off = v.subscribe(() => seen.push(v.get()));
    v.set(1);
    v.set(1);
    v.set(null);
    off();
    v.set(2);
    expect(seen).toEqual([1, null]);
    expect(v.get()).toBe(2);
  });

  it('treats NaN as one value and +0 and -0 as two (Object.is, as useSyncExternalStore compares)', () => {
    const v = new ExternalValue(Number.NaN);
    let calls = 0;
    v.subscribe(() => calls++);
    v.set(Number.NaN);
    v.set(0);
    v.set(-0);
    expect(calls).toBe(2);
  });
});
