import type { CurveFactory } from 'd3-shape';
import { curveLinear, line } from 'd3-shape';

/**
 * SVG path data of a polyline through the defined points of data (d3-shape's `line()`, coordinates rounded to
 * `digits` decimals, default 3 as d3's): a gap where `defined` is false, never a zero or a NaN drawn; `curve`
 * is d3's interpolation, default linear (curveStep for counts that hold between samples).
 */
export function linePath<T>(
  data: Iterable<T>,
  x: (d: T, i: number) => number,
  y: (d: T, i: number) => number,
  defined: (d: T, i: number) => boolean = () => true,
  digits = 3,
  curve: CurveFactory = curveLinear,
): string {
  return line<T>().x(x).y(y).defined(defined).digits(digits).curve(curve)(data) ?? '';
}
