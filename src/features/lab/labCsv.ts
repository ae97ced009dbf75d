import { csvFormatRows } from 'd3-dsv';
import type { LabResult } from '../../study/workPrecision';
import { csvNumber } from '../../shared/csv';

/** Column names of the solver lab's CSV: one row per method and tolerance (errors in radians, time in ns). */
export const LAB_CSV_HEADER = [
  'method',
  'tolerance',
  'ns_per_point',
  'iterations_per_point',
  'max_error_rad',
  'p99_error_rad',
  'failed',
  'wrong_branch',
  'false_convergence',
  'points',
  'step_deg',
] as const;

/**
 * The lab's work-precision data as CSV text (d3-dsv): a header row, then one row per method and
 * tolerance ('default' for a method's own setting). Errors are empty where no point succeeded.
 */
export function labToCsv(result: LabResult): string {
  const rows: string[][] = [[...LAB_CSV_HEADER]];
  for (const s of result.series) {
    for (const p of s.points) {
      rows.push([
        s.method,
        p.tol === null ? 'default' : String(p.tol),
        csvNumber(p.nsPerPoint),
        csvNumber(p.itersPerPoint),
        csvNumber(p.maxError),
        csvNumber(p.p99Error),
        String(p.failures),
        String(p.wrongBranch),
        String(p.falseConvergence),
        String(result.theta2Deg.length),
        String(result.stepDeg),
      ]);
    }
  }
  return `${csvFormatRows(rows)}\n`;
}
