import { afterEach, describe, expect, it, vi } from 'vitest';

const FLAG = '__FOURBAR_BENCH__';

afterEach(() => {
  delete (globalThis as Record<string, unknown>)[FLAG];
  performance.clearMarks();
  vi.resetModules();
});

describe('benchMark', () => {
  it('adds nothing to the performance timeline in normal use', async () => {
    const { benchMark, BENCH_MARKS } = await import('../../src/shared/benchMarks');
    for (let i = 0; i < 100; i++) benchMark('fourbar:work:cycle', { points: i });
    expect(BENCH_MARKS).toBe(false);
    expect(performance.getEntriesByName('fourbar:work:cycle')).toHaveLength(0);
  });

  it('marks with its detail when a benchmark set the flag before the app loaded', async () => {
    (globalThis as Record<string, unknown>)[FLAG] = true;
    const { benchMark, BENCH_GLOBAL } = await import('../../src/shared/benchMarks');
    expect(BENCH_GLOBAL).toBe(FLAG);
    benchMark('fourbar:work:point', { points: 3 });
    const marks = performance.getEntriesByName('fourbar:work:point') as PerformanceMark[];
    expect(marks.map((m) => m.detail)).toEqual([{ points: 3 }]);
  });
});
