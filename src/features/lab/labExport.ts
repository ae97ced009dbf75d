import { drawWorkPrecisionChart } from './workPrecisionChart';
import type { WorkPrecisionChartOptions } from './workPrecisionChart';
import type { LabSeries } from '../../study/workPrecision';
import type { ChartExport } from '../../shared/charts/exportChart';

/** The work-precision diagram as a chart to export (exportChart): these series, drawn at opts.width x opts.height CSS pixels. */
export function labExport(series: readonly LabSeries[], opts: WorkPrecisionChartOptions): ChartExport {
  return {
    width: opts.width,
    height: opts.height,
    draw: (svg, width, height) => drawWorkPrecisionChart(svg, series, { ...opts, width, height }),
  };
}
