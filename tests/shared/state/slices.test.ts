import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE, SLICES, SLICE_NAMES, reducer } from '../../../src/shared/state/appState';
import { URL_KEYS } from '../../../src/shared/url/urlKeys';

const ROOT = join(import.meta.dirname, '../../..');

/** The table rows between `<!-- name… -->` and `<!-- /name -->` in a doc: each row's cells, backticks removed. */
function markedRows(doc: string, name: string): string[][] {
  const text = readFileSync(join(ROOT, doc), 'utf8');
  const start = text.indexOf(`<!-- ${name}`);
  const end = text.indexOf(`<!-- /${name} -->`);
  expect(start, `${doc} has <!-- ${name} -->`).toBeGreaterThan(-1);
  expect(end, `${doc} has <!-- /${name} -->`).toBeGreaterThan(start);
  return text
    .slice(start, end)
    .split('\n')
    .filter((line) => line.startsWith('|'))
    .slice(2)
    .map((line) =>
      line
        .split('|')
        .slice(1, -1)
        .map((cell) => cell.trim().replace(/`/g, '')),
    );
}

describe('SLICES', () => {
  it('gives DEFAULT_STATE one field per slice, its defaults', () => {
    expect(Object.keys(DEFAULT_STATE)).toEqual(SLICE_NAMES);
    for (const name of SLICE_NAMES) expect(DEFAULT_STATE[name]).toBe(SLICES[name].defaults);
  });

  it("hands every action to every slice's reducer and keeps the state when none changes", () => {
    expect(reducer(DEFAULT_STATE, { type: 'setLabStep', stepDeg: DEFAULT_STATE.lab.stepDeg })).toBe(DEFAULT_STATE);
    const next = reducer(DEFAULT_STATE, { type: 'setLabStep', stepDeg: 5 });
    expect(next.lab.stepDeg).toBe(5);
    for (const name of SLICE_NAMES.filter((n) => n !== 'lab')) expect(next[name]).toBe(DEFAULT_STATE[name]);
  });

  it("makes the URL table: every slice's keys in SLICES's order, then panels and lock", () => {
    const names = SLICE_NAMES.flatMap((n) => SLICES[n].urlKeys.map((k) => k.name));
    expect(URL_KEYS.map((k) => k.name)).toEqual([...names, 'panels', 'lock']);
  });

  it('is the list of keys docs/instructors.md gives, slice by slice', () => {
    const rows = markedRows('docs/instructors.md', 'url-keys');
    const derived = SLICE_NAMES.map((n) => [n, SLICES[n].urlKeys.map((k) => k.name).join(' ')]);
    expect(rows).toEqual([...derived, ['embed only', 'panels lock']]);
  });

  it('is the list of slices docs/ARCHITECTURE.md gives, each with its summary', () => {
    const rows = markedRows('docs/ARCHITECTURE.md', 'slices');
    expect(rows).toEqual(SLICE_NAMES.map((n) => [n, SLICES[n].summary]));
  });
});
