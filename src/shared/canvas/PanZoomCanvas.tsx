import { useId } from 'react';
import type { CanvasHTMLAttributes, KeyboardEvent, PointerEvent, ReactNode, RefObject } from 'react';
import type { PanZoom } from './usePanZoom';
import { ZoomTools } from './ZoomTools';
import './PanZoomCanvas.css';
import type { ZoomToolsProps } from './ZoomTools';

/** The canvas element's own attributes (its role, label, class, test id, data-*), all but what PanZoomCanvas sets. */
type CanvasAttributes = Omit<
  CanvasHTMLAttributes<HTMLCanvasElement>,
  'onKeyDown' | 'tabIndex' | 'title' | 'aria-describedby' | 'onPointerLeave' | keyof PanZoom['pointerHandlers']
> & { [data: `data-${string}`]: string | number | undefined };

/** The wrapper's and the canvas's refs and the canvas's pan and zoom (usePanZoom's): useFittedCanvas's frame. */
export interface PanZoomFrame {
  wrapRef: RefObject<HTMLDivElement | null>;
  canvasRef: RefObject<HTMLCanvasElement | null>;
  panZoom: PanZoom;
}

/** Props of PanZoomCanvas: the frame (refs, pan and zoom), the canvas's attributes, keys, hint, overlays. */
export interface PanZoomCanvasProps {
  frame: PanZoomFrame;
  /** The class of the wrapper (it sizes the canvas: useElementSize on wrapRef). */
  wrapClassName: string;
  canvas: CanvasAttributes;
  /** Told of each pointer move after the pan and zoom's handler (a cursor readout), and when the pointer leaves. */
  onPointerMove?: (e: PointerEvent<HTMLCanvasElement>) => void;
  onPointerLeave?: () => void;
  /** Keys other than the zoom keys (+ - 0, which PanZoomCanvas takes and prevents). */
  onKeyDown?: (e: KeyboardEvent<HTMLCanvasElement>) => void;
  zoomLabels: ZoomToolsProps['labels'];
  /** The pointer and keyboard hint: the canvas's title and description, shown while the canvas has keyboard focus. */
  hint?: string;
  /** Laid over the canvas under the zoom buttons (the live stage's canvas). */
  overlay?: ReactNode;
  /** After the zoom buttons, before the hint (an empty canvas's message). */
  beforeHint?: ReactNode;
  /** After the hint (exports, a status line). */
  children?: ReactNode;
}

/**
 * The one pan-and-zoom canvas of every page (the simulator's linkage, the synthesis modes'): a focusable canvas with
 * usePanZoom's pointer handlers and zoom keys, the zoom buttons (ZoomTools) in its corner and its hint. The caller
 * draws into canvasRef and holds the view.
 */
export function PanZoomCanvas(props: PanZoomCanvasProps) {
  const { frame, wrapClassName, canvas, onKeyDown, zoomLabels, hint } = props;
  const { wrapRef, canvasRef, panZoom } = frame;
  const hintId = useId();
  return (
    <div className={`pan-zoom-wrap ${wrapClassName}`} ref={wrapRef}>
      <canvas
        ref={canvasRef}
        {...canvas}
        aria-describedby={hint ? hintId : undefined}
        title={hint}
        tabIndex={0}
        {...panZoom.pointerHandlers}
        onPointerMove={(e) => {
          panZoom.pointerHandlers.onPointerMove(e);
          props.onPointerMove?.(e);
        }}
        onPointerLeave={props.onPointerLeave}
        onKeyDown={(e) => {
          if (panZoom.onZoomKey(e)) {
            e.preventDefault();
            return;
          }
          onKeyDown?.(e);
        }}
      />
      {props.overlay}
      <ZoomTools zoomBy={panZoom.zoomBy} resetView={panZoom.resetView} labels={zoomLabels} />
      {props.beforeHint}
      {hint ? (
        <p id={hintId} className="pan-zoom-hint">
          {hint}
        </p>
      ) : null}
      {props.children}
    </div>
  );
}
