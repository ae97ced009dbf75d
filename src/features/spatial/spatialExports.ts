import { csvNumber } from '../../shared/csv';
import { fileNumber } from '../../shared/format';
import type { SpatialState } from '../../shared/state/appState';
import type { SpatialModel } from '../../spatial';
import { spatialCsvRows } from '../../spatial';
import type { SpatialInput } from './useSpatialAnalysis';

/** Input step of the CSV, degrees. */
export const CSV_STEP_DEG = 1;

/**
 * The CSV of the page's linkage (issue 32's columns: theta2_deg, A_x … B_z, [P_x, P_y, P_z], theta4_deg,
 * omega4_rad_s, alpha4_rad_s2), one row per degree over the input's range, every number at full precision; an
 * unbounded rate at a range's end is an empty cell. The rates are for the input's ω2 (rad/s) and α2 (rad/s²).
 */
export function spatialCsvText(model: SpatialModel, branch: SpatialState['branch'], input: SpatialInput): string {
  const { columns, rows } = spatialCsvRows(model, branch, { stepDeg: CSV_STEP_DEG, ...input });
  return [columns.join(','), ...rows.map((r) => r.map(csvNumber).join(','))].join('\n') + '\n';
}

/** The stem of the page's file names: spatial_sph_60-20-55-45_open or spatial_rssr_1-4-2-3_open. */
export function spatialFileStem(s: SpatialState): string {
  const values =
    s.kind === 'sph' ? [s.a1Deg, s.a2Deg, s.a3Deg, s.a4Deg] : [s.r2, s.r3, s.r4, s.a, s.betaDeg, s.h2, s.h4];
  return `spatial_${s.kind}_${values.map(fileNumber).join('-')}_${s.branch}`;
}
