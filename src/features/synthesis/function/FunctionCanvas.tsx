import { useLayoutEffect, useRef, useState } from 'react';
import type { ViewOffset } from '../../../shared/state/appState';
import { fitView } from '../../../shared/canvas/view';
import { usePanZoom } from '../../../shared/canvas/usePanZoom';
import { useElementSize } from '../../../shared/hooks/useElementSize';
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
  const wrapRef = useRef<HTMLDivElement>(null);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const { width, height } = useElementSize(wrapRef);
  const [view, setView] = useState<ViewOffset>({ zoom: 1, panX: 0, panY: 0 });
  const bounds = functionBounds(picture);
  const panZoom = usePanZoom<never>({
    canvasRef,
    view,
    onViewChange: setView,
    width,
    height,
  });
  useLayoutEffect(() => {
    const canvas = canvasRef.current;
    const sized = canvas && sizeCanvas(canvas, width, height);
    if (sized) drawFunction(sized.ctx, picture, fitView(bounds, width, height, view));
  }, [picture, bounds, view, width, height]);
  return (
    <PanZoomCanvas
      wrapRef={wrapRef}
      canvasRef={canvasRef}
      wrapClassName="syn-canvas-wrap"
      panZoom={panZoom}
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
        draw={(ctx) => drawFunction(ctx, picture, fitView(bounds, width, height, view))}
        width={width}
        height={height}
        fileBase="synthesis-function"
      />
    </PanZoomCanvas>
  );
}
