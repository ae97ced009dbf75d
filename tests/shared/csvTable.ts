import { csvParseRows } from 'd3-dsv';

/**
 * A CSV text read as a table (d3-dsv's parser, not the app's writer): the header, the data rows (the empty line
 * after the last newline dropped) and a cell of a row by column name as a number.
 */
export function csvTable(text: string): {
  header: string[];
  data: string[][];
  col: (row: string[], name: string) => number;
} {
  const rows = csvParseRows(text).filter((r) => r.length > 1);
  const header = rows[0];
  return { header, data: rows.slice(1), col: (row, name) => Number(row[header.indexOf(name)]) };
}

/**
 * The cycle CSV's columns with the motion columns, in the issues' order (written here, not read from the app; the
 * e2e specs read them too).
 */
export const CYCLE_CSV_MOTION_COLUMNS = [
  'theta2_deg',
  'theta3_deg',
  'theta4_deg',
  'omega3_rad_s',
  'omega4_rad_s',
  'alpha3_rad_s2',
  'alpha4_rad_s2',
  'mu_deg',
  'px',
  'py',
  'vpx',
  'vpy',
  'apx',
  'apy',
  'status',
  'iterations',
  'residual',
  'omega2_rad_s',
  'alpha2_rad_s2',
];

/** The force columns the cycle CSV ends with while Forces is on, in the order. */
export const CYCLE_CSV_FORCE_COLUMNS = [
  'torque_Nm',
  'f12x_N',
  'f12y_N',
  'f32x_N',
  'f32y_N',
  'f43x_N',
  'f43y_N',
  'f14x_N',
  'f14y_N',
];
