import { csvParseRows } from 'd3-dsv';
import { describe, expect, it } from 'vitest';
import { referencePose } from '../../../src/study/reference';
import { runWorkPrecision } from '../../../src/study/workPrecision';
import { LAB_CSV_HEADER, labToCsv } from '../../../src/features/lab/labCsv';

describe('labToCsv', () => {
  it('writes a header and one parseable row per method and tolerance, nothing NaN', async () => {
    const r = (await runWorkPrecision(
      { r1: 6, r2: 2, r3: 5, r4: 5 },
      { branch: 'open', stepDeg: 30, now: () => performance.now(), minTimeMs: 0, reference: referencePose },
    ))!;
    const rows = csvParseRows(labToCsv(r));
    expect(rows[0]).toEqual([...LAB_CSV_HEADER]);
    const n = r.series.reduce((k, s) => k + s.points.length, 0);
    expect(rows.length - 1).toBe(n);
    for (const row of rows.slice(1)) {
      expect(row.join(',')).not.toMatch(/NaN|Infinity/);
      expect(Number(row[2])).toBeGreaterThan(0);
      expect(row[9]).toBe('13');
    }
    expect(rows.find((x) => x[0] === 'seed' && x[1] === '0.001')).toBeDefined();
  });
});
