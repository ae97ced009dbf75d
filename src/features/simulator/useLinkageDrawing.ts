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

/** The cached background bitmap (device pixels) and what it was drawn for. */
interface Background {
  canvas: HTMLCanvasElement;
  scene: LinkageScene;
  key: string;
}

/** The background bitmap for scene in this transform: the last one when it still holds, else redrawn. */
function backgroundFor(
  last: Background | null,
  scene: LinkageScene,
  transform: ViewTransform,
  pw: number,
  ph: number,
  dpr: number,
): Background {
  const t = transform;
  const key = `${pw} ${ph} ${dpr} ${t.width} ${t.height} ${t.scale} ${t.centerX} ${t.centerY} ${t.panXPx} ${t.panYPx}`;
  if (last && last.key === key && sameBackground(last.scene, scene)) return last;
  const canvas = last?.canvas ?? document.createElement('canvas');
  if (canvas.width !== pw || canvas.height !== ph) {
    canvas.width = pw;
    canvas.height = ph;
  }
  const ctx = canvas.getContext('2d');
  if (ctx) {
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    drawLinkageBackground(ctx, scene, transform);
  }
  return { canvas, scene, key };
}

/**
 * Draws the scene on the canvas (sized for devicePixelRatio) in a layout effect whenever the scene, the fit bounds,
 * the view or the size (CSS pixels) changes: the background (grid, curves, ground) is kept in a bitmap and redrawn
 * only when it changes, so Play redraws just the linkage over a copy of it. The canvas's data-o2, data-a and data-p
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
    const { ctx, dpr, pixelWidth: pw, pixelHeight: ph } = sized;
    const transform = fitScene(scene, bounds, width, height, view);
    const back = backgroundFor(background.current, scene, transform, pw, ph, dpr);
    background.current = back;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(back.canvas, 0, 0);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
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
