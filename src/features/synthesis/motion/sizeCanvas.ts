/**
 * Sizes a canvas's bitmap for devicePixelRatio (capped at 4) at width × height CSS pixels and returns its context
 * scaled to CSS pixels; null when the canvas has no size yet or no 2D context.
 */
export function sizeCanvas(canvas: HTMLCanvasElement, width: number, height: number): CanvasRenderingContext2D | null {
  if (width <= 0 || height <= 0) return null;
  const dpr = Math.max(1, Math.min(4, window.devicePixelRatio || 1));
  const pw = Math.round(width * dpr);
  const ph = Math.round(height * dpr);
  if (canvas.width !== pw || canvas.height !== ph) {
    canvas.width = pw;
    canvas.height = ph;
  }
  const ctx = canvas.getContext('2d');
  ctx?.setTransform(dpr, 0, 0, dpr, 0, 0);
  return ctx;
}
