import type { ViewTransform } from '../../../shared/canvas/view';
import { fitView } from '../../../shared/canvas/view';
import type { MechPicture } from '../drawMechanism';
import { drawMechanismBackground, drawMechanismParts } from '../drawMechanism';
import type { MechStagePainter } from './mechStageLoop';
import type { MechStageView } from './mechStageProtocol';

/** A background bitmap and what it was drawn for (the traces, faintness, view and size, compared by identity). */
interface Background {
  bitmap: OffscreenCanvas;
  traces: MechPicture['traces'];
  faint: boolean;
  view: MechStageView;
}

/**
 * The live stage's painter on an OffscreenCanvas: sizes its bitmap for the view's pixel ratio and draws the picture
 * as drawMechanism does, in the view the page's canvas fits (fitView). The background, grid and traces
 * (drawMechanismBackground) are kept in a bitmap while the traces and the view hold, and copied under each frame's
 * links (drawMechanismParts): rasterising the grid and the traces' hundreds of segments again was most of a frame.
 */
export function createMechStagePainter(): MechStagePainter {
  let canvas: OffscreenCanvas | null = null;
  let background: Background | null = null;
  const backgroundFor = (picture: MechPicture, view: MechStageView, v: ViewTransform): OffscreenCanvas | null => {
    const b = background;
    if (b && b.traces === picture.traces && b.faint === picture.faint && b.view === view) return b.bitmap;
    const bitmap = new OffscreenCanvas(Math.round(view.width * view.dpr), Math.round(view.height * view.dpr));
    const ctx = bitmap.getContext('2d');
    if (!ctx) return null;
    ctx.setTransform(view.dpr, 0, 0, view.dpr, 0, 0);
    drawMechanismBackground(ctx, picture, v);
    background = { bitmap, traces: picture.traces, faint: picture.faint, view };
    return bitmap;
  };
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
      const v = fitView(view.bounds, width, height, view.offset);
      const bitmap = backgroundFor(picture, view, v);
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      if (bitmap) ctx.drawImage(bitmap, 0, 0);
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      if (!bitmap) drawMechanismBackground(ctx, picture, v);
      drawMechanismParts(ctx, picture, v);
      return performance.now() - started;
    },
  };
}
