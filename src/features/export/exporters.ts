import { angleSpec } from '../../shared/charts/theta2Chart';
import { CONVERGENCE_SIZE, convergenceSpec } from '../../shared/charts/convergenceChart';
import { rateSpec } from '../../shared/charts/rateChart';
import type { ChartExport } from '../../shared/charts/exportChart';
import { exportChart, specDrawing } from '../../shared/charts/exportChart';
import { canvasToPngBytes, downloadCsv, downloadPng, downloadText } from '../../shared/canvas/download';
import { drawLinkage } from '../../shared/linkage/drawLinkage';
import { withPngDpi } from '../../shared/canvas/png';
import type { LinkageScene } from '../../shared/linkage/scene';
import { SvgContext } from '../../shared/canvas/svgContext';
import { fitScene } from '../../shared/linkage/scene';
import type { ViewOffset } from '../../shared/state/appState';
import type { CycleForces, CycleTable } from '../../shared/csv';
import type { PngSize } from '../../shared/fileNames';
import { PNG_DPI, PNG_SCALE } from '../../shared/fileNames';
import { radToDeg360 } from '../../solver/angles';
import type { Branch } from '../../solver/types';
import type { ExportSubject } from '../../shared/fileNames';
import { csvFileName, pngFileName, svgFileName } from '../../shared/fileNames';
import type { Messages } from '../../shared/i18n/messages';
import { plotSeries } from '../../shared/charts/plotSeries';
import type { PointResponse, TableResponse } from '../../shared/solution';
import { decodeStatuses } from '../../shared/pointStatusCodes';
import type { CycleDegrees } from '../../shared/charts/chartInputs';
import { angleChartInputs, angleMarker, convergenceInputs } from '../../shared/charts/chartInputs';
import type { RateChartKind } from '../../shared/charts/rateInputs';
import { plotRates, rateChartInputs, rateMarker } from '../../shared/charts/rateInputs';
import type { ShownFrame } from '../../shared/linkage/shownFrame';

/** Logical (CSS pixel) size of exported angle and rate plots. */
export const ANGLE_EXPORT_SIZE = { width: 640, height: 360 } as const;
/** Device pixels the exported rate curves are solved at: the 640 px chart at 2x. */
const RATE_EXPORT_PIXELS = 2 * ANGLE_EXPORT_SIZE.width;
/** Logical (CSS pixel) size of the exported convergence plot. */
export const CONVERGENCE_EXPORT_SIZE = { width: 560, height: 340 } as const;

/** What a PNG or SVG export draws: the frame on screen, the NR runs, the plotted angles, the strings, the canvas size. */
export interface ExportContext {
  frame: ShownFrame;
  /** The worker's point answer (NR runs for the convergence plot). */
  point: PointResponse | null;
  deg: CycleDegrees | null;
  t: Messages;
  /** The linkage PNG and SVG are drawn at the on-screen canvas size (CSS pixels). */
  canvasSize: { width: number; height: number };
}

/**
 * The exported ω or α plot (both links in one chart, as the page's "Together" layout) for the frame on screen: the
 * curves solved on the main thread at the export's resolution (they are not solved while no rate plot shows), for
 * the input motion as set and the direction the input turns, the other branch faint when the ghost shows.
 */
export function rateExport(subject: 'omega' | 'alpha', frame: ShownFrame, t: Messages) {
  const s = frame.state;
  const chart: RateChartKind = subject === 'omega' ? 'omegaBoth' : 'alphaBoth';
  const branches: Branch[] = s.display.showGhost ? ['open', 'crossed'] : [s.design.branch];
  const input = { omega2: s.motion.omega2RadPerS, alpha2: s.motion.alpha2RadPerS2 };
  const plot = plotSeries(
    s.design.linkage,
    RATE_EXPORT_PIXELS,
    branches,
    { method: s.solver.method, tol: s.solver.tol },
    input,
  );
  return {
    inputs: rateChartInputs(chart, plotRates(plot, s.motion.direction), s.design.branch, s.display.showGhost, t),
    marker: rateMarker(chart, radToDeg360(frame.marker.theta2Rad), frame.motion ? frame.motion.rates : null),
  };
}

/** A plot subject (not the linkage) as a chart to export: drawn as on screen, at its export size. */
export function plotExport(subject: Exclude<ExportSubject, 'linkage'>, c: ExportContext): ChartExport {
  const { state: s, marker } = c.frame;
  if (subject === 'convergence') {
    const { runs, tolerance, toleranceLabel, ...text } = convergenceInputs(c.point, s.solver.nrStart, c.t);
    const data = { runs, tolerance, toleranceLabel };
    return { ...CONVERGENCE_EXPORT_SIZE, draw: specDrawing(convergenceSpec, text, data, null, CONVERGENCE_SIZE) };
  }
  if (subject === 'omega' || subject === 'alpha') {
    const { inputs, marker: at } = rateExport(subject, c.frame, c.t);
    const { data, ...text } = inputs;
    return { ...ANGLE_EXPORT_SIZE, draw: specDrawing(rateSpec, text, data, at) };
  }
  const { data, ...text } = angleChartInputs(subject, c.deg, s.design.branch, s.display.showGhost, c.t);
  return { ...ANGLE_EXPORT_SIZE, draw: specDrawing(angleSpec, text, data, angleMarker(subject, marker)) };
}

/** Builds and downloads the PNG of a subject at a size: the linkage as on screen, a plot at its export size. */
export async function exportPng(subject: ExportSubject, size: PngSize, c: ExportContext): Promise<void> {
  const { state: s, scene } = c.frame;
  const bytes =
    subject === 'linkage'
      ? await linkagePng(scene, s.display.view, c.canvasSize.width, c.canvasSize.height, size)
      : await exportChart(plotExport(subject, c), size);
  downloadPng(bytes, pngFileName(s.design.linkage, s.design.branch, s.motion.theta2Deg, subject, size));
}

/** Builds and downloads the SVG of a subject (text as text). */
export function exportSvg(subject: ExportSubject, c: ExportContext): void {
  const { state: s, scene } = c.frame;
  const text =
    subject === 'linkage'
      ? linkageSvg(scene, s.display.view, c.canvasSize.width, c.canvasSize.height)
      : exportChart(plotExport(subject, c), 'svg');
  downloadText(
    text,
    svgFileName(s.design.linkage, s.design.branch, s.motion.theta2Deg, subject),
    'image/svg+xml;charset=utf-8',
  );
}

/** The CSV writer's table from the worker's full n-point table (statuses decoded). */
export function cycleTableOf(tbl: TableResponse): CycleTable {
  return {
    theta2Deg: tbl.theta2Deg,
    theta3Rad: tbl.theta3Rad,
    theta4Rad: tbl.theta4Rad,
    status: decodeStatuses(tbl.statusCodes),
    iterations: tbl.iterations,
    residual: tbl.residual,
    motion: tbl.motion ?? null,
  };
}

/** Downloads the full n-point table as the cycle CSV, the force columns last when given. */
export function exportCsv(tbl: TableResponse, forces: CycleForces | null = null): void {
  downloadCsv({ ...cycleTableOf(tbl), forces }, csvFileName(tbl.linkage, tbl.branch, tbl.samples));
}

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
  drawLinkage(ctx, scene, fitScene(scene, scene.bounds, width, height, view));
  return withPngDpi(await canvasToPngBytes(canvas), PNG_DPI[size]);
}

/** The linkage scene as an SVG document of width x height CSS pixels, drawn by drawLinkage itself (text as <text>). */
export function linkageSvg(scene: LinkageScene, view: ViewOffset, width: number, height: number): string {
  const ctx = new SvgContext(width, height);
  drawLinkage(ctx, scene, fitScene(scene, scene.bounds, width, height, view));
  return ctx.toSvg();
}
