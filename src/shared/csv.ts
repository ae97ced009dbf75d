import { csvFormatRows } from 'd3-dsv';
import type { PointStatus } from '../solver/types';
import { radToDeg, radToDeg180 } from '../solver/angles';

/** Per-row motion of the cycle: rates (rad/s, rad/s²), transmission angle (radians) and P (length unit, per s, per s²). */
export interface CycleMotion {
  omega3: ArrayLike<number>;
  omega4: ArrayLike<number>;
  alpha3: ArrayLike<number>;
  alpha4: ArrayLike<number>;
  mu: ArrayLike<number>;
  px: ArrayLike<number>;
  py: ArrayLike<number>;
  vpx: ArrayLike<number>;
  vpy: ArrayLike<number>;
  apx: ArrayLike<number>;
  apy: ArrayLike<number>;
}

/** One branch of a swept cycle: input angles in degrees, output angles in radians (NaN where not assembled). */
export interface CycleTable {
  theta2Deg: ArrayLike<number>;
  theta3Rad: ArrayLike<number>;
  theta4Rad: ArrayLike<number>;
  status: readonly PointStatus[];
  iterations: ArrayLike<number>;
  residual: ArrayLike<number>;
  /** The motion columns, written after theta4_deg when present. */
  motion?: CycleMotion | null;
}

/** Column names of the cycle CSV (angles in degrees, residual in the linkage's length unit). */
export const CSV_HEADER = ['theta2_deg', 'theta3_deg', 'theta4_deg', 'status', 'iterations', 'residual'] as const;

/**
 * The motion columns, written after theta4_deg: rates in rad/s and rad/s², the transmission angle in degrees,
 * the coupler point P in the length unit with its velocity (per s) and acceleration (per s²).
 */
export const CSV_MOTION_HEADER = [
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
] as const;

/** A number for the CSV at full double precision; empty (never "NaN" or "Infinity") when not finite. */
export function csvNumber(x: number): string {
  return Number.isFinite(x) ? String(x) : '';
}

/**
 * The cycle as CSV text (d3-dsv csvFormatRows): a header row, then one row per sample with theta2 in
 * degrees as swept, theta3 and theta4 in degrees wrapped to (-180, 180], status, NR iterations and residual.
 * Angles and residual are empty where the point is not assembled. With table.motion the CSV_MOTION_HEADER
 * columns follow theta4_deg, each cell empty where its value is not finite (not assembled, a limit position).
 */
export function cycleToCsv(table: CycleTable): string {
  const m = table.motion ?? null;
  const header: string[] = m
    ? [...CSV_HEADER.slice(0, 3), ...CSV_MOTION_HEADER, ...CSV_HEADER.slice(3)]
    : [...CSV_HEADER];
  const rows: string[][] = [header];
  const n = table.theta2Deg.length;
  for (let i = 0; i < n; i++) {
    const ok = table.status[i] === 'ok';
    const t3 = ok ? radToDeg180(table.theta3Rad[i]) : Number.NaN;
    const t4 = ok ? radToDeg180(table.theta4Rad[i]) : Number.NaN;
    const motion = m
      ? [
          m.omega3[i],
          m.omega4[i],
          m.alpha3[i],
          m.alpha4[i],
          radToDeg(m.mu[i]),
          m.px[i],
          m.py[i],
          m.vpx[i],
          m.vpy[i],
          m.apx[i],
          m.apy[i],
        ].map((x) => (ok ? csvNumber(x) : ''))
      : [];
    rows.push([
      csvNumber(table.theta2Deg[i]),
      csvNumber(t3),
      csvNumber(t4),
      ...motion,
      table.status[i] ?? 'failed',
      csvNumber(table.iterations[i]),
      ok ? csvNumber(table.residual[i]) : '',
    ]);
  }
  return `${csvFormatRows(rows)}\n`;
}
