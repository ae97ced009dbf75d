import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { AppState } from '../../../src/shared/state/appState';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import type { MechanismSpec } from '../../../src/mechanism';
import { DEFAULT_MECH } from '../../../src/shared/state/slices/mechSlice';
import type { BadField } from '../../../src/features/designs/designFile';
import {
  DESIGN_FILE_FORMAT,
  MECH_SECTION_KEYS,
  designValues,
  readDesignFile,
  taskName,
  writeDesignFile,
} from '../../../src/features/designs/designFile';
import { SLICE_ARBITRARIES } from '../../shared/state/sliceArbitraries';

const SEED = 20261205;
const SAVED_AT = new Date('2026-12-05T03:30:00.000Z');

/** -0 and 0 are written alike; the state never needs to tell them apart. */
const plain = <T>(x: T): T => JSON.parse(JSON.stringify(x)) as T;

/** The slider-crank of docs/mechanism.md, written by hand (an oracle independent of the app's encoder). */
const SLIDER_CRANK: MechanismSpec = {
  links: ['ground', 'crank', 'rod', 'slider'],
  joints: [
    { id: 'O2', kind: 'R', links: ['ground', 'crank'], x: 0, y: 0 },
    { id: 'A', kind: 'R', links: ['crank', 'rod'], x: 2, y: 0 },
    { id: 'B', kind: 'R', links: ['rod', 'slider'], x: 6.5, y: 1 },
    { id: 'S', kind: 'P', links: ['slider', 'ground'], x: 6.5, y: 1, angle: 0 },
  ],
  points: [{ id: 'P', link: 'rod', x: 4.25, y: 0.5 }],
  input: { joint: 'O2' },
};
/** The same linkage in mech='s compact form, written by hand. */
const SLIDER_CRANK_CODE =
  'm1*4*ground*crank*rod*slider*4*O2*R*0*1*0*0*A*R*1*2*2*0*B*R*2*3*6.5*1*S*P*3*0*6.5*1*0*1*P*2*4.25*0.5*0';

/** Work on the Mechanisms page: an edited linkage, Jansen's template chosen before, every page setting off its default. */
const ON_MECH: AppState = {
  ...DEFAULT_STATE,
  shell: { ...DEFAULT_STATE.shell, page: 'mechanism' },
  mech: {
    template: 'jansen',
    spec: SLIDER_CRANK,
    forces: { enabled: true, rhoKgPerM: 2.5, gravityMPerS2: 0, inputSpeed: -30, joint: 'B', arrows: true },
    input: 0.75,
    direction: -1,
    speed: 120,
    traced: ['P', 'A'],
    plots: ['slide:S', 'accel:P'],
    velocities: true,
  },
};

/** A file of ON_MECH with its JSON changed by edit. */
function edited(edit: (file: Record<string, Record<string, unknown>>) => void): string {
  const file = JSON.parse(writeDesignFile(ON_MECH, 'test', SAVED_AT)) as Record<string, Record<string, unknown>>;
  edit(file);
  return JSON.stringify(file);
}

/** The fields named by a refused read (fails the test when the file was read or refused for another reason). */
function badFields(text: string): BadField[] {
  const r = readDesignFile(text, DEFAULT_STATE);
  if (r.ok) throw new Error('the file was read');
  if (r.error.kind !== 'fields') throw new Error(`refused as ${r.error.kind}, not for its fields`);
  return r.error.fields;
}

describe('the mechanism section of a design file (issue 33)', () => {
  it('holds the Mechanisms page’s work under its URL keys, the linkage as a plain MechanismSpec, and names the page', () => {
    const file = JSON.parse(writeDesignFile(ON_MECH, 'leg', SAVED_AT));
    expect(file.page).toBe('mech');
    expect(file.mechanism).toEqual({
      tpl: 'jansen',
      mech: SLIDER_CRANK,
      mfrc: true,
      mrho: 2.5,
      mgr: 0,
      mw: -30,
      mrj: 'B',
      mfv: true,
      mi: 0.75,
      mdir: 'rev',
      mspd: 120,
      mtr: '2*P*A',
      mp: '2*slide%3AS*accel%3AP',
      mvel: true,
    });
    // The slice's keys are in the section only.
    expect(Object.keys(file.state).filter((k) => MECH_SECTION_KEYS.has(k))).toEqual([]);
    expect([...MECH_SECTION_KEYS].sort()).toEqual(
      ['tpl', 'mech', 'mfrc', 'mrho', 'mgr', 'mw', 'mrj', 'mfv', 'mi', 'mdir', 'mspd', 'mtr', 'mp', 'mvel'].sort(),
    );
  });

  it('opens it on the Mechanisms page with every field of the slice', () => {
    const r = readDesignFile(writeDesignFile(ON_MECH, 'leg', SAVED_AT), DEFAULT_STATE);
    if (!r.ok) throw new Error(JSON.stringify(r.error));
    expect(r.page).toBe('mechanism');
    expect(r.state.mech).toEqual(ON_MECH.mech);
  });

  it('round-trips every key of the mech slice saved on the Mechanisms page (seeded property)', () => {
    fc.assert(
      fc.property(SLICE_ARBITRARIES.mech, (mech) => {
        const saved = plain({ ...ON_MECH, mech });
        const r = readDesignFile(writeDesignFile(saved, 'd', SAVED_AT), DEFAULT_STATE);
        if (!r.ok) throw new Error(JSON.stringify(r.error));
        expect(r.page).toBe('mechanism');
        expect(plain(r.state)).toEqual({ ...saved, shell: DEFAULT_STATE.shell });
      }),
      { seed: SEED, numRuns: 200 },
    );
  });

  it('writes an empty section for an unedited template on the page, and none for the simulator’s work', () => {
    const onPage = { ...DEFAULT_STATE, shell: { ...DEFAULT_STATE.shell, page: 'mechanism' as const } };
    expect(JSON.parse(writeDesignFile(onPage, 'x', SAVED_AT))).toMatchObject({ page: 'mech', mechanism: {} });
    expect(JSON.parse(writeDesignFile(DEFAULT_STATE, 'x', SAVED_AT))).not.toHaveProperty('mechanism');
  });

  it('names the work after the template on the Mechanisms page, as its exports do', () => {
    expect(taskName(ON_MECH)).toBe('mechanism_jansen_edited');
    expect(taskName({ ...ON_MECH, mech: { ...ON_MECH.mech, template: 'wattII', spec: null } })).toBe(
      'mechanism_watt-ii',
    );
  });

  it('reads the linkage written as the compact mech= text, or as a plain spec written by hand', () => {
    for (const mech of [SLIDER_CRANK_CODE, SLIDER_CRANK]) {
      const text = JSON.stringify({ format: DESIGN_FILE_FORMAT, version: 1, state: {}, mechanism: { mech } });
      const r = readDesignFile(text, DEFAULT_STATE);
      expect(r.ok && r.state.mech).toEqual({ ...DEFAULT_MECH, spec: SLIDER_CRANK });
    }
  });
});

describe('design files from before the mechanism section still open exactly as before', () => {
  /** A file as the app saved it before the section: the mech slice's keys were in state, with the simulator's. */
  const OLD_WITH_MECH = `{
  "format": "fourbar-lab.design",
  "version": 1,
  "name": "old leg",
  "savedAt": "2026-12-04T22:00:00.000Z",
  "state": {
    "r1": 7, "r2": 2, "r3": 5, "r4": 5, "br": "crossed", "t2": 120,
    "tpl": "jansen",
    "mech": "${SLIDER_CRANK_CODE}",
    "mfrc": true, "mrho": 2, "mrj": "B"
  }
}`;
  /** A file of the first version, before the Mechanisms page existed. */
  const OLD_SIMULATOR = `{"format":"fourbar-lab.design","version":1,"name":"crank-rocker","state":{"r1":7,"r2":2,"r3":5,"r4":5,"t2":30,"trace":true}}`;

  it('a file with the slice’s keys in state', () => {
    const r = readDesignFile(OLD_WITH_MECH, DEFAULT_STATE);
    if (!r.ok) throw new Error(JSON.stringify(r.error));
    expect(r.page).toBeNull();
    expect(r.state.design.linkage).toEqual({ r1: 7, r2: 2, r3: 5, r4: 5 });
    expect(r.state.design.branch).toBe('crossed');
    expect(r.state.mech).toEqual({
      ...DEFAULT_MECH,
      template: 'jansen',
      spec: SLIDER_CRANK,
      forces: { ...DEFAULT_MECH.forces, enabled: true, rhoKgPerM: 2, joint: 'B' },
    });
  });

  it('a simulator file: the mech slice at its defaults, everything else as written', () => {
    const r = readDesignFile(OLD_SIMULATOR, DEFAULT_STATE);
    if (!r.ok) throw new Error(JSON.stringify(r.error));
    expect(r.state.mech).toEqual(DEFAULT_MECH);
    expect(r.state.design.linkage).toEqual({ r1: 7, r2: 2, r3: 5, r4: 5 });
    expect(r.state.motion.theta2Deg).toBe(30);
    // Saved again, it is the same work, the slice's keys (none) out of state.
    expect(designValues(r.state)).toMatchObject({ r1: 7, r2: 2, r3: 5, r4: 5, t2: 30, trace: true });
  });
});

describe('a malformed mechanism section is refused, naming the field and the value', () => {
  it.each([['[1]'], ['"jansen"'], ['null'], ['7']])('mechanism = %s', (value) => {
    expect(badFields(edited((f) => (f.mechanism = JSON.parse(value) as Record<string, unknown>)))).toEqual([
      { field: 'mechanism', value, why: 'expected an object of mechanism fields' },
    ]);
  });

  it.each([
    ['tpl', 'moonwalker', /expected four-bar, slider-crank/],
    ['mech', 'm1*2*ground*crank*1*O2*Q*0*1*0*0*0*0', /kind must be R or P, got "Q"/],
    ['mech', 'm9*0*0*0*-1', /unknown version "m9"/],
    ['mech', { ...SLIDER_CRANK, input: { joint: 'Z' } }, /input.joint: unknown joint "Z"/],
    ['mech', { ...SLIDER_CRANK, joints: [{ ...SLIDER_CRANK.joints[0], x: 'far' }] }, /x/],
    ['mech', 42, /not a finite number|count|version/],
    ['mfrc', 'yes please', /expected 0 or 1/],
    ['mrho', -1, /out of range|negative/],
    ['mgr', 1001, /out of range/],
    ['mw', 2e6, /out of range/],
    ['mrj', 'x'.repeat(201), /at most 200 characters/],
    ['mfv', 2, /expected 0 or 1/],
    ['mi', 'abc', /not a number/],
    ['mi', 2e9, /out of range/],
    ['mdir', 'up', /expected fwd or rev/],
    ['mspd', 0, /out of range/],
    ['mtr', '3*P', /ends before traced\[1\]/],
    ['mtr', ['P'], /expected a number, true or false, or text/],
    ['mp', '1*angle%3Acrank', /plots count must be 2, got 1/],
    ['mvel', 'maybe', /expected 0 or 1/],
    ['r1', 7, /unknown field/],
    ['colour', 'red', /unknown field/],
  ] as const)('mechanism.%s = %j', (key, value, why) => {
    const fields = badFields(edited((f) => (f.mechanism[key] = value)));
    expect(fields).toHaveLength(1);
    expect(fields[0].field).toBe(`mechanism.${key}`);
    expect(fields[0].value).toBe(JSON.stringify(value));
    expect(fields[0].why).toMatch(why);
  });

  it('names every bad field of the section and of state at once, and applies none', () => {
    const text = edited((f) => {
      f.state.r1 = -1;
      Object.assign(f.mechanism, { mi: 'x', mdir: 'sideways' });
    });
    expect(badFields(text).map((b) => b.field)).toEqual(['state.r1', 'mechanism.mi', 'mechanism.mdir']);
  });
});
