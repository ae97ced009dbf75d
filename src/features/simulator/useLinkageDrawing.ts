import { useLayoutEffect, useRef } from 'react';
import type { RefObject } from 'react';
import { canvasToolsRect } from '../../shared/canvas/canvasTools';
import type { Bounds, ViewTransform } from '../../shared/canvas/view';
import { frameToScreen } from '../../shared/canvas/view';
import { drawLinkageBackground, drawLinkageForeground, sameBackground } from '../../shared/linkage/drawLinkage';
import type { LinkageScene } from '../../shared/linkage/scene';
import { fitScene } from '../../shared/linkage/scene';
import type { ViewOffset } from '../../shared/state/appState';
import { benchMark } from '../../shared/benchMarks';
import { sizeCanvas } from '../../shared/canvas/sizeCanvas';

/** What the canvas's background was last drawn for, and the bitmap that keeps it once it is drawn a second time. */
interface Background {
  scene: LinkageScene;
  key: string;
  /** The bitmap (device pixels), kept between draws so it is allocated once. */
  canvas: HTMLCanvasElement | null;
  /** Whether the bitmap holds this background. */
  cached: boolean;
}

/**
 * Draws the background of scene under ctx (scaled to CSS pixels) and returns what it drew. A background drawn for
 * the first time is drawn straight on the canvas; the second draw of the same background (the first frame of Play
 * or of a θ2 drag) keeps it in a bitmap, and later ones copy the bitmap. A one-off draw (the first load, a length
 * edit) so costs no second bitmap and no copy.
 */
function drawBackground(
  ctx: CanvasRenderingContext2D,
  last: Background | null,
  scene: LinkageScene,
  transform: ViewTransform,
  sized: { dpr: number; pixelWidth: number; pixelHeight: number },
): Background {
  const { dpr, pixelWidth: pw, pixelHeight: ph } = sized;
  const t = transform;
  const key = `${pw} ${ph} ${dpr} ${t.width} ${t.height} ${t.scale} ${t.centerX} ${t.centerY} ${t.panXPx} ${t.panYPx}`;
  const same = last !== null && last.key === key && sameBackground(last.scene, scene);
  if (!same) {
    drawLinkageBackground(ctx, scene, transform);
    return { scene, key, canvas: last?.canvas ?? null, cached: false };
  }
  let next = last;
  if (!last.cached) {
    const canvas = last.canvas ?? document.createElement('canvas');
    if (canvas.width !== pw || canvas.height !== ph) {
      canvas.width = pw;
      canvas.height = ph;
    }
    const back = canvas.getContext('2d');
    if (!back) {
      drawLinkageBackground(ctx, scene, transform);
      return { ...last, canvas };
    }
    back.setTransform(dpr, 0, 0, dpr, 0, 0);
    drawLinkageBackground(back, scene, transform);
    next = { scene, key, canvas, cached: true };
  }
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.drawImage(next.canvas as HTMLCanvasElement, 0, 0);
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return next;
}

/**
 * Draws the scene on the canvas (sized for devicePixelRatio) in a layout effect whenever the scene, the fit bounds,
 * the view or the size (CSS pixels) changes: the background (grid, curves, ground) is kept in a bitmap once it is
 * drawn twice (drawBackground), so Play redraws just the linkage over a copy of it. The canvas's data-o2, data-a and data-p
 * say where the draggable joints are drawn (CSS pixels), for tests and tools that drive the canvas.
 */
export function useLinkageDrawing(
  canvasRef: RefObject<HTMLCanvasElement | null>,
  scene: LinkageScene,
  bounds: Bounds,
  view: ViewOffset,
  width: number,
  height: number,
): void {
  // Touched in the drawing effect only.
  const background = useRef<Background | null>(null);
  useLayoutEffect(() => {
    const canvas = canvasRef.current;
    const sized = canvas && sizeCanvas(canvas, width, height);
    if (!sized) return;
    const { ctx } = sized;
    const transform = fitScene(scene, bounds, width, height, view);
    background.current = drawBackground(ctx, background.current, scene, transform, sized);
    drawLinkageForeground(ctx, scene, transform, [canvasToolsRect(width)]);
    // Where the draggable joints are drawn (CSS pixels), for tests and tools that drive the canvas.
    const at = (p: { x: number; y: number } | undefined) => {
      const s = p ? frameToScreen(transform, p) : null;
      return s ? `${s.x.toFixed(1)},${s.y.toFixed(1)}` : '';
    };
    canvas.dataset.o2 = at({ x: 0, y: 0 });
    canvas.dataset.a = at(scene.pose?.A);
    canvas.dataset.p = at(scene.pose?.P);
    benchMark('fourbar:canvas', { theta2Rad: scene.theta2 });
  }, [canvasRef, scene, bounds, view, width, height]);
}
