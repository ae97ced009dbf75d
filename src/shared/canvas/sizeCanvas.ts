/** A canvas sized for the screen: its 2D context scaled to CSS pixels, the pixel ratio and the bitmap's size. */
export interface SizedCanvas {
  ctx: CanvasRenderingContext2D;
  /** devicePixelRatio, capped at 4 (a bitmap past that costs memory and shows nothing more). */
  dpr: number;
  pixelWidth: number;
  pixelHeight: number;
}

/**
 * Sizes a canvas's bitmap for devicePixelRatio (capped at 4) at width × height CSS pixels, resizing it only when
 * the size changed (a resize clears it), and returns its context scaled to CSS pixels; null when the canvas has no
 * size yet or no 2D context. Every canvas of the app (the linkage, the synthesis canvases) sizes itself here.
 */
export function sizeCanvas(canvas: HTMLCanvasElement, width: number, height: number): SizedCanvas | null {
  if (width <= 0 || height <= 0) return null;
  const dpr = Math.max(1, Math.min(4, window.devicePixelRatio || 1));
  const pixelWidth = Math.round(width * dpr);
  const pixelHeight = Math.round(height * dpr);
  if (canvas.width !== pixelWidth || canvas.height !== pixelHeight) {
    canvas.width = pixelWidth;
    canvas.height = pixelHeight;
  }
  const ctx = canvas.getContext('2d');
  if (!ctx) return null;
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return { ctx, dpr, pixelWidth, pixelHeight };
}
