import { describe, expect, it } from 'vitest';
import { formatTargetsText, parseTargetsText, targetsToCsv } from '../../../../src/features/synthesis/path/targetsText';
import { MAX_TARGETS } from '../../../../src/shared/state/slices/synthesisSlice';

describe('parseTargetsText', () => {
  it('reads x, y with commas, tabs, spaces or semicolons, skipping blank lines', () => {
    const r = parseTargetsText('1, 2\n3\t4\n\n  -5   6.5 \r\n7;8e-1\n');
    expect(r).toEqual({
      ok: true,
      value: {
        targets: [
          { x: 1, y: 2 },
          { x: 3, y: 4 },
          { x: -5, y: 6.5 },
          { x: 7, y: 0.8 },
        ],
        theta2Deg: null,
      },
    });
  });

  it('reads a third number as θ2 in degrees when every line has one', () => {
    const r = parseTargetsText('0, 0, 10\n1, 1, 40');
    expect(r.ok && r.value.theta2Deg).toEqual([10, 40]);
    const mixed = parseTargetsText('0, 0, 10\n1, 1');
    expect(mixed.ok && mixed.value.theta2Deg).toBe(null);
  });

  it('names the first bad line by its number and text', () => {
    expect(parseTargetsText('1, 2\n\n3, four\n5, 6')).toEqual({
      ok: false,
      error: { kind: 'line', line: 3, text: '3, four' },
    });
    expect(parseTargetsText('1')).toEqual({ ok: false, error: { kind: 'line', line: 1, text: '1' } });
    expect(parseTargetsText('1, 2, 3, 4')).toEqual({ ok: false, error: { kind: 'line', line: 1, text: '1, 2, 3, 4' } });
    expect(parseTargetsText('0x1, 2').ok).toBe(false);
    expect(parseTargetsText('Infinity, 2').ok).toBe(false);
  });

  it('refuses more than MAX_TARGETS points', () => {
    const text = Array.from({ length: MAX_TARGETS + 1 }, (_, i) => `${i}, 0`).join('\n');
    expect(parseTargetsText(text)).toEqual({ ok: false, error: { kind: 'too-many', max: MAX_TARGETS } });
  });

  it('skips a CSV header only when asked', () => {
    expect(parseTargetsText('x,y\n1,2', true)).toEqual({
      ok: true,
      value: { targets: [{ x: 1, y: 2 }], theta2Deg: null },
    });
    expect(parseTargetsText('x,y\n1,2').ok).toBe(false);
  });

  it('writes no θ2 for a target without one: a missing θ2 never becomes 0 (issue 34, 3)', () => {
    const targets = [
      { x: 1, y: 2 },
      { x: 3, y: 4 },
    ];
    expect(formatTargetsText(targets, [15, NaN])).toBe('1, 2, 15\n3, 4');
    expect(formatTargetsText(targets, [15])).toBe('1, 2, 15\n3, 4');
    expect(targetsToCsv(targets, [NaN, 20])).toBe('x,y,theta2_deg\n1,2,\n3,4,20\n');
  });

  it('reads back what formatTargetsText and targetsToCsv write, exactly', () => {
    const targets = [
      { x: 0.1 + 0.2, y: -1e-9 },
      { x: 12345.678, y: 2 / 3 },
    ];
    expect(parseTargetsText(formatTargetsText(targets))).toEqual({ ok: true, value: { targets, theta2Deg: null } });
    expect(parseTargetsText(targetsToCsv(targets, [5, -7.25]), true)).toEqual({
      ok: true,
      value: { targets, theta2Deg: [5, -7.25] },
    });
    expect(targetsToCsv(targets).split('\n')[0]).toBe('x,y');
  });
});
