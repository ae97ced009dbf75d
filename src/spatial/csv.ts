import { TWO_PI, degToRad, radToDeg } from '../solver';
import { kernelOf } from './kernel';
import { Closure, newPoint } from './point';
import type { SpatialBranch, SpatialModel } from './types';
import { branchSigma, checkFinite, describe } from './validate';

/** The CSV's columns, as issue 32 names them; P_x, P_y, P_z only for a spherical linkage with a coupler point. */
export const SPATIAL_CSV_COLUMNS = ['theta2_deg', 'A_x', 'A_y', 'A_z', 'B_x', 'B_y', 'B_z'] as const;
export const SPATIAL_CSV_P_COLUMNS = ['P_x', 'P_y', 'P_z'] as const;
export const SPATIAL_CSV_RATE_COLUMNS = ['theta4_deg', 'omega4_rad_s', 'alpha4_rad_s2'] as const;

/** Header and rows (full-precision numbers, one row per input step) of the spatial CSV. */
export interface SpatialCsv {
  columns: string[];
  rows: number[][];
}

/** Options of spatialCsvRows: stepDeg (degrees, > 0, default 1), omega2 (rad/s, default 1), alpha2 (rad/s^2, default 0). */
export interface SpatialCsvOptions {
  stepDeg?: number;
  omega2?: number;
  alpha2?: number;
}

/** Most rows one export makes. */
export const MAX_CSV_ROWS = 1_000_000;

/**
 * The CSV rows of a spatial linkage on a branch: one row per stepDeg over the input's range (0..360 degrees for a
 * crank; each reachable interval from its lower to its upper end, both included, otherwise), columns theta2_deg,
 * A_x..B_z, (P_x..P_z), theta4_deg, omega4_rad_s, alpha4_rad_s2. Numbers are the doubles themselves (write them with
 * String() for full precision). At an interval's end the output rates are unbounded (+-Infinity). Throws an Error naming
 * the field for bad input.
 */
export function spatialCsvRows(
  model: SpatialModel,
  branch: SpatialBranch,
  options: SpatialCsvOptions = {},
): SpatialCsv {
  const k = kernelOf(model);
  const sigma = branchSigma(branch);
  const stepDeg = options.stepDeg ?? 1;
  const omega2 = options.omega2 ?? 1;
  const alpha2 = options.alpha2 ?? 0;
  if (typeof stepDeg !== 'number' || !(stepDeg > 0) || !Number.isFinite(stepDeg)) {
    throw new Error(`stepDeg must be a positive finite number of degrees, got ${describe(stepDeg)}`);
  }
  checkFinite('omega2', omega2, 'angular velocity in rad/s');
  checkFinite('alpha2', alpha2, 'angular acceleration in rad/s^2');
  const range = k.inputRange();
  const withP = k.coupler !== null;
  const columns: string[] = [
    ...SPATIAL_CSV_COLUMNS,
    ...(withP ? SPATIAL_CSV_P_COLUMNS : []),
    ...SPATIAL_CSV_RATE_COLUMNS,
  ];
  const spans = range.full ? [{ lo: 0, hi: TWO_PI }] : range.intervals;
  const step = degToRad(stepDeg);
  let total = 0;
  for (const s of spans) total += Math.floor((s.hi - s.lo) / step) + 2;
  if (total > MAX_CSV_ROWS) throw new Error(`stepDeg gives more than ${MAX_CSV_ROWS} rows, got ${describe(stepDeg)}`);
  const rows: number[][] = [];
  const p = newPoint();
  const u = k.unit;
  for (const s of spans) {
    const count = Math.floor((s.hi - s.lo) / step + 1e-9);
    const angles: number[] = [];
    for (let i = 0; i <= count; i++) angles.push(range.full ? degToRad(i * stepDeg) : s.lo + i * step);
    // A range's upper end is a row of its own unless the grid landed on it.
    const last = angles[angles.length - 1];
    if (s.hi - last > 1e-9 * step) angles.push(range.full ? TWO_PI : s.hi);
    for (const t2 of angles) {
      if (k.at(t2, sigma, p) === Closure.Unreachable) continue;
      k.rates(p, omega2, alpha2);
      const row = [radToDeg(t2), p.ax * u, p.ay * u, p.az * u, p.bx * u, p.by * u, p.bz * u];
      if (k.coupler) {
        k.coupler(p, row, row.length);
      }
      row.push(radToDeg(p.theta4), p.omega4, p.alpha4);
      rows.push(row);
    }
  }
  return { columns, rows };
}
