import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE, reducer } from '../../../src/shared/state/appState';
import { parseUrl, serializeState } from '../../../src/shared/url/url';
import { withFields } from './stateFixtures';

const quiet = () => undefined;

describe('the ω2 unit in the motion slice', () => {
  it('starts in rad/s and is set by setOmegaUnit, keeping ω2 itself in rad/s', () => {
    expect(DEFAULT_STATE.motion.omegaUnit).toBe('rad/s');
    const s = reducer(DEFAULT_STATE, { type: 'setOmegaUnit', unit: 'rpm' });
    expect(s.motion).toEqual({ ...DEFAULT_STATE.motion, omegaUnit: 'rpm' });
    expect(reducer(s, { type: 'setOmegaUnit', unit: 'rpm' })).toBe(s);
  });

  it('is written to the URL as w2u only when not rad/s, and read back', () => {
    expect(new URLSearchParams(serializeState(DEFAULT_STATE)).has('w2u')).toBe(false);
    for (const [unit, text] of [
      ['rpm', 'rpm'],
      ['deg/s', 'deg'],
    ] as const) {
      const q = serializeState(withFields(DEFAULT_STATE, { omegaUnit: unit }));
      expect(new URLSearchParams(q).get('w2u')).toBe(text);
      expect(parseUrl(q, DEFAULT_STATE, quiet).state.motion.omegaUnit).toBe(unit);
    }
    expect(parseUrl('w2u=rad', DEFAULT_STATE, quiet).state.motion.omegaUnit).toBe('rad/s');
  });

  it('refuses an unknown unit in the URL, naming it', () => {
    const r = parseUrl('w2u=rps', DEFAULT_STATE, quiet);
    expect(r.state).toEqual(DEFAULT_STATE);
    expect(r.ignored).toMatchObject([{ key: 'w2u', value: 'rps', why: 'expected rad, rpm or deg' }]);
  });
});
