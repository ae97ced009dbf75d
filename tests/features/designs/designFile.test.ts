import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { AppState } from '../../../src/shared/state/appState';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import { parseUrl, serializeState } from '../../../src/shared/url/url';
import type { BadField, DesignFileError } from '../../../src/features/designs/designFile';
import {
  DESIGN_FILE_FORMAT,
  DESIGN_FILE_VERSION,
  NOT_IN_FILE,
  designFileName,
  designNameOf,
  designValues,
  mechanismValues,
  readDesignFile,
  taskName,
  writeDesignFile,
} from '../../../src/features/designs/designFile';
import { withFields } from '../../shared/state/stateFixtures';
import {
  SLICE_ARBITRARIES,
  SLICE_PAGE,
  anyLinkState as anyState,
  oneSliceState,
} from '../../shared/state/sliceArbitraries';
import { SLICE_NAMES } from '../../../src/shared/state/appState';

const SEED = 20260119;
const SAVED_AT = new Date('2026-01-19T10:30:00.000Z');

/** -0 and 0 are written alike; the state never needs to tell them apart. */
function plain<T>(x: T): T {
  return JSON.parse(JSON.stringify(x)) as T;
}

/** A file's text with its JSON changed by edit. */
function edited(state: AppState, edit: (file: Record<string, unknown>) => void): string {
  const file = JSON.parse(writeDesignFile(state, 'test', SAVED_AT)) as Record<string, unknown>;
  edit(file);
  return JSON.stringify(file);
}

/** The fields named by a refused read (fails the test when the read was not refused for its fields). */
function badFields(text: string): BadField[] {
  const r = readDesignFile(text, DEFAULT_STATE);
  if (r.ok) throw new Error('the file was read');
  if (r.error.kind !== 'fields') throw new Error(`refused as ${r.error.kind}, not for its fields`);
  return r.error.fields;
}

function errorOf(text: string): DesignFileError {
  const r = readDesignFile(text, DEFAULT_STATE);
  if (r.ok) throw new Error('the file was read');
  return r.error;
}

describe('writeDesignFile', () => {
  it('writes the format, the version, the name, the time and the work', () => {
    const file = JSON.parse(writeDesignFile(DEFAULT_STATE, 'Report case', SAVED_AT));
    expect(file).toMatchObject({
      format: DESIGN_FILE_FORMAT,
      version: DESIGN_FILE_VERSION,
      name: 'Report case',
      savedAt: '2026-01-19T10:30:00.000Z',
    });
    expect(file.state).toMatchObject({ r1: 6, r2: 2, r3: 5, r4: 5, br: 'open', pd: 2.5, pa: 30, t2: 45 });
  });

  it('holds exactly the share link keys but the language, the page and Play (so a slice added later is saved)', () => {
    fc.assert(
      fc.property(anyState, (s) => {
        const linkKeys = [...new URLSearchParams(serializeState(s)).keys()].filter((k) => !NOT_IN_FILE.has(k));
        expect([...Object.keys(designValues(s)), ...Object.keys(mechanismValues(s))]).toEqual(linkKeys);
      }),
      { seed: SEED, numRuns: 50 },
    );
    expect([...NOT_IN_FILE].sort()).toEqual(['lang', 'page', 'play']);
  });

  it('keeps the ω2 unit (w2u) when it is not rad/s', () => {
    expect(designValues(DEFAULT_STATE)).not.toHaveProperty('w2u');
    expect(designValues(withFields(DEFAULT_STATE, { omegaUnit: 'rpm' }))).toMatchObject({ w2u: 'rpm' });
    expect(designValues(withFields(DEFAULT_STATE, { omegaUnit: 'deg/s' }))).toMatchObject({ w2u: 'deg' });
  });
});

describe('readDesignFile', () => {
  it('round-trips any state exactly, with the reader’s language and page and Play off (seeded property)', () => {
    fc.assert(
      fc.property(anyState, anyState, (s, reader) => {
        const saved = plain(s);
        const r = readDesignFile(writeDesignFile(saved, 'd', SAVED_AT), reader);
        if (!r.ok) throw new Error(JSON.stringify(r.error));
        const expected = { ...saved, shell: reader.shell, motion: { ...saved.motion, playing: false } };
        expect(plain(r.state)).toEqual(expected);
      }),
      { seed: SEED, numRuns: 300 },
    );
  });

  // A design file is the simulator's: a slice whose keys only a page of its own reads (the spatial page) is not in it.
  it.each(SLICE_NAMES.filter((n) => !SLICE_PAGE[n]))(
    'round-trips any %s slice exactly (seeded property, every key of the slice)',
    (name) => {
      fc.assert(
        fc.property(oneSliceState(name), (s) => {
          const saved = plain(s);
          const r = readDesignFile(writeDesignFile(saved, 'd', SAVED_AT), DEFAULT_STATE);
          if (!r.ok) throw new Error(JSON.stringify(r.error));
          const expected = { ...saved, shell: DEFAULT_STATE.shell, motion: { ...saved.motion, playing: false } };
          expect(plain(r.state)).toEqual(expected);
        }),
        { seed: SEED, numRuns: 100 },
      );
      expect(SLICE_ARBITRARIES[name]).toBeDefined();
    },
  );

  it("holds the simulator's keys, not the spatial page's, when saved on the spatial page", () => {
    const s: AppState = {
      ...DEFAULT_STATE,
      shell: { ...DEFAULT_STATE.shell, page: 'spatial' },
      spatial: { ...DEFAULT_STATE.spatial, kind: 'rssr', r2: 7, a1Deg: 33 },
    };
    const values = designValues(s);
    expect(values).toMatchObject({ r2: DEFAULT_STATE.design.linkage.r2 });
    expect(values).not.toHaveProperty('a1');
    expect(values).not.toHaveProperty('sk');
  });

  it('keeps an off-centre pivot box of the path task (bp) exactly', () => {
    const pivotBox = { min: { x: -30, y: 5 }, max: { x: 12.5, y: 40 } };
    const s = { ...DEFAULT_STATE, synPath: { ...DEFAULT_STATE.synPath, mode: 'path' as const, pivotBox } };
    const file = JSON.parse(writeDesignFile(s, 'box', SAVED_AT));
    expect(file.state.bp).toBe('-30,5,12.5,40');
    const r = readDesignFile(JSON.stringify(file), DEFAULT_STATE);
    expect(r.ok && r.state.synPath.pivotBox).toEqual(pivotBox);
  });

  it('reads back the name and the time', () => {
    const r = readDesignFile(writeDesignFile(DEFAULT_STATE, 'My crank-rocker', SAVED_AT), DEFAULT_STATE);
    expect(r).toMatchObject({ ok: true, name: 'My crank-rocker', savedAt: '2026-01-19T10:30:00.000Z' });
  });

  it('gives a field a file leaves out its default (an older file, a hand-written one)', () => {
    const text = JSON.stringify({ format: DESIGN_FILE_FORMAT, version: 1, state: { r2: 2.5 } });
    const r = readDesignFile(text, withFields(DEFAULT_STATE, { linkage: { r1: 9, r2: 9, r3: 9, r4: 9 } }));
    expect(r.ok && r.state).toEqual(withFields(DEFAULT_STATE, { linkage: { r1: 6, r2: 2.5, r3: 5, r4: 5 } }));
  });

  it('reads numbers written as text and on/off written as 1 and 0, as a share link does', () => {
    const text = JSON.stringify({ format: DESIGN_FILE_FORMAT, version: 1, state: { r1: '7', grid: 0, vel: '1' } });
    const r = readDesignFile(text, DEFAULT_STATE);
    expect(r.ok && [r.state.design.linkage.r1, r.state.display.showGrid, r.state.display.showVelocity]).toEqual([
      7,
      false,
      true,
    ]);
  });

  it('ignores lang, page and play in a file (they are the reader’s)', () => {
    const text = edited(DEFAULT_STATE, (f) => {
      (f.state as Record<string, unknown>).lang = 'zh-TW';
      (f.state as Record<string, unknown>).play = true;
      (f.state as Record<string, unknown>).page = 'lab';
    });
    const r = readDesignFile(text, DEFAULT_STATE);
    expect(r.ok && r.state).toEqual(DEFAULT_STATE);
  });

  it('agrees with the share link of the same state (one validated source)', () => {
    fc.assert(
      fc.property(anyState, (s) => {
        const r = readDesignFile(writeDesignFile(s, 'd', SAVED_AT), DEFAULT_STATE);
        const link = parseUrl(serializeState({ ...s, shell: DEFAULT_STATE.shell }), DEFAULT_STATE, () => {}).state;
        expect(r.ok && plain(r.state)).toEqual(plain({ ...link, motion: { ...link.motion, playing: false } }));
      }),
      { seed: SEED, numRuns: 100 },
    );
  });
});

describe('readDesignFile refuses', () => {
  it('a file that is not JSON (a corrupt or truncated file)', () => {
    const text = writeDesignFile(DEFAULT_STATE, 'x', SAVED_AT);
    expect(errorOf(text.slice(0, text.length / 2))).toEqual({ kind: 'notJson' });
    expect(errorOf('')).toEqual({ kind: 'notJson' });
    expect(errorOf('\u0089PNG')).toEqual({ kind: 'notJson' });
  });

  it('JSON that is not an object', () => {
    expect(errorOf('[1, 2]')).toEqual({ kind: 'notObject' });
    expect(errorOf('"design"')).toEqual({ kind: 'notObject' });
    expect(errorOf('null')).toEqual({ kind: 'notObject' });
  });

  it('a newer version, saying which', () => {
    expect(errorOf(edited(DEFAULT_STATE, (f) => (f.version = DESIGN_FILE_VERSION + 1)))).toEqual({
      kind: 'newer',
      version: DESIGN_FILE_VERSION + 1,
    });
  });

  it('a wrong format, naming the value', () => {
    expect(badFields(edited(DEFAULT_STATE, (f) => (f.format = 'fourbar-lab.link')))).toEqual([
      { field: 'format', value: '"fourbar-lab.link"', why: `expected "${DESIGN_FILE_FORMAT}"` },
    ]);
    expect(badFields(edited(DEFAULT_STATE, (f) => delete f.format))[0]).toMatchObject({
      field: 'format',
      value: 'missing',
    });
  });

  it.each([['"1"'], ['0'], ['1.5'], ['-2'], ['null']])('version %s, naming it', (v) => {
    const fields = badFields(edited(DEFAULT_STATE, (f) => (f.version = JSON.parse(v))));
    expect(fields).toEqual([{ field: 'version', value: v, why: 'expected a whole number from 1' }]);
  });

  it('a name that is not text, a time that is not a time, a missing or wrong state', () => {
    expect(badFields(edited(DEFAULT_STATE, (f) => (f.name = 42)))).toEqual([
      { field: 'name', value: '42', why: 'expected text' },
    ]);
    expect(badFields(edited(DEFAULT_STATE, (f) => (f.savedAt = 'yesterday')))[0]).toMatchObject({
      field: 'savedAt',
      value: '"yesterday"',
    });
    expect(badFields(edited(DEFAULT_STATE, (f) => delete f.state))[0]).toMatchObject({
      field: 'state',
      value: 'missing',
    });
    expect(badFields(edited(DEFAULT_STATE, (f) => (f.state = [1])))[0]).toMatchObject({
      field: 'state',
      value: '[1]',
    });
  });

  it.each([
    ['r1', -1, /negative/],
    ['r2', 0, /notPositive/],
    ['r3', 'long', /not a number/],
    ['br', 'sideways', /expected open or crossed/],
    ['t2', { deg: 45 }, /expected a number/],
    ['dir', 'up', /expected ccw or cw/],
    ['w2u', 'rps', /expected rad, rpm or deg/],
    ['n', 5, /12/],
    ['m', 'bisection', /expected/],
    ['z', 0, /out of range/],
    ['grid', 'maybe', /expected 0 or 1/],
    ['colour', 'red', /unknown field/],
    ['panels', 'plots', /unknown field/],
  ] as const)('state.%s = %j, naming the field and the value', (key, value, why) => {
    const fields = badFields(edited(DEFAULT_STATE, (f) => ((f.state as Record<string, unknown>)[key] = value)));
    expect(fields).toHaveLength(1);
    expect(fields[0].field).toBe(`state.${key}`);
    expect(fields[0].value).toBe(JSON.stringify(value));
    expect(fields[0].why).toMatch(why);
  });

  it('a transmission band whose edges cross, naming both edges', () => {
    const fields = badFields(
      edited(DEFAULT_STATE, (f) => Object.assign(f.state as Record<string, unknown>, { mulo: 150, muhi: 30 })),
    );
    expect(fields.map((f) => f.field)).toEqual(['state.mulo', 'state.muhi']);
    expect(fields[0].why).toMatch(/mulo < muhi/);
  });

  it('every bad field at once, not only the first', () => {
    const fields = badFields(
      edited(DEFAULT_STATE, (f) => Object.assign(f.state as Record<string, unknown>, { r1: -1, br: 'x', foo: 1 })),
    );
    expect(fields.map((f) => f.field)).toEqual(['state.r1', 'state.br', 'state.foo']);
  });
});

describe('designFileName and designNameOf', () => {
  it('make <name>.fourbar.json and back', () => {
    expect(designFileName('Report case 6-2-5-5')).toBe('Report case 6-2-5-5.fourbar.json');
    expect(designNameOf('Report case 6-2-5-5.fourbar.json')).toBe('Report case 6-2-5-5');
    expect(designNameOf('old.JSON')).toBe('old');
  });

  it('replace the characters file systems refuse', () => {
    expect(designFileName('a/b:c*?')).toBe('a_b_c_.fourbar.json');
    expect(designFileName('  ')).toBe('design.fourbar.json');
  });
});

describe('design files of synthesis work (issue 34, item 13)', () => {
  const onSynthesis = (patch: Partial<AppState>): AppState => ({
    ...DEFAULT_STATE,
    ...patch,
    shell: { ...DEFAULT_STATE.shell, page: 'synthesis' },
  });
  const eight = Array.from({ length: 8 }, (_, i) => ({ x: i, y: i / 2, angleDeg: 10 * i }));
  const motion = onSynthesis({
    synPath: { ...DEFAULT_STATE.synPath, mode: 'motion' },
    synMotion: { ...DEFAULT_STATE.synMotion, poses: eight, choice: 3 },
  });

  it('a file saved on the synthesis page says so, and opens there with the task, the mode and the choice', () => {
    const text = writeDesignFile(motion, 'motion-8-poses', SAVED_AT);
    expect(JSON.parse(text)).toMatchObject({ page: 'syn', state: { syn: 'motion', mc: 3 } });
    const r = readDesignFile(text, DEFAULT_STATE);
    if (!r.ok) throw new Error(JSON.stringify(r.error));
    expect(r.page).toBe('synthesis');
    expect(r.state.synPath.mode).toBe('motion');
    expect(r.state.synMotion.poses).toEqual(eight);
    expect(r.state.synMotion.choice).toBe(3);
  });

  it('a simulator file names no page, and an older file without one opens on the reader’s page', () => {
    const text = writeDesignFile(DEFAULT_STATE, 'x', SAVED_AT);
    expect(JSON.parse(text)).not.toHaveProperty('page');
    const r = readDesignFile(text, DEFAULT_STATE);
    expect(r.ok && r.page).toBeNull();
  });

  it('refuses a page it does not know, naming the field', () => {
    expect(badFields(edited(motion, (f) => (f.page = 'moon')))).toEqual([
      { field: 'page', value: '"moon"', why: 'expected "syn" or "mech"' },
    ]);
  });

  it('names the work after the task on the synthesis page, after the lengths elsewhere', () => {
    expect(taskName(motion)).toBe('motion-8-poses');
    expect(taskName(onSynthesis({ synPath: { ...DEFAULT_STATE.synPath, mode: 'function' } }))).toBe(
      `function-${DEFAULT_STATE.synFunction.expression}`,
    );
    expect(taskName(onSynthesis({ synPath: { ...DEFAULT_STATE.synPath, mode: 'nine' } }))).toBe('nine-points');
    const targets = [
      { x: 0, y: 0 },
      { x: 1, y: 2 },
      { x: 3, y: 1 },
    ];
    expect(taskName(onSynthesis({ synPath: { ...DEFAULT_STATE.synPath, targets } }))).toBe('path-3-targets');
    expect(taskName(DEFAULT_STATE)).toBeNull();
  });
});
