import { drawWorkPrecisionChart } from '../charts/workPrecisionChart';
import type { WorkPrecisionChartOptions } from '../charts/workPrecisionChart';
import type { LabSeries } from '../lab/workPrecision';
import { withPngDpi } from '../render/png';
import { svgToPngBytes, svgToText } from '../render/rasterize';
import type { PngSize } from '../state/fileNames';
import { PNG_DPI, PNG_SCALE } from '../state/fileNames';
import { detachedSvg } from './exporters';

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
