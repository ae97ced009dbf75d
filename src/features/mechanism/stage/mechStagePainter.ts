import { fitView } from '../../../shared/canvas/view';
import { drawMechanism } from '../drawMechanism';
import type { MechStagePainter } from './mechStageLoop';

/**
 * The live stage's painter on an OffscreenCanvas: sizes its bitmap for the view's pixel ratio and draws the picture
 * with drawMechanism in the view the page's canvas fits (fitView), as the page's canvas does.
 */
export function createMechStagePainter(): MechStagePainter {
  let canvas: OffscreenCanvas | null = null;
  return {
    setCanvas(next) {
      canvas = next;
    },
    draw(picture, view) {
      const started = performance.now();
      const ctx = canvas?.getContext('2d');
      const { width, height, dpr } = view;
      if (!canvas || !ctx || width <= 0 || height <= 0) return null;
      const pixelWidth = Math.round(width * dpr);
      const pixelHeight = Math.round(height * dpr);
      if (canvas.width !== pixelWidth || canvas.height !== pixelHeight) {
        canvas.width = pixelWidth;
        canvas.height = pixelHeight;
      }
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      drawMechanism(ctx, picture, fitView(view.bounds, width, height, view.offset));
      return performance.now() - started;
    },
  };
}
