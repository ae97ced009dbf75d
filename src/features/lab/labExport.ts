import { drawWorkPrecisionChart } from './workPrecisionChart';
import type { WorkPrecisionChartOptions } from './workPrecisionChart';
import type { LabSeries } from '../../study/workPrecision';
import { withPngDpi } from '../../shared/canvas/png';
import { svgToPngBytes, svgToText } from '../../shared/canvas/rasterize';
import type { PngSize } from '../../shared/fileNames';
import { PNG_DPI, PNG_SCALE } from '../../shared/fileNames';
import { detachedSvg } from '../../shared/canvas/svgContext';

/** Renders the work-precision diagram off screen at opts.width x opts.height CSS pixels; PNG bytes at the export size. */
export async function labPng(
  series: readonly LabSeries[],
  opts: WorkPrecisionChartOptions,
  size: PngSize,
): Promise<Uint8Array> {
  const svg = detachedSvg();
  drawWorkPrecisionChart(svg, series, opts);
  return withPngDpi(await svgToPngBytes(svg, opts.width, opts.height, PNG_SCALE[size]), PNG_DPI[size]);
}

/** The work-precision diagram drawn off screen at opts.width x opts.height CSS pixels, as SVG text (text as <text>). */
export function labSvg(series: readonly LabSeries[], opts: WorkPrecisionChartOptions): string {
  const svg = detachedSvg();
  drawWorkPrecisionChart(svg, series, opts);
  return svgToText(svg);
}
