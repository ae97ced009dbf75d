import { radToDeg } from '../../../solver/angles';
import type { NinePointClass } from '../../../synthesis/ninePoint/ninePointSynthesis';
import { PLACED_CSV_COLUMNS, csvText, placedCsvCells } from '../path/resultsCsv';

/** The columns of the Nine points mode's "Export results CSV", in order (θ2 at each of the nine points, degrees). */
export const NINE_CSV_COLUMNS = [
  'class',
  'cognate',
  ...PLACED_CSV_COLUMNS,
  'branch',
  'grashof',
  'defects',
  ...Array.from({ length: 9 }, (_, k) => `theta2_${k + 1}_deg`),
] as const;

/**
 * The classes as CSV: one row per linkage (class and cognate numbered from 1), lengths, O2, the ground angle and the
 * coupler point's angle from AB in degrees, the assembly at the first point, the class's Grashof flag and defects
 * (separated by spaces), θ2 at each point in degrees; every number at full precision.
 */
export function ninePointCsv(classes: readonly NinePointClass[]): string {
  const rows = classes.flatMap((c, i) =>
    c.cognates.map((d, k) => [
      String(i + 1),
      String(k + 1),
      ...placedCsvCells(d),
      d.branches[0] ?? d.branch,
      String(c.grashof),
      c.defects.join(' '),
      ...d.theta2.map((t) => String(radToDeg(t))),
    ]),
  );
  return csvText(NINE_CSV_COLUMNS, rows);
}
