import { csvFormatRows } from 'd3-dsv';
import type { PointStatus } from '../solver/types';
import { radToDeg180 } from '../solver/angles';

/** One branch of a swept cycle: input angles in degrees, output angles in radians (NaN where not assembled). */
export interface CycleTable {
  theta2Deg: ArrayLike<number>;
  theta3Rad: ArrayLike<number>;
  theta4Rad: ArrayLike<number>;
  status: readonly PointStatus[];
  iterations: ArrayLike<number>;
  residual: ArrayLike<number>;
}

/** Column names of the cycle CSV (angles in degrees, residual in the linkage's length unit). */
export const CSV_HEADER = ['theta2_deg', 'theta3_deg', 'theta4_deg', 'status', 'iterations', 'residual'] as const;

/** A number for the CSV at full double precision; empty (never "NaN" or "Infinity") when not finite. */
export function csvNumber(x: number): string {
  return Number.isFinite(x) ? String(x) : '';
}

/**
 * The cycle as CSV text (d3-dsv csvFormatRows): a header row, then one row per sample with theta2 in
 * degrees as swept, theta3 and theta4 in degrees wrapped to (-180, 180], status, NR iterations and residual.
 * Angles and residual are empty where the point is not assembled.
 */
export function cycleToCsv(table: CycleTable): string {
  const rows: string[][] = [[...CSV_HEADER]];
  const n = table.theta2Deg.length;
  for (let i = 0; i < n; i++) {
    const ok = table.status[i] === 'ok';
    const t3 = ok ? radToDeg180(table.theta3Rad[i]) : Number.NaN;
    const t4 = ok ? radToDeg180(table.theta4Rad[i]) : Number.NaN;
    rows.push([
      csvNumber(table.theta2Deg[i]),
      csvNumber(t3),
      csvNumber(t4),
      table.status[i] ?? 'failed',
      csvNumber(table.iterations[i]),
      ok ? csvNumber(table.residual[i]) : '',
    ]);
  }
  return `${csvFormatRows(rows)}\n`;
}
