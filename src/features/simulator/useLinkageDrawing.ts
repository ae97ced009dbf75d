import { useLayoutEffect, useRef } from 'react';
import type { RefObject } from 'react';
import type { Bounds, ViewTransform } from '../../shared/canvas/view';
import { frameToScreen } from '../../shared/canvas/view';
import type { FrameBackground } from '../../shared/linkage/linkageFrame';
import { drawLinkageFrame } from '../../shared/linkage/linkageFrame';
import type { LinkageScene } from '../../shared/linkage/scene';
import { fitScene } from '../../shared/linkage/scene';
import type { ViewOffset } from '../../shared/state/appState';
import { benchMark } from '../../shared/benchMarks';
import { sizeCanvas } from '../../shared/canvas/sizeCanvas';
import { JUDGED_AFTER_DRAWS } from './stage/pageDraws';

/** A canvas element for the background bitmap. */
const newCanvas = () => document.createElement('canvas');

/**
 * Draws timed before the page stops redrawing the first frame at idle to time it (see useLinkageDrawing): as many as
 * the live stage's judgement of the page waits for.
 */
const MEASURED_DRAWS = JUDGED_AFTER_DRAWS;

/** Runs task when the page is idle (requestIdleCallback, or a short timeout where there is none); returns its cancel. */
function whenIdle(task: () => void): () => void {
  if (typeof requestIdleCallback === 'function') {
    const handle = requestIdleCallback(task, { timeout: 1000 });
    return () => cancelIdleCallback(handle);
  }
  const handle = setTimeout(task, 100);
  return () => clearTimeout(handle);
}

/**
 * Draws the scene on the canvas (sized for devicePixelRatio) in a layout effect whenever the scene, the fit bounds,
 * the view or the size (CSS pixels) changes: the background (grid, curves, ground) is kept in a bitmap once it is
 * drawn twice (drawLinkageFrame), so Play redraws just the linkage over a copy of it. The canvas's data-o2, data-a and data-p
 * say where the draggable joints are drawn (CSS pixels), for tests and tools that drive the canvas. onDrawn gets how
 * long each draw took (ms). While covered (the live stage's canvas lies over this one and shows Play) nothing is drawn,
 * only the joints' places are updated: the canvas is drawn again in the commit that uncovers it.
 */
export function useLinkageDrawing(
  canvasRef: RefObject<HTMLCanvasElement | null>,
  scene: LinkageScene,
  bounds: Bounds,
  view: ViewOffset,
  width: number,
  height: number,
  onDrawn?: (ms: number) => void,
  covered = false,
): void {
  // Touched in the drawing effect only.
  const background = useRef<FrameBackground | null>(null);
  /** How many draws were timed (the idle redraws of the first count). */
  const measured = useRef(0);
  useLayoutEffect(() => {
    const canvas = canvasRef.current;
    if (canvas && covered) {
      markJoints(canvas, scene, fitScene(scene, bounds, width, height, view));
      return;
    }
    const sized = canvas && sizeCanvas(canvas, width, height);
    if (!sized) return;
    const started = performance.now();
    const drawn = drawLinkageFrame(
      sized.ctx,
      background.current,
      scene,
      { bounds, view, width, height },
      sized,
      newCanvas,
    );
    background.current = drawn.background;
    markJoints(canvas, scene, drawn.transform);
    onDrawn?.(performance.now() - started);
    benchMark('fourbar:canvas', { theta2Rad: scene.theta2 });
    measured.current += 1;
    if (!onDrawn || measured.current >= MEASURED_DRAWS) return;
    // The first draws carry one-time costs (fonts, compiling, the background's bitmap): the same frame is drawn again
    // when the page is idle until MEASURED_DRAWS are timed, so the time of a draw like Play's and a drag's is known
    // before the first one (the live stage's route).
    let cancel = () => {};
    const redraw = () => {
      const again = performance.now();
      background.current = drawLinkageFrame(
        sized.ctx,
        background.current,
        scene,
        { bounds, view, width, height },
        sized,
        newCanvas,
      ).background;
      measured.current += 1;
      onDrawn(performance.now() - again);
      if (measured.current < MEASURED_DRAWS) cancel = whenIdle(redraw);
    };
    cancel = whenIdle(redraw);
    return () => cancel();
  }, [canvasRef, scene, bounds, view, width, height, onDrawn, covered]);
}

/** Writes where the draggable joints are drawn (CSS pixels) on the canvas, for tests and tools that drive it. */
function markJoints(canvas: HTMLCanvasElement, scene: LinkageScene, transform: ViewTransform): void {
  const at = (p: { x: number; y: number } | undefined) => {
    const s = p ? frameToScreen(transform, p) : null;
    return s ? `${s.x.toFixed(1)},${s.y.toFixed(1)}` : '';
  };
  canvas.dataset.o2 = at({ x: 0, y: 0 });
  canvas.dataset.a = at(scene.pose?.A);
  canvas.dataset.p = at(scene.pose?.P);
}
