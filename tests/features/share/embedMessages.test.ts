import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import { applyPatch, readSetState, stateEvent, stateValues } from '../../../src/features/share/embedMessages';
import { withFields } from '../../shared/state/stateFixtures';
import { parseUrl, serializeState } from '../../../src/shared/url/url';

const quiet = () => undefined;

// A state off the defaults in every field a host is likely to read.
const MOVED = withFields(DEFAULT_STATE, {
  linkage: { r1: 7.5, r2: 1.25, r3: 6, r4: 4.5 },
  theta2Deg: 248.98895999999954,
  branch: 'crossed',
  coupler: { distance: 3, angleDeg: -40 },
  playing: true,
  direction: -1,
  showGrid: false,
  locale: 'zh-TW',
});

describe('stateValues', () => {
  it('gives the share-link keys with numbers, booleans and URL words', () => {
    const v = stateValues(MOVED);
    expect(v).toMatchObject({
      r1: 7.5,
      r2: 1.25,
      r3: 6,
      r4: 4.5,
      t2: 248.98896,
      br: 'crossed',
      pd: 3,
      pa: -40,
      play: true,
      dir: 'cw',
      grid: false,
      lang: 'zh-TW',
    });
    // Exactly the keys of a share link: the oracle is the URL itself.
    expect(Object.keys(v)).toEqual([...new URLSearchParams(serializeState(MOVED)).keys()]);
  });

  it('reads back through applyPatch to the state the share link gives', () => {
    for (const s of [DEFAULT_STATE, MOVED]) {
      const r = applyPatch(DEFAULT_STATE, stateValues(s));
      expect(r.refused).toEqual([]);
      expect(r.state).toEqual(parseUrl(serializeState(s), DEFAULT_STATE, quiet).state);
    }
  });

  it('is wrapped in a message tagged with its source', () => {
    expect(stateEvent(stateValues(DEFAULT_STATE))).toEqual({
      source: 'fourbar-lab',
      type: 'state',
      state: stateValues(DEFAULT_STATE),
    });
  });
});

describe('readSetState', () => {
  it('accepts only a set-state command for the widget, with an object of values', () => {
    expect(readSetState({ target: 'fourbar-lab', type: 'set-state', state: { r1: 5 } })).toEqual({ r1: 5 });
    for (const bad of [
      null,
      'set-state',
      42,
      [],
      { target: 'other', type: 'set-state', state: { r1: 5 } },
      { source: 'fourbar-lab', type: 'set-state', state: { r1: 5 } },
      { target: 'fourbar-lab', type: 'state', state: { r1: 5 } },
      { target: 'fourbar-lab', type: 'set-state', state: [5] },
      { target: 'fourbar-lab', type: 'set-state', state: 'r1=5' },
      { target: 'fourbar-lab', type: 'set-state' },
    ])
      expect(readSetState(bad)).toBeNull();
  });
});

describe('applyPatch', () => {
  it('sets lengths, the input angle and the branch through the URL codecs', () => {
    const r = applyPatch(DEFAULT_STATE, { r3: 5.5, t2: 370, br: 'crossed', play: true });
    expect(r.applied).toEqual(['r3', 't2', 'br', 'play']);
    expect(r.state.design.linkage).toEqual({ r1: 6, r2: 2, r3: 5.5, r4: 5 });
    expect(r.state.motion.theta2Deg).toBe(10); // the URL codec wraps 370 degrees into [0, 360)
    expect(r.state.design.branch).toBe('crossed');
    expect(r.state.motion.playing).toBe(true);
  });

  it('reads strings as URL text, as a link would', () => {
    const r = applyPatch(DEFAULT_STATE, { r1: '7', play: '1', dir: 'cw' });
    expect([r.state.design.linkage.r1, r.state.motion.playing, r.state.motion.direction]).toEqual([7, true, -1]);
  });

  it('ignores unknown keys and embed-only keys, keeping the rest', () => {
    const r = applyPatch(DEFAULT_STATE, { r2: 1.5, bogus: 1, panels: 'none', lock: 'none', __proto__x: 1 });
    expect(r.applied).toEqual(['r2']);
    expect(r.refused.map((x) => [x.key, x.why])).toEqual([
      ['bogus', 'unknown key'],
      ['panels', 'unknown key'],
      ['lock', 'unknown key'],
      ['__proto__x', 'unknown key'],
    ]);
  });

  it('refuses values the URL would refuse, and anything that is not a number, boolean or short string', () => {
    let touched = false;
    const sneaky = {
      valueOf: () => ((touched = true), 3),
      toString: () => ((touched = true), '3'),
    };
    const patch: Record<string, unknown> = {
      r1: -1,
      r2: Number.NaN,
      r3: Number.POSITIVE_INFINITY,
      r4: sneaky,
      t2: [45],
      br: 'sideways',
      pd: '2'.padEnd(65, '0'),
      pa: null,
      play: 'alert(1)',
    };
    const r = applyPatch(DEFAULT_STATE, patch);
    expect(r.applied).toEqual([]);
    expect(r.refused.map((x) => x.key)).toEqual(Object.keys(patch));
    expect(r.state).toBe(DEFAULT_STATE);
    expect(touched).toBe(false);
  });

  it('refuses locked values and applies the unlocked ones', () => {
    const r = applyPatch(DEFAULT_STATE, { r1: 5, r2: 1.5, t2: 90, br: 'crossed', pa: 10, play: true }, [
      'r1',
      'theta2',
      'coupler',
      'play',
    ]);
    expect(r.applied).toEqual(['r2', 'br']);
    expect(r.refused).toEqual([
      { key: 'r1', why: 'locked (r1)' },
      { key: 't2', why: 'locked (theta2)' },
      { key: 'pa', why: 'locked (coupler)' },
      { key: 'play', why: 'locked (play)' },
    ]);
    expect([
      r.state.design.linkage.r1,
      r.state.motion.theta2Deg,
      r.state.design.coupler.angleDeg,
      r.state.motion.playing,
    ]).toEqual([6, 45, 30, false]);
  });

  it('reverts keys that break a rule between keys', () => {
    const r = applyPatch(DEFAULT_STATE, { mulo: 150, r3: 4 });
    expect(r.applied).toEqual(['r3']);
    expect(r.refused).toEqual([{ key: 'mulo', why: 'the transmission band needs mulo < muhi' }]);
    expect(r.state.display.muBandLoDeg).toBe(DEFAULT_STATE.display.muBandLoDeg);
  });
});
