import { canvasToolsRect } from '../canvas/canvasTools';
import type { Bounds, ViewTransform } from '../canvas/view';
import { drawLinkageBackground, drawLinkageForeground, sameBackground } from './drawLinkage';
import type { LinkageScene } from './scene';
import { fitScene } from './scene';
import type { ViewOffset } from '../state/appState';

/** A 2D context a linkage frame is drawn on: a canvas's on the page, or an OffscreenCanvas's in a worker. */
export type FrameContext = CanvasRenderingContext2D | OffscreenCanvasRenderingContext2D;

/** A bitmap the background is kept in: a canvas element on the page, an OffscreenCanvas in a worker. */
export type BackgroundCanvas = HTMLCanvasElement | OffscreenCanvas;

/** The canvas's bitmap size (device pixels) and its pixel ratio. */
export interface FrameSize {
  dpr: number;
  pixelWidth: number;
  pixelHeight: number;
}

/** What a canvas's background was last drawn for, and the bitmap that keeps it once it is drawn a second time. */
export interface FrameBackground {
  scene: LinkageScene;
  key: string;
  /** The bitmap (device pixels), kept between draws so it is allocated once. */
  canvas: BackgroundCanvas | null;
  /** Whether the bitmap holds this background. */
  cached: boolean;
}

/**
 * Draws the background of scene under ctx (scaled to CSS pixels) and returns what it drew. A background drawn for
 * the first time is drawn straight on the canvas; the second draw of the same background (the first frame of Play
 * or of a θ2 drag) keeps it in a bitmap from makeCanvas, and later ones copy the bitmap. A one-off draw (the first
 * load, a length edit) so costs no second bitmap and no copy.
 */
function drawBackground(
  ctx: FrameContext,
  last: FrameBackground | null,
  scene: LinkageScene,
  transform: ViewTransform,
  size: FrameSize,
  makeCanvas: (width: number, height: number) => BackgroundCanvas,
): FrameBackground {
  const { dpr, pixelWidth: pw, pixelHeight: ph } = size;
  const t = transform;
  const key = `${pw} ${ph} ${dpr} ${t.width} ${t.height} ${t.scale} ${t.centerX} ${t.centerY} ${t.panXPx} ${t.panYPx}`;
  const same = last !== null && last.key === key && sameBackground(last.scene, scene);
  if (!same) {
    drawLinkageBackground(ctx, scene, transform);
    return { scene, key, canvas: last?.canvas ?? null, cached: false };
  }
  let next = last;
  if (!last.cached) {
    const canvas = last.canvas ?? makeCanvas(pw, ph);
    if (canvas.width !== pw || canvas.height !== ph) {
      canvas.width = pw;
      canvas.height = ph;
    }
    const back = canvas.getContext('2d') as FrameContext | null;
    if (!back) {
      drawLinkageBackground(ctx, scene, transform);
      return { ...last, canvas };
    }
    back.setTransform(dpr, 0, 0, dpr, 0, 0);
    drawLinkageBackground(back, scene, transform);
    next = { scene, key, canvas, cached: true };
  }
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.drawImage(next.canvas as BackgroundCanvas, 0, 0);
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return next;
}

/** Where a frame is drawn: the scene, the bounds to fit, the user's pan and zoom, and the canvas size in CSS pixels. */
export interface FrameView {
  bounds: Bounds;
  view: ViewOffset;
  width: number;
  height: number;
}

/**
 * Draws one frame of the linkage on ctx (scaled to CSS pixels, its bitmap sized as `size` says): the background
 * (kept in a bitmap once it repeats, drawBackground) and the linkage over it, its labels clear of the zoom buttons.
 * Returns the background to pass to the next frame and the view transform it drew in. The page's canvas
 * (useLinkageDrawing) and the live stage's worker draw every frame through here.
 */
export function drawLinkageFrame(
  ctx: FrameContext,
  last: FrameBackground | null,
  scene: LinkageScene,
  where: FrameView,
  size: FrameSize,
  makeCanvas: (width: number, height: number) => BackgroundCanvas,
): { background: FrameBackground; transform: ViewTransform } {
  const transform = fitScene(scene, where.bounds, where.width, where.height, where.view);
  const background = drawBackground(ctx, last, scene, transform, size, makeCanvas);
  drawLinkageForeground(ctx, scene, transform, [canvasToolsRect(where.width)]);
  return { background, transform };
}
