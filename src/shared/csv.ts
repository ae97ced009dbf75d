import { csvFormatRows } from 'd3-dsv';
import type { PointStatus } from '../solver/types';
import { radToDeg, radToDeg180 } from '../solver/angles';

/**
 * Per-row motion of the cycle: rates (rad/s, rad/s²), transmission angle (radians) and P (length unit, per s, per
 * s²), and the input motion it was solved for.
 */
export interface CycleMotion {
  /** ω2 (rad/s) and α2 (rad/s²) of the input, signed by the direction it turns (clockwise: ω2 < 0). */
  input: { omega2: number; alpha2: number };
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
  /** The force columns (CSV_FORCE_HEADER), written after every other column when present (Forces on). */
  forces?: CycleForces | null;
}

/** Per-row input torque T12 (N·m) and pin forces Fij (N, force of link i on link j); NaN where undetermined. */
export interface CycleForces {
  torque: ArrayLike<number>;
  f12x: ArrayLike<number>;
  f12y: ArrayLike<number>;
  f32x: ArrayLike<number>;
  f32y: ArrayLike<number>;
  f43x: ArrayLike<number>;
  f43y: ArrayLike<number>;
  f14x: ArrayLike<number>;
  f14y: ArrayLike<number>;
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

/**
 * The input motion's columns, written after residual with the motion columns: ω2 in rad/s and α2 in rad/s², the
 * same on every row, signed by the direction the input turns (a clockwise input has ω2 < 0), so the file says what
 * its rates were solved for.
 */
export const CSV_INPUT_HEADER = ['omega2_rad_s', 'alpha2_rad_s2'] as const;

/** The force columns, written after all the others when Forces is on: T12 in N·m, then F12, F32, F43, F14 in N (SI). */
export const CSV_FORCE_HEADER = [
  'torque_Nm',
  'f12x_N',
  'f12y_N',
  'f32x_N',
  'f32y_N',
  'f43x_N',
  'f43y_N',
  'f14x_N',
  'f14y_N',
] as const;

/** The CycleForces array behind each force column, in CSV_FORCE_HEADER's order. */
const FORCE_COLUMNS: readonly (keyof CycleForces)[] = [
  'torque',
  'f12x',
  'f12y',
  'f32x',
  'f32y',
  'f43x',
  'f43y',
  'f14x',
  'f14y',
];

/** A number for the CSV at full double precision; empty (never "NaN" or "Infinity") when not finite. */
export function csvNumber(x: number): string {
  return Number.isFinite(x) ? String(x) : '';
}

/**
 * The cycle as CSV text (d3-dsv csvFormatRows): a header row, then one row per sample with theta2 in
 * degrees as swept, theta3 and theta4 in degrees wrapped to (-180, 180], status, NR iterations and residual.
 * Angles and residual are empty where the point is not assembled. With table.motion the CSV_MOTION_HEADER
 * columns follow theta4_deg, each cell empty where its value is not finite (not assembled, a limit position).
 * With table.motion the CSV_INPUT_HEADER columns follow residual, on every row. With table.forces the
 * CSV_FORCE_HEADER columns come last, empty where the point is not assembled.
 */
export function cycleToCsv(table: CycleTable): string {
  const m = table.motion ?? null;
  const f = table.forces ?? null;
  const header: string[] = m
    ? [...CSV_HEADER.slice(0, 3), ...CSV_MOTION_HEADER, ...CSV_HEADER.slice(3), ...CSV_INPUT_HEADER]
    : [...CSV_HEADER];
  if (f) header.push(...CSV_FORCE_HEADER);
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
      // The input is driven whether or not the loop closes: its columns are on every row.
      ...(m ? [csvNumber(m.input.omega2), csvNumber(m.input.alpha2)] : []),
      ...(f ? FORCE_COLUMNS.map((k) => (ok ? csvNumber(f[k][i]) : '')) : []),
    ]);
  }
  return `${csvFormatRows(rows)}\n`;
}
