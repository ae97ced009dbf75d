import { useLayoutEffect } from 'react';
import { useFittedCanvas } from '../../../shared/canvas/useFittedCanvas';
import { fitView } from '../../../shared/canvas/view';
import { PanZoomCanvas } from '../../../shared/canvas/PanZoomCanvas';
import { sizeCanvas } from '../../../shared/canvas/sizeCanvas';
import { CanvasExports } from '../CanvasExports';
import type { FunctionPicture } from './functionPicture';
import { drawFunction, functionBounds } from './functionPicture';

/** Props of FunctionCanvas: the picture and the texts. */
export interface FunctionCanvasProps {
  picture: FunctionPicture;
  labels: { canvas: string; zoomIn: string; zoomOut: string; resetView: string };
}

/** The function generator on a pan-and-zoom canvas (drag pans, wheel or pinch zooms, + − 0 on the keyboard). */
export function FunctionCanvas({ picture, labels }: FunctionCanvasProps) {
  const bounds = functionBounds(picture);
  const { frame, canvasRef, width, height, view, transform } = useFittedCanvas(bounds);
  useLayoutEffect(() => {
    const canvas = canvasRef.current;
    const sized = canvas && sizeCanvas(canvas, width, height);
    if (sized) drawFunction(sized.ctx, picture, fitView(bounds, width, height, view));
  }, [canvasRef, picture, bounds, view, width, height]);
  return (
    <PanZoomCanvas
      frame={frame}
      wrapClassName="syn-canvas-wrap"
      canvas={{
        className: 'synmode-canvas',
        role: 'img',
        'aria-label': labels.canvas,
        'aria-keyshortcuts': '+ - 0',
        'data-testid': 'function-canvas',
      }}
      zoomLabels={labels}
    >
      <CanvasExports
        draw={(ctx) => drawFunction(ctx, picture, transform())}
        width={width}
        height={height}
        fileBase="synthesis-function"
      />
    </PanZoomCanvas>
  );
}
