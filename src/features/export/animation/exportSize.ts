/** Output sizes offered: the linkage view as on screen (CSS size × devicePixelRatio), or 1280 × 720. */
export type AnimationSize = 'screen' | '720p';

/** Width and height of the 720p size, pixels. */
export const SIZE_720P = { width: 1280, height: 720 } as const;

/** Largest side the export makes, pixels (a 4K screen at devicePixelRatio 2 stays under it). */
export const MAX_SIDE_PX = 4096;

/** Where the view lands in the output: scale (output pixels per CSS pixel) and the offset of its top left corner. */
export interface Letterbox {
  scale: number;
  offsetX: number;
  offsetY: number;
}

function even(px: number): number {
  return Math.max(2, 2 * Math.round(px / 2));
}

/**
 * Output size in pixels for a view of viewWidth x viewHeight CSS pixels: 'screen' is the view times
 * devicePixelRatio, '720p' is 1280 x 720. Sides are rounded to even numbers (video encoders need them) and
 * capped at MAX_SIDE_PX keeping the aspect ratio. Throws for a view or ratio that is not positive and finite.
 */
export function exportSizePx(
  size: AnimationSize,
  viewWidth: number,
  viewHeight: number,
  devicePixelRatio: number,
): { width: number; height: number } {
  for (const [name, v] of [
    ['viewWidth', viewWidth],
    ['viewHeight', viewHeight],
    ['devicePixelRatio', devicePixelRatio],
  ] as const) {
    if (!(v > 0) || !Number.isFinite(v)) throw new Error(`${name} must be a positive finite number, got ${v}`);
  }
  if (size === '720p') return { ...SIZE_720P };
  const w = viewWidth * devicePixelRatio;
  const h = viewHeight * devicePixelRatio;
  const k = Math.min(1, MAX_SIDE_PX / Math.max(w, h));
  return { width: even(w * k), height: even(h * k) };
}

/**
 * Fits a view of viewWidth x viewHeight CSS pixels into width x height output pixels, whole and centred,
 * keeping its aspect ratio (bars on two sides when the ratios differ), so the picture is the one on screen.
 */
export function letterbox(viewWidth: number, viewHeight: number, width: number, height: number): Letterbox {
  const scale = Math.min(width / viewWidth, height / viewHeight);
  return { scale, offsetX: (width - viewWidth * scale) / 2, offsetY: (height - viewHeight * scale) / 2 };
}
