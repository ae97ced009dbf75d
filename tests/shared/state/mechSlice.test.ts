import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { MECHANISM_TEMPLATES } from '../../../src/mechanism';
import type { MechanismSpec } from '../../../src/mechanism';
import {
  DEFAULT_MECH,
  MECH_TEMPLATE_KEYS,
  decodeMechSpec,
  encodeMechSpec,
  mechReducer,
  mechSpecCodec,
  templateUrlValue,
} from '../../../src/shared/state/slices/mechSlice';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import { parseUrl, serializeState } from '../../../src/shared/url/url';
import { SLICE_ARBITRARIES } from './sliceArbitraries';

const quiet = () => {};

describe('MECH_TEMPLATE_KEYS', () => {
  it('lists the templates of src/mechanism, in their order', () => {
    expect([...MECH_TEMPLATE_KEYS]).toEqual(Object.keys(MECHANISM_TEMPLATES));
  });

  it('writes the issue’s URL values: tpl=slider-crank, tpl=jansen, runs of capitals together', () => {
    expect(templateUrlValue('sliderCrank')).toBe('slider-crank');
    expect(templateUrlValue('jansen')).toBe('jansen');
    expect(templateUrlValue('wattII')).toBe('watt-ii');
    expect(templateUrlValue('stephensonIII')).toBe('stephenson-iii');
    expect(new Set(MECH_TEMPLATE_KEYS.map(templateUrlValue)).size).toBe(MECH_TEMPLATE_KEYS.length);
  });
});

describe('mechReducer', () => {
  it('opens a template unedited, and keeps the same object when nothing changes', () => {
    const edited = { ...DEFAULT_MECH, spec: MECHANISM_TEMPLATES.jansen.spec };
    expect(mechReducer(edited, { type: 'setMechTemplate', template: 'jansen' })).toEqual({
      ...DEFAULT_MECH,
      template: 'jansen',
      spec: null,
    });
    expect(mechReducer(DEFAULT_MECH, { type: 'setMechTemplate', template: DEFAULT_MECH.template })).toBe(DEFAULT_MECH);
    expect(mechReducer(DEFAULT_MECH, { type: 'setLocale', locale: 'zh-TW' })).toBe(DEFAULT_MECH);
  });

  it('opens a template afresh: as drawn, forward, the default traces, plots and speed (issue 33)', () => {
    const moved = mechReducer(DEFAULT_MECH, {
      type: 'setMechPage',
      patch: { input: 1.25, direction: -1, speed: 90, traced: ['A'], plots: ['', 'speed:A'], velocities: true },
    });
    expect(moved).toMatchObject({ input: 1.25, direction: -1, speed: 90, traced: ['A'], velocities: true });
    expect(mechReducer(moved, { type: 'setMechPage', patch: { input: 1.25 } })).toBe(moved);
    expect(mechReducer(moved, { type: 'setMechTemplate', template: 'jansen' })).toEqual({
      ...DEFAULT_MECH,
      template: 'jansen',
    });
  });

  it('sets the forces, keeps them when a template opens, and keeps the same object for a patch that changes nothing', () => {
    const on = mechReducer(DEFAULT_MECH, { type: 'setMechForces', patch: { enabled: true, rhoKgPerM: 2 } });
    expect(on.forces).toEqual({ ...DEFAULT_MECH.forces, enabled: true, rhoKgPerM: 2 });
    expect(mechReducer(on, { type: 'setMechForces', patch: { enabled: true } })).toBe(on);
    expect(mechReducer(on, { type: 'setMechTemplate', template: 'jansen' }).forces).toBe(on.forces);
  });
});

/** The slider-crank of docs/mechanism.md written by hand in the compact form (an oracle independent of the encoder). */
const HAND_WRITTEN =
  'm1*4*ground*crank*rod*slider*4*O2*R*0*1*0*0*A*R*1*2*2*0*B*R*2*3*6.5*1*S*P*3*0*6.5*1*0*1*P*2*4.25*0.5*0';

describe('encodeMechSpec and decodeMechSpec', () => {
  const spec: MechanismSpec = {
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

  it('writes the documented token layout', () => {
    expect(encodeMechSpec(spec)).toBe(HAND_WRITTEN);
    expect(decodeMechSpec(HAND_WRITTEN)).toEqual(spec);
  });

  it('round-trips every template exactly (the shortest round-trip text of each double)', () => {
    for (const key of MECH_TEMPLATE_KEYS) {
      const s = MECHANISM_TEMPLATES[key].spec;
      expect(decodeMechSpec(encodeMechSpec(s)), key).toEqual(s);
    }
  });

  it('refuses a corrupted code naming what is wrong and where', () => {
    expect(() => decodeMechSpec('m2*1*ground*0*0*-1')).toThrow(/unknown version "m2"/);
    expect(() => decodeMechSpec(HAND_WRITTEN.replace('*6.5*1*0*', '*6.5*x*0*'))).toThrow(
      /joint "S": y must be a finite number, got "x"/,
    );
    expect(() => decodeMechSpec(HAND_WRITTEN.replace('O2*R*0*1', 'O2*R*0*9'))).toThrow(
      /joint "O2": links\[1\] must be an index below 4, got "9"/,
    );
    expect(() => decodeMechSpec(HAND_WRITTEN.slice(0, -2))).toThrow(/the code ends before the input joint/);
    expect(() => decodeMechSpec(`${HAND_WRITTEN}*7`)).toThrow(/1 tokens after the end/);
  });
});

describe('mechSpecCodec', () => {
  it('reads a plain MechanismSpec as JSON, and writes it back compact', () => {
    const json = JSON.stringify(MECHANISM_TEMPLATES.jansen.spec);
    const r = mechSpecCodec.parse(json);
    expect(r).toEqual({ ok: true, value: MECHANISM_TEMPLATES.jansen.spec });
    if (r.ok) expect(r.value && mechSpecCodec.format(r.value)).toBe(encodeMechSpec(MECHANISM_TEMPLATES.jansen.spec));
  });

  it('keeps a linkage still being built (mobility 2, no input), and refuses a malformed one with the reason', () => {
    const open = { links: ['ground', 'a'], joints: [{ id: 'O', kind: 'R', links: ['ground', 'a'], x: 0, y: 0 }] };
    expect(mechSpecCodec.parse(JSON.stringify({ ...open, input: { joint: '' } })).ok).toBe(true);
    expect(mechSpecCodec.parse(JSON.stringify({ ...open, input: { joint: 'Z' } }))).toEqual({
      ok: false,
      why: 'input.joint: unknown joint "Z"',
    });
    const nan = { ...open, joints: [{ ...open.joints[0], x: 'NaN' }], input: { joint: 'O' } };
    expect(mechSpecCodec.parse(JSON.stringify(nan))).toEqual({
      ok: false,
      why: 'joint "O": x must be a finite number, got "NaN"',
    });
    expect(mechSpecCodec.parse('{"links":')).toMatchObject({ ok: false, why: expect.stringMatching(/^not JSON/) });
  });

  it('parses a link whose mech= is corrupted by naming it, and keeps the last good linkage', () => {
    const good = {
      ...DEFAULT_STATE,
      mech: { ...DEFAULT_MECH, template: 'jansen' as const, spec: MECHANISM_TEMPLATES.klann.spec },
    };
    const r = parseUrl('page=mech&tpl=jansen&mech=m1*2*ground', good, quiet);
    expect(r.state.mech.spec).toBe(MECHANISM_TEMPLATES.klann.spec);
    expect(r.ignored.map((p) => [p.key, p.why])).toEqual([['mech', 'the code ends before links[1]']]);
  });

  it('writes the forces’ keys only when they differ from their defaults, and reads them back', () => {
    const forces = { enabled: true, rhoKgPerM: 2.5, gravityMPerS2: 0, inputSpeed: -3, joint: 'B', arrows: true };
    const state = { ...DEFAULT_STATE, mech: { ...DEFAULT_MECH, forces } };
    const query = new URLSearchParams(serializeState(state));
    expect(['mfrc', 'mrho', 'mgr', 'mw', 'mrj', 'mfv'].map((k) => query.get(k))).toEqual([
      '1',
      '2.5',
      '0',
      '-3',
      'B',
      '1',
    ]);
    expect(new URLSearchParams(serializeState(DEFAULT_STATE)).has('mfrc')).toBe(false);
    const back = parseUrl(serializeState(state), DEFAULT_STATE, quiet);
    expect(back.state.mech.forces).toEqual(forces);
    const bad = parseUrl('page=mech&mrho=-1&mgr=x', DEFAULT_STATE, quiet);
    expect(bad.ignored.map((p) => p.key)).toEqual(['mrho', 'mgr']);
  });

  it('round-trips any state of the slice through a link', () => {
    fc.assert(
      fc.property(SLICE_ARBITRARIES.mech, (mech) => {
        const state = { ...DEFAULT_STATE, mech };
        const back = parseUrl(serializeState(state), DEFAULT_STATE, quiet);
        expect(back.ignored).toEqual([]);
        expect(back.state.mech).toEqual(mech);
      }),
      { numRuns: 150, seed: 33 },
    );
  });
});
