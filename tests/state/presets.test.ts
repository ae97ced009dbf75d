import { describe, expect, it } from 'vitest';
import { classify } from '../../src/solver';
import { PRESETS, getPreset, matchPreset } from '../../src/state/presets';
import type { PresetId } from '../../src/state/presets';
import { parseField } from '../../src/state/validate';

describe('PRESETS', () => {
  it('are valid linkages with valid fields', () => {
    for (const p of PRESETS) {
      for (const f of ['r1', 'r2', 'r3', 'r4'] as const) expect(parseField(f, String(p.linkage[f])).ok).toBe(true);
      expect(parseField('couplerDistance', String(p.coupler.distance)).ok).toBe(true);
    }
  });

  it('are the linkage types their names say', () => {
    const expected: Record<PresetId, string> = {
      report: 'crank-rocker',
      dragLink: 'double-crank',
      doubleRocker: 'double-rocker',
      tripleRocker: 'triple-rocker',
      parallelogram: 'change-point',
      nearToggle: 'crank-rocker',
      chebyshevLambda: 'crank-rocker',
      hoeckens: 'crank-rocker',
    };
    for (const p of PRESETS) expect(classify(p.linkage).type, p.id).toBe(expected[p.id]);
  });

  it('are found again from their values', () => {
    for (const p of PRESETS) expect(matchPreset(p.linkage, p.branch, p.coupler)).toBe(p.id);
    expect(matchPreset({ r1: 1, r2: 1, r3: 1, r4: 1 }, 'open', { distance: 0, angleDeg: 0 })).toBeNull();
    expect(() => getPreset('nope' as PresetId)).toThrow(/nope/);
  });
});
