import type { AnimationFrame } from './animationFrames';
import { letterbox } from './exportSize';
import type { FrameContext, RenderFrame } from './types';

/** A drawing surface of the output size and a way to read its pixels back. */
export interface FrameSurface {
  ctx: FrameContext;
  width: number;
  height: number;
  /** The surface's RGBA pixels now (a fresh array the caller may transfer). */
  readPixels(): Uint8ClampedArray;
}

/**
 * A surface of width x height pixels: an OffscreenCanvas where there is one, else a detached canvas element.
 * Throws when the browser gives no 2D context.
 */
export function createFrameSurface(width: number, height: number): FrameSurface {
  let ctx: FrameContext | null;
  if (typeof OffscreenCanvas !== 'undefined') {
    ctx = new OffscreenCanvas(width, height).getContext('2d', { willReadFrequently: true });
  } else {
    const canvas = document.createElement('canvas');
    canvas.width = width;
    canvas.height = height;
    ctx = canvas.getContext('2d', { willReadFrequently: true });
  }
  if (!ctx) throw new Error(`no 2D context for a ${width}x${height} canvas`);
  const c = ctx;
  return { ctx: c, width, height, readPixels: () => c.getImageData(0, 0, width, height).data };
}

/** What drawFrame needs besides the frame: the view size (CSS pixels), the bars' colour and the caller's drawing. */
export interface DrawFrameOptions {
  viewWidth: number;
  viewHeight: number;
  background: string;
  renderFrame: RenderFrame;
}

/**
 * Clears the surface to the background, letterboxes the view into it and lets renderFrame draw the frame
 * in view (CSS pixel) coordinates, clipped to the view.
 */
export async function drawFrame(
  surface: Pick<FrameSurface, 'ctx' | 'width' | 'height'>,
  frame: AnimationFrame,
  o: DrawFrameOptions,
): Promise<void> {
  const { ctx, width, height } = surface;
  const box = letterbox(o.viewWidth, o.viewHeight, width, height);
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = o.background;
  ctx.fillRect(0, 0, width, height);
  ctx.save();
  ctx.setTransform(box.scale, 0, 0, box.scale, box.offsetX, box.offsetY);
  ctx.beginPath();
  ctx.rect(0, 0, o.viewWidth, o.viewHeight);
  ctx.clip();
  try {
    await o.renderFrame(ctx, frame, o.viewWidth, o.viewHeight);
  } finally {
    ctx.restore();
  }
}
