import { COLORS } from '../theme/tokens';
import { canvasToPngBytes } from './download';

/** Serialises an SVG element to standalone SVG text (with its namespace). */
export function svgToText(svg: SVGSVGElement): string {
  const clone = svg.cloneNode(true) as SVGSVGElement;
  clone.setAttribute('xmlns', 'http://www.w3.org/2000/svg');
  return new XMLSerializer().serializeToString(clone);
}

function loadImage(src: string): Promise<HTMLImageElement> {
  return new Promise((resolve, reject) => {
    const img = new Image();
    img.onload = () => resolve(img);
    img.onerror = () => reject(new Error('the chart could not be rendered as an image'));
    img.src = src;
  });
}

/** Renders an SVG of width x height CSS pixels to PNG bytes at scale pixels per CSS pixel, on the surface colour (white). */
export async function svgToPngBytes(
  svg: SVGSVGElement,
  width: number,
  height: number,
  scale: number,
): Promise<Uint8Array> {
  // A data URL (not a blob URL) so this also works in an opaque-origin sandboxed iframe.
  const img = await loadImage(`data:image/svg+xml;charset=utf-8,${encodeURIComponent(svgToText(svg))}`);
  const canvas = document.createElement('canvas');
  canvas.width = Math.round(width * scale);
  canvas.height = Math.round(height * scale);
  const ctx = canvas.getContext('2d');
  if (!ctx) throw new Error('no 2D canvas context');
  ctx.fillStyle = COLORS.surface;
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.drawImage(img, 0, 0, canvas.width, canvas.height);
  return canvasToPngBytes(canvas);
}
