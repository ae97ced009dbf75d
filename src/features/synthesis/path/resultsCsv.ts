import { csvFormatRows } from 'd3-dsv';
import { radToDeg } from '../../../solver/angles';
import type { PathSolution, PlacedFourBar } from '../../../synthesis/types';

/**
 * The columns that say where a placed four-bar is and what it is (the Path and Nine points modes' CSVs): lengths,
 * O2, the ground angle, and the coupler point's distance from A and angle from AB in degrees.
 */
export const PLACED_CSV_COLUMNS = [
  'r1',
  'r2',
  'r3',
  'r4',
  'o2x',
  'o2y',
  'ground_deg',
  'p_dist',
  'p_angle_deg',
] as const;

/** A placed four-bar's cells under PLACED_CSV_COLUMNS, every number at full precision (angles in degrees). */
export function placedCsvCells(d: PlacedFourBar): string[] {
  return [
    d.links.r1,
    d.links.r2,
    d.links.r3,
    d.links.r4,
    d.O2.x,
    d.O2.y,
    radToDeg(d.groundAngle),
    d.pDist,
    radToDeg(d.pAngle),
  ].map(String);
}

/** CSV text: the header, then the rows (d3-dsv quoting), ending with a newline. */
export function csvText(columns: readonly string[], rows: readonly string[][]): string {
  return `${csvFormatRows([[...columns], ...rows])}\n`;
}

/** The columns of "Export results CSV", in order. */
export const RESULTS_CSV_COLUMNS = ['rank', 'error', 'max_distance', ...PLACED_CSV_COLUMNS, 'branch'] as const;

/**
 * The candidates as CSV: one row per candidate (rank from 1, Σd² and the largest distance in the task's unit,
 * lengths, O2, the ground angle and the coupler point's angle from AB in degrees, the branch), every number at full
 * precision (the shortest text that reads back as the same double).
 */
export function resultsToCsv(solutions: readonly PathSolution[]): string {
  const rows = solutions.map((s, i) => [
    String(i + 1),
    String(s.error),
    String(s.maxDistance),
    ...placedCsvCells(s.design),
    s.design.branch,
  ]);
  return csvText(RESULTS_CSV_COLUMNS, rows);
}
