import { drawAngleChart } from '../charts/angleChart';
import type { AngleMarker } from '../charts/angleChart';
import { drawConvergenceChart } from '../charts/convergenceChart';
import type { RateMarker } from '../charts/rateChart';
import { drawRateChart } from '../charts/rateChart';
import { canvasToPngBytes, downloadBlob } from '../render/download';
import { drawLinkage } from '../render/drawLinkage';
import { withPngDpi } from '../render/png';
import { svgToPngBytes, svgToText } from '../render/rasterize';
import type { LinkageScene } from '../render/scene';
import { SvgContext } from '../render/svgContext';
import { fitView } from '../render/view';
import type { ViewOffset } from '../state/appState';
import type { CycleTable } from '../state/csv';
import { cycleToCsv } from '../state/csv';
import type { PngSize } from '../state/fileNames';
import { PNG_DPI, PNG_SCALE } from '../state/fileNames';
import type { AngleChartInputs, ConvergenceInputs } from './chartInputs';
import type { RateChartInputs } from './rateInputs';

/** Draws the linkage scene at width x height CSS pixels into a new canvas at the export size; returns PNG bytes with DPI. */
export async function linkagePng(
  scene: LinkageScene,
  view: ViewOffset,
  width: number,
  height: number,
  size: PngSize,
): Promise<Uint8Array> {
  const scale = PNG_SCALE[size];
  const canvas = document.createElement('canvas');
  canvas.width = Math.round(width * scale);
  canvas.height = Math.round(height * scale);
  const ctx = canvas.getContext('2d');
  if (!ctx) throw new Error('no 2D canvas context');
  ctx.setTransform(canvas.width / width, 0, 0, canvas.height / height, 0, 0);
  drawLinkage(ctx, scene, fitView(scene.bounds, width, height, view));
  return withPngDpi(await canvasToPngBytes(canvas), PNG_DPI[size]);
}

/** The linkage scene as an SVG document of width x height CSS pixels, drawn by drawLinkage itself (text as <text>). */
export function linkageSvg(scene: LinkageScene, view: ViewOffset, width: number, height: number): string {
  const ctx = new SvgContext(width, height);
  drawLinkage(ctx, scene, fitView(scene.bounds, width, height, view));
  return ctx.toSvg();
}

/** An angle chart drawn off screen at width x height CSS pixels, as SVG text (the chart's own SVG). */
export function angleChartSvg(inputs: AngleChartInputs, marker: AngleMarker, width: number, height: number): string {
  const svg = detachedSvg();
  drawAngleChart(svg, inputs.data, marker, {
    width,
    height,
    title: inputs.title,
    xLabel: inputs.xLabel,
    yLabel: inputs.yLabel,
  });
  return svgToText(svg);
}

/** A rate chart (ω or α against θ2) drawn off screen at width x height CSS pixels, as SVG text. */
export function rateChartSvg(inputs: RateChartInputs, marker: RateMarker, width: number, height: number): string {
  const svg = detachedSvg();
  const { data, ...text } = inputs;
  drawRateChart(svg, data, marker, { ...text, width, height });
  return svgToText(svg);
}

/** The convergence chart drawn off screen at width x height CSS pixels, as SVG text. */
export function convergenceSvg(inputs: ConvergenceInputs, width: number, height: number): string {
  const svg = detachedSvg();
  const { runs, tolerance, ...text } = inputs;
  drawConvergenceChart(svg, { runs, tolerance }, { ...text, width, height });
  return svgToText(svg);
}

/** A new SVG element outside the document, for off-screen chart rendering. */
export function detachedSvg(): SVGSVGElement {
  return document.createElementNS('http://www.w3.org/2000/svg', 'svg');
}

/** Renders an angle chart off screen at width x height CSS pixels and returns PNG bytes at the export size. */
export async function angleChartPng(
  inputs: AngleChartInputs,
  marker: AngleMarker,
  width: number,
  height: number,
  size: PngSize,
): Promise<Uint8Array> {
  const svg = detachedSvg();
  drawAngleChart(svg, inputs.data, marker, {
    width,
    height,
    title: inputs.title,
    xLabel: inputs.xLabel,
    yLabel: inputs.yLabel,
  });
  return withPngDpi(await svgToPngBytes(svg, width, height, PNG_SCALE[size]), PNG_DPI[size]);
}

/** Renders a rate chart off screen at width x height CSS pixels and returns PNG bytes at the export size. */
export async function rateChartPng(
  inputs: RateChartInputs,
  marker: RateMarker,
  width: number,
  height: number,
  size: PngSize,
): Promise<Uint8Array> {
  const svg = detachedSvg();
  const { data, ...text } = inputs;
  drawRateChart(svg, data, marker, { ...text, width, height });
  return withPngDpi(await svgToPngBytes(svg, width, height, PNG_SCALE[size]), PNG_DPI[size]);
}

/** Renders the convergence chart off screen at width x height CSS pixels and returns PNG bytes at the export size. */
export async function convergencePng(
  inputs: ConvergenceInputs,
  width: number,
  height: number,
  size: PngSize,
): Promise<Uint8Array> {
  const svg = detachedSvg();
  const { runs, tolerance, ...text } = inputs;
  drawConvergenceChart(svg, { runs, tolerance }, { ...text, width, height });
  return withPngDpi(await svgToPngBytes(svg, width, height, PNG_SCALE[size]), PNG_DPI[size]);
}

/** Downloads PNG bytes under fileName. */
export function downloadPng(bytes: Uint8Array, fileName: string): void {
  downloadBlob(new Blob([bytes as BlobPart], { type: 'image/png' }), fileName);
}

/** Downloads the cycle as CSV (d3-dsv formatting) under fileName. */
export function downloadCsv(table: CycleTable, fileName: string): void {
  downloadBlob(new Blob([cycleToCsv(table)], { type: 'text/csv;charset=utf-8' }), fileName);
}

/** Downloads text (CSV) under fileName with the given MIME type. */
export function downloadText(text: string, fileName: string, type: string): void {
  downloadBlob(new Blob([text], { type }), fileName);
}
