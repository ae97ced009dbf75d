import { csvFormatRows } from 'd3-dsv';
import type { MechanismSpec, MechanismSweep } from '../../mechanism';
import { degToRad, radToDeg } from '../../solver/angles';
import { csvNumber } from '../../shared/csv';
import { STEPS_PER_TURN } from './mechAnalysis';

/** The rate columns of a point, after its x and y, when rates are shown. */
const RATE_SUFFIXES = ['vx', 'vy', 'ax', 'ay'] as const;

/**
 * The inputs of the CSV: a pin input that turns fully, 0°, 1°, … 359° (360 rows, the first at 0); a rocking pin,
 * the whole degrees within its range [lo, hi] (rad); a slider, STEPS_PER_TURN + 1 slides from lo to hi.
 */
export function csvInputs(kind: 'R' | 'P', range: [number, number], fullTurn: boolean): Float64Array {
  if (kind === 'R' && fullTurn) return Float64Array.from({ length: 360 }, (_, k) => degToRad(k));
  if (kind === 'R') {
    // A hair inside, so that the rounding of a whole-degree end does not drop it.
    const k0 = Math.ceil(radToDeg(range[0]) - 1e-9);
    const k1 = Math.floor(radToDeg(range[1]) + 1e-9);
    return Float64Array.from({ length: Math.max(0, k1 - k0 + 1) }, (_, i) => degToRad(k0 + i));
  }
  const [lo, hi] = range;
  return Float64Array.from({ length: STEPS_PER_TURN + 1 }, (_, k) => lo + ((hi - lo) * k) / STEPS_PER_TURN);
}

/** The CSV header: input, then each joint's and tracer's id_x, id_y (and id_vx, id_vy, id_ax, id_ay with rates). */
export function csvHeader(spec: MechanismSpec, rates: boolean): string[] {
  const ids = [...spec.joints.map((j) => j.id), ...(spec.points ?? []).map((p) => p.id)];
  return [
    'input',
    ...ids.flatMap((id) => [`${id}_x`, `${id}_y`, ...(rates ? RATE_SUFFIXES.map((s) => `${id}_${s}`) : [])]),
  ];
}

/**
 * The linkage over its inputs as CSV text (d3-dsv): the header, then one row per input, numbers at full double
 * precision, empty cells where the linkage does not assemble. sweep is sweepMechanism's answer for these inputs
 * (with rates when rates is true).
 */
export function mechCsv(spec: MechanismSpec, inputs: ArrayLike<number>, sweep: MechanismSweep, rates: boolean): string {
  const series = [...spec.joints.map((j) => sweep.joints[j.id]), ...(spec.points ?? []).map((p) => sweep.points[p.id])];
  const rows: string[][] = [csvHeader(spec, rates)];
  for (let i = 0; i < inputs.length; i++) {
    const row = [csvNumber(inputs[i])];
    for (const s of series) {
      row.push(csvNumber(s.x[i]), csvNumber(s.y[i]));
      if (rates) for (const k of RATE_SUFFIXES) row.push(csvNumber(s[k]?.[i] ?? NaN));
    }
    rows.push(row);
  }
  return csvFormatRows(rows);
}
