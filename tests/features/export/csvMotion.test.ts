import { csvParseRows } from 'd3-dsv';
import { describe, expect, it } from 'vitest';
import { CSV_HEADER, CSV_INPUT_HEADER, CSV_MOTION_HEADER, cycleToCsv } from '../../../src/shared/csv';
import { computeTable } from '../../../src/features/simulator/solve/compute';
import { cycleTableOf } from '../../../src/features/export/exporters';
import { referenceMotion } from '../../oracle/rates';
import { CYCLE_CSV_MOTION_COLUMNS, csvTable } from '../../shared/csvTable';

/** The CSV the export writes for a table request with motion (the same path as useExports). */
function exportCsv(linkage: { r1: number; r2: number; r3: number; r4: number }, input = { omega2: 10, alpha2: 0 }) {
  const coupler = { distance: 2.5, angleRad: Math.PI / 6 };
  const tbl = computeTable({
    linkage,
    samples: 36,
    branch: 'open',
    solver: { method: 'newton', tol: null },
    motion: { input, coupler },
  });
  const text = cycleToCsv(cycleTableOf(tbl));
  const { header, data } = csvTable(text);
  return { header, data, coupler, input };
}

describe('cycleToCsv with motion', () => {
  it('puts the motion columns right after theta4_deg, in the order of the issue', () => {
    const { header } = exportCsv({ r1: 6, r2: 2, r3: 5, r4: 5 });
    expect(header).toEqual(CYCLE_CSV_MOTION_COLUMNS);
    expect(header).toEqual([
      ...CSV_HEADER.slice(0, 3),
      ...CSV_MOTION_HEADER,
      ...CSV_HEADER.slice(3),
      ...CSV_INPUT_HEADER,
    ]);
  });

  it('agrees with the 80-digit differentiated positions on every row', () => {
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    const input = { omega2: -7.5, alpha2: 40 };
    const { header, data, coupler } = exportCsv(l, input);
    const col = (name: string) => header.indexOf(name);
    const w = Math.abs(input.omega2);
    const a = Math.hypot(input.omega2 ** 2, input.alpha2);
    for (const row of data) {
      const theta2 = (Number(row[0]) * Math.PI) / 180;
      const ref = referenceMotion(l, theta2, 1, input, coupler.distance, coupler.angleRad);
      // |sin mu| >= 0.6 over this linkage's cycle and |omega3|, |omega4| <= 0.6 |omega2|: the rates carry a few
      // ulps of their scale, the point a few ulps of (length unit * scale); 1e-11 leaves room and still fails
      // for any wrong term (each is of order 1 of its scale).
      const close = (name: string, want: number, scale: number) =>
        expect(Math.abs(Number(row[col(name)]) - want), `${name} at ${row[0]}`).toBeLessThan(1e-11 * scale);
      close('omega3_rad_s', ref.omega3, w);
      close('omega4_rad_s', ref.omega4, w);
      close('alpha3_rad_s2', ref.alpha3, a);
      close('alpha4_rad_s2', ref.alpha4, a);
      close('mu_deg', (Math.acos(ref.cosMu) * 180) / Math.PI, 180);
      close('px', ref.point.x, 10);
      close('py', ref.point.y, 10);
      close('vpx', ref.point.vx, 10 * w);
      close('vpy', ref.point.vy, 10 * w);
      close('apx', ref.point.ax, 10 * a);
      close('apy', ref.point.ay, 10 * a);
    }
  });

  it('records the input motion it was solved for on every row, ω2 negative for a clockwise input', () => {
    const l = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
    // The export asks with the effective input: a clockwise 7.5 rad/s crank is ω2 = −7.5 (inputMotion.ts).
    const { header, data } = exportCsv(l, { omega2: -7.5, alpha2: 40 });
    expect(data.some((r) => r[header.indexOf('status')] !== 'ok')).toBe(true);
    for (const r of data) {
      expect(r[header.indexOf('omega2_rad_s')]).toBe('-7.5');
      expect(r[header.indexOf('alpha2_rad_s2')]).toBe('40');
    }
  });

  it('leaves every motion cell empty where the linkage cannot assemble', () => {
    const { header, data } = exportCsv({ r1: 4, r2: 3, r3: 3.5, r4: 3 });
    const unreachable = data.filter((r) => r[col(header, 'status')] === 'unreachable');
    expect(unreachable.length).toBeGreaterThan(0);
    for (const r of unreachable) for (const name of CSV_MOTION_HEADER) expect(r[col(header, name)]).toBe('');
    const ok = data.filter((r) => r[col(header, 'status')] === 'ok');
    expect(ok.length).toBeGreaterThan(0);
    for (const r of ok) for (const name of CSV_MOTION_HEADER) expect(r[col(header, name)]).not.toBe('');
  });

  it('writes an empty cell, never NaN or Infinity, for a rate at a limit position', () => {
    const text = cycleToCsv({
      theta2Deg: [0],
      theta3Rad: [0],
      theta4Rad: [0],
      status: ['ok'],
      iterations: [1],
      residual: [0],
      motion: {
        input: { omega2: 10, alpha2: 0 },
        omega3: [Number.NaN],
        omega4: [Number.POSITIVE_INFINITY],
        alpha3: [Number.NaN],
        alpha4: [Number.NaN],
        mu: [0],
        px: [1],
        py: [2],
        vpx: [Number.NaN],
        vpy: [Number.NaN],
        apx: [Number.NaN],
        apy: [Number.NaN],
      },
    });
    expect(text).not.toMatch(/NaN|Infinity/);
    expect(csvParseRows(text)[1]).toEqual([
      '0',
      '0',
      '0',
      '',
      '',
      '',
      '',
      '0',
      '1',
      '2',
      '',
      '',
      '',
      '',
      'ok',
      '1',
      '0',
      '10',
      '0',
    ]);
  });
});

function col(header: string[], name: string): number {
  return header.indexOf(name);
}
