import { describe, expect, it } from 'vitest';
import { classify } from '../../../src/solver';
import { PRESETS, getPreset, matchPreset } from '../../../src/shared/state/presets';
import type { PresetId } from '../../../src/shared/state/presets';
import { parseField } from '../../../src/shared/ui/validateNumber';

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

  it('keeps the preset named when only the branch changes (choosing Crossed)', () => {
    for (const p of PRESETS) {
      const other = p.branch === 'open' ? 'crossed' : 'open';
      const twin = PRESETS.find(
        (q) =>
          q.id !== p.id &&
          q.branch === other &&
          JSON.stringify([q.linkage, q.coupler]) === JSON.stringify([p.linkage, p.coupler]),
      );
      // Hoeckens and Chebyshev's lambda are one linkage on its two branches: the branch names which.
      expect(matchPreset(p.linkage, other, p.coupler), p.id).toBe(twin ? twin.id : p.id);
    }
    expect(matchPreset(getPreset('hoeckens').linkage, 'crossed', getPreset('hoeckens').coupler)).toBe(
      'chebyshevLambda',
    );
    expect(matchPreset(getPreset('report').linkage, 'crossed', getPreset('report').coupler)).toBe('report');
  });

  it('is custom once a length or the coupler point changes', () => {
    const p = getPreset('report');
    expect(matchPreset({ ...p.linkage, r3: 5.01 }, p.branch, p.coupler)).toBeNull();
    expect(matchPreset(p.linkage, p.branch, { ...p.coupler, angleDeg: 31 })).toBeNull();
  });
});
