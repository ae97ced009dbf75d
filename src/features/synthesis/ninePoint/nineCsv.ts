import { csvFormatRows } from 'd3-dsv';
import { radToDeg } from '../../../solver/angles';
import type { NinePointClass } from '../../../synthesis/ninePoint/ninePointSynthesis';

/** The columns of the Nine points mode's "Export results CSV", in order (θ2 at each of the nine points, degrees). */
export const NINE_CSV_COLUMNS = [
  'class',
  'cognate',
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
    c.cognates.map((d, k) =>
      [
        i + 1,
        k + 1,
        d.links.r1,
        d.links.r2,
        d.links.r3,
        d.links.r4,
        d.O2.x,
        d.O2.y,
        radToDeg(d.groundAngle),
        d.pDist,
        radToDeg(d.pAngle),
        d.branches[0] ?? d.branch,
        c.grashof,
        c.defects.join(' '),
        ...d.theta2.map(radToDeg),
      ].map(String),
    ),
  );
  return `${csvFormatRows([[...NINE_CSV_COLUMNS], ...rows])}\n`;
}
