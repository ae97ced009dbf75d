import { describe, expect, it } from 'vitest';
import type { RecentDesign } from '../../../src/features/designs/recentDesigns';
import { RECENT_MAX, parseRecent, withRecent } from '../../../src/features/designs/recentDesigns';

const entry = (name: string, i = 0): RecentDesign => ({ name, at: `2026-01-${10 + i}T10:00:00.000Z`, file: '{}' });

describe('withRecent', () => {
  it('puts the newest first and keeps RECENT_MAX', () => {
    let list: RecentDesign[] = [];
    for (let i = 0; i < RECENT_MAX + 3; i++) list = withRecent(list, entry(`d${i}`, i));
    expect(list.map((d) => d.name)).toEqual(['d7', 'd6', 'd5', 'd4', 'd3']);
    expect(RECENT_MAX).toBe(5);
  });

  it('moves a design opened again to the top instead of listing it twice', () => {
    const list = withRecent([entry('a'), entry('b')], entry('b', 5));
    expect(list.map((d) => [d.name, d.at])).toEqual([
      ['b', '2026-01-15T10:00:00.000Z'],
      ['a', '2026-01-10T10:00:00.000Z'],
    ]);
  });
});

describe('parseRecent', () => {
  it('reads a stored list and drops what is not an entry', () => {
    const text = JSON.stringify([entry('a'), { name: 3 }, null, entry('b')]);
    expect(parseRecent(text).map((d) => d.name)).toEqual(['a', 'b']);
  });

  it('gives [] for nothing, bad JSON or not a list', () => {
    expect(parseRecent(null)).toEqual([]);
    expect(parseRecent('{oops')).toEqual([]);
    expect(parseRecent('{"a":1}')).toEqual([]);
  });
});
