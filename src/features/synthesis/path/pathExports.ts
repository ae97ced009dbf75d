import { canvasToPngBytes, downloadPng, downloadText } from '../../../shared/canvas/download';
import { withPngDpi } from '../../../shared/canvas/png';
import { SvgContext } from '../../../shared/canvas/svgContext';
import type { ViewTransform } from '../../../shared/canvas/view';
import type { PathSolution } from '../../../synthesis/types';
import type { PathScene } from './drawPathScene';
import { drawPathScene } from './drawPathScene';
import { resultsToCsv } from './resultsCsv';

/** Pixels per CSS pixel of the PNG export, and the resolution written into it (dots per inch). */
const PNG_SCALE = 2;
const PNG_DPI = 192;

/** Downloads the candidates as synthesis-results.csv (resultsToCsv). */
export function exportResultsCsv(solutions: readonly PathSolution[]): void {
  downloadText(resultsToCsv(solutions), 'synthesis-results.csv', 'text/csv;charset=utf-8');
}

/** The synthesis canvas as SVG text: the same drawing through SvgContext, at the view's size (CSS pixels). */
export function pathSceneSvg(scene: PathScene, view: ViewTransform): string {
  const ctx = new SvgContext(view.width, view.height);
  drawPathScene(ctx, scene, view);
  return ctx.toSvg();
}

/** Downloads the synthesis canvas as synthesis.svg. */
export function exportPathSvg(scene: PathScene, view: ViewTransform): void {
  downloadText(pathSceneSvg(scene, view), 'synthesis.svg', 'image/svg+xml');
}

/** Downloads the synthesis canvas as synthesis.png, drawn afresh at twice the CSS size (192 dpi). */
export async function exportPathPng(scene: PathScene, view: ViewTransform): Promise<void> {
  const canvas = document.createElement('canvas');
  canvas.width = Math.round(view.width * PNG_SCALE);
  canvas.height = Math.round(view.height * PNG_SCALE);
  const ctx = canvas.getContext('2d');
  if (!ctx) throw new Error('no 2D canvas context');
  ctx.setTransform(PNG_SCALE, 0, 0, PNG_SCALE, 0, 0);
  drawPathScene(ctx, scene, view);
  downloadPng(withPngDpi(await canvasToPngBytes(canvas), PNG_DPI), 'synthesis.png');
}
