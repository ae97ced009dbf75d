import { CANVAS_TOOLS } from '../theme/tokens';
import type { ScreenRect } from './rect';

/**
 * The rectangle (CSS pixels) covered by the zoom buttons stacked in the top-right corner of a canvas
 * widthPx wide, as LinkageCanvas.css lays them out from the same tokens (CANVAS_TOOLS); labels keep out of it.
 */
export function canvasToolsRect(widthPx: number): ScreenRect {
  const { insetPx, buttonPx, gapPx, count } = CANVAS_TOOLS;
  return {
    x: widthPx - insetPx - buttonPx,
    y: insetPx,
    width: buttonPx,
    height: count * buttonPx + (count - 1) * gapPx,
  };
}
