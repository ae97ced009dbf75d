import { withPngDpi } from '../canvas/png';
import { svgToPngBytes, svgToText } from '../canvas/rasterize';
import { detachedSvg } from '../canvas/svgContext';
import type { PngSize } from '../fileNames';
import { PNG_DPI, PNG_SCALE } from '../fileNames';
import type { ChartSizeOptions, ChartSpec, ChartTexts } from './chart';
import { createChart } from './chart';

/** Draws a chart into svg at width x height CSS pixels, in one call (data, texts and marker included). */
export type ChartDrawing = (svg: SVGSVGElement, width: number, height: number) => void;

/** A chart to export: how to draw it and its logical size (CSS pixels). */
export interface ChartExport {
  draw: ChartDrawing;
  width: number;
  height: number;
}

/**
 * The drawing of a chart spec with these texts, data and marker (the marker inside the SVG, as exports need it),
 * with the spec's margins and tick spacing (default the kit's).
 */
export function specDrawing<D, M, T extends ChartTexts>(
  spec: ChartSpec<D, M, T>,
  text: T,
  data: D,
  marker: M | null,
  size: Omit<ChartSizeOptions, 'width' | 'height'> = {},
): ChartDrawing {
  return (svg, width, height) => createChart(svg, { ...size, width, height }, text, spec, data).setMarker(marker);
}

/**
 * Draws a chart off screen into a detached SVG at its size and returns it as standalone SVG text ('svg'),
 * or as PNG bytes at a PngSize (PNG_SCALE device pixels per CSS pixel, PNG_DPI written in its pHYs chunk).
 */
export function exportChart(chart: ChartExport, format: 'svg'): string;
export function exportChart(chart: ChartExport, format: PngSize): Promise<Uint8Array>;
export function exportChart(chart: ChartExport, format: 'svg' | PngSize): string | Promise<Uint8Array> {
  const svg = detachedSvg();
  chart.draw(svg, chart.width, chart.height);
  if (format === 'svg') return svgToText(svg);
  return svgToPngBytes(svg, chart.width, chart.height, PNG_SCALE[format]).then((bytes) =>
    withPngDpi(bytes, PNG_DPI[format]),
  );
}
