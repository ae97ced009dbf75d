import { workPrecisionDrawing } from './workPrecisionChart';
import type { WorkPrecisionChartOptions } from './workPrecisionChart';
import type { LabSeries } from '../../study/workPrecision';
import type { ChartExport } from '../../shared/charts/exportChart';

/** The work-precision diagram as a chart to export (exportChart): these series, drawn at width x height CSS pixels. */
export function labExport(
  series: readonly LabSeries[],
  opts: WorkPrecisionChartOptions,
  size: { width: number; height: number },
): ChartExport {
  return { ...size, draw: workPrecisionDrawing(series, opts) };
}
