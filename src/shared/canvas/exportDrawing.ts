import { canvasToPngBytes, downloadPng, downloadText } from './download';
import type { DrawContext } from './drawContext';
import { withPngDpi } from './png';
import { SvgContext } from './svgContext';

/** Draws a picture into a context whose units are CSS pixels (a canvas scaled for export, or an SVG). */
export type DrawPicture = (ctx: DrawContext) => void;

/** Pixels per CSS pixel of a drawing's PNG export, and the resolution written into it (dots per inch). */
export const DRAWING_PNG_SCALE = 2;
const DRAWING_PNG_DPI = 96 * DRAWING_PNG_SCALE;

/** A drawing as SVG text at width × height CSS pixels: the same drawing code through SvgContext (text stays text). */
export function drawingSvg(draw: DrawPicture, width: number, height: number): string {
  const ctx = new SvgContext(width, height);
  draw(ctx);
  return ctx.toSvg();
}

/** Downloads a drawing as `${fileBase}.svg`. */
export function exportDrawingSvg(draw: DrawPicture, width: number, height: number, fileBase: string): void {
  downloadText(drawingSvg(draw, width, height), `${fileBase}.svg`, 'image/svg+xml');
}

/** Downloads a drawing as `${fileBase}.png`, drawn afresh at twice the CSS size (192 dpi written into the file). */
export async function exportDrawingPng(
  draw: DrawPicture,
  width: number,
  height: number,
  fileBase: string,
): Promise<void> {
  const canvas = document.createElement('canvas');
  canvas.width = Math.round(width * DRAWING_PNG_SCALE);
  canvas.height = Math.round(height * DRAWING_PNG_SCALE);
  const ctx = canvas.getContext('2d');
  if (!ctx) throw new Error('no 2D canvas context');
  ctx.setTransform(DRAWING_PNG_SCALE, 0, 0, DRAWING_PNG_SCALE, 0, 0);
  draw(ctx);
  downloadPng(withPngDpi(await canvasToPngBytes(canvas), DRAWING_PNG_DPI), `${fileBase}.png`);
}
