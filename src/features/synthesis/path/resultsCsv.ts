import { csvFormatRows } from 'd3-dsv';
import { radToDeg } from '../../../solver/angles';
import type { PathSolution } from '../../../synthesis/types';

/** The columns of "Export results CSV", in order. */
export const RESULTS_CSV_COLUMNS = [
  'rank',
  'error',
  'max_distance',
  'r1',
  'r2',
  'r3',
  'r4',
  'o2x',
  'o2y',
  'ground_deg',
  'p_dist',
  'p_angle_deg',
  'branch',
] as const;

/**
 * The candidates as CSV: one row per candidate (rank from 1, Σd² and the largest distance in the task's unit,
 * lengths, O2, the ground angle and the coupler point's angle from AB in degrees, the branch), every number at full
 * precision (the shortest text that reads back as the same double).
 */
export function resultsToCsv(solutions: readonly PathSolution[]): string {
  const rows = solutions.map((s, i) => {
    const d = s.design;
    return [
      i + 1,
      s.error,
      s.maxDistance,
      d.links.r1,
      d.links.r2,
      d.links.r3,
      d.links.r4,
      d.O2.x,
      d.O2.y,
      radToDeg(d.groundAngle),
      d.pDist,
      radToDeg(d.pAngle),
      d.branch,
    ].map(String);
  });
  return `${csvFormatRows([[...RESULTS_CSV_COLUMNS], ...rows])}\n`;
}
