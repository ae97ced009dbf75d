import { csvParseRows } from 'd3-dsv';
import { describe, expect, it } from 'vitest';
import { CSV_HEADER, csvNumber, cycleToCsv } from '../../src/shared/csv';

describe('cycleToCsv', () => {
  const table = {
    theta2Deg: [0, 180, 360],
    theta3Rad: [Math.PI / 4, Number.NaN, (3 * Math.PI) / 2],
    theta4Rad: [Math.PI / 2, Number.NaN, Math.PI],
    status: ['ok', 'unreachable', 'ok'] as const,
    iterations: [3, 0, 2],
    residual: [1e-16, Number.NaN, 0],
  };

  it('writes a header and one row per sample', () => {
    const rows = csvParseRows(cycleToCsv({ ...table, status: [...table.status] }));
    expect(rows[0]).toEqual([...CSV_HEADER]);
    expect(rows).toHaveLength(4);
  });

  it('writes degrees wrapped to (-180, 180] and leaves unassembled angles empty, never NaN', () => {
    const text = cycleToCsv({ ...table, status: [...table.status] });
    expect(text).not.toMatch(/NaN|Infinity/);
    const rows = csvParseRows(text);
    expect(rows[1]).toEqual(['0', '45', '90', 'ok', '3', '1e-16']);
    expect(rows[2]).toEqual(['180', '', '', 'unreachable', '0', '']);
    expect(Number(rows[3][1])).toBeCloseTo(-90, 12);
    expect(rows[3][2]).toBe('180');
  });
});

describe('csvNumber', () => {
  it('keeps full double precision and blanks non-finite values', () => {
    expect(Number(csvNumber(Math.PI))).toBe(Math.PI);
    expect(csvNumber(Number.NaN)).toBe('');
    expect(csvNumber(-Infinity)).toBe('');
  });
});
