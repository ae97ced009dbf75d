import { describe, expect, it } from 'vitest';
import { classify, degToRad } from '../../../src/solver';
import type { InputRange } from '../../../src/solver';
import type { HardCaseId } from '../../../src/features/lab/hardCases';
import { HARD_CASES } from '../../../src/features/lab/hardCases';
import { labMessagesEn } from '../../../src/features/lab/labMessagesEn';
import { labMessagesZhTw } from '../../../src/features/lab/labMessagesZhTw';

/** The class column of the hard-case table, as Barker classes (Norton); 'none' = cannot be assembled. */
const EXPECTED_BARKER: Record<number, string> = {
  1: 'I-2 GCRR',
  2: 'I-2 GCRR',
  3: 'I-2 GCRR',
  4: 'III-2 SCRR',
  5: 'I-2 GCRR',
  6: 'II-1 RRR1',
  7: 'III-5 S2X',
  8: 'III-5 S2X',
  9: 'III-5 S2X',
  10: 'II-1 RRR1',
  11: 'II-3 RRR3',
  12: 'I-3 GRCR',
  13: 'II-1 RRR1',
  14: 'I-1 GCCC',
  15: 'I-2 GCRR',
  16: 'I-2 GCRR',
  17: 'I-2 GCRR',
  18: 'I-2 GCRR',
  19: 'I-2 GCRR',
  20: 'I-3 GRCR',
  21: 'none',
  22: 'II-1 RRR1',
  23: 'I-2 GCRR',
};

/** True when theta2 (rad) lies in one of the intervals, modulo a full turn. */
function reachable(theta2: number, range: InputRange): boolean {
  if (range.full) return true;
  return range.intervals.some((iv) =>
    [-2, -1, 0, 1, 2].some((k) => theta2 + 2 * Math.PI * k >= iv.lo && theta2 + 2 * Math.PI * k <= iv.hi),
  );
}

/** The case with this id (the table is what the lab's preset menu lists). */
function getHardCase(id: HardCaseId) {
  const c = HARD_CASES.find((h) => h.id === id);
  if (!c) throw new Error(`no hard case ${id}`);
  return c;
}

describe('HARD_CASES', () => {
  it('numbers the 23 cases 1..23 once each, with unique ids', () => {
    expect(HARD_CASES).toHaveLength(23);
    expect(HARD_CASES.map((c) => c.number)).toEqual(Array.from({ length: 23 }, (_v, i) => i + 1));
    expect(new Set(HARD_CASES.map((c) => c.id)).size).toBe(23);
  });

  it('has four positive finite lengths and an input angle in [0, 360) everywhere', () => {
    for (const c of HARD_CASES) {
      for (const r of [c.linkage.r1, c.linkage.r2, c.linkage.r3, c.linkage.r4]) {
        expect(Number.isFinite(r) && r > 0, `case ${c.number}`).toBe(true);
        expect(r, `case ${c.number}`).toBeLessThanOrEqual(1e300);
      }
      expect(c.theta2Deg).toBeGreaterThanOrEqual(0);
      expect(c.theta2Deg).toBeLessThan(360);
      expect(['open', 'crossed']).toContain(c.branch);
    }
  });

  it('classifies every case as the table does', () => {
    for (const c of HARD_CASES) expect(classify(c.linkage).barker, `case ${c.number}`).toBe(EXPECTED_BARKER[c.number]);
  });

  it('keeps the exact lengths of the table where rounding matters', () => {
    expect(getHardCase('toggle180').linkage.r4).toBe(2 + 1e-9);
    expect(getHardCase('justGrashof').linkage.r4).toBe(2 + 1e-12);
    expect(getHardCase('justNonGrashof').linkage.r4).toBe(2 - 1e-12);
    expect(getHardCase('dragLinkFlat').linkage.r3).toBe(Math.sqrt(5.25));
    expect(getHardCase('longLinks').linkage.r3).toBe(1e6 + 0.5);
    expect(getHardCase('vanishingCrank').linkage.r2).toBe(1e-300);
    expect(getHardCase('tinyCoupler').linkage.r3).toBe(1e-9);
  });

  it('scales case 1 by 1e9 and 1e-12 for cases 17 and 18, and starts case 23 from case 1 at 45 degrees', () => {
    const base = getHardCase('reportCase').linkage;
    const up = getHardCase('scaledUp').linkage;
    const down = getHardCase('scaledDown').linkage;
    for (const k of ['r1', 'r2', 'r3', 'r4'] as const) {
      expect(up[k]).toBe(base[k] * 1e9);
      expect(down[k]).toBe(base[k] * 1e-12);
    }
    const singular = getHardCase('singularStart');
    expect(singular.linkage).toEqual(base);
    expect(singular.theta2Deg).toBe(45);
  });

  it('starts every assemblable case at a reachable input angle', () => {
    for (const c of HARD_CASES) {
      const cls = classify(c.linkage);
      if (cls.type === 'cannot-assemble') continue;
      expect(reachable(degToRad(c.theta2Deg), cls.inputRange), `case ${c.number} at ${c.theta2Deg}`).toBe(true);
    }
  });

  it('throws for an unknown id', () => {});
});

describe('hard-case strings', () => {
  it('names and explains every case in both languages', () => {
    for (const m of [labMessagesEn, labMessagesZhTw]) {
      for (const c of HARD_CASES) {
        expect(m.hardCaseNames[c.id].trim(), c.id).not.toBe('');
        expect(m.hardCaseNotes[c.id].trim(), c.id).not.toBe('');
      }
      expect(Object.keys(m.hardCaseNames).sort()).toEqual(HARD_CASES.map((c) => c.id).sort());
      expect(Object.keys(m.hardCaseNotes).sort()).toEqual(HARD_CASES.map((c) => c.id).sort());
    }
  });
});
