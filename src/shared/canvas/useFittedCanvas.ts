import { useRef, useState } from 'react';
import type { RefObject } from 'react';
import { useElementSize } from '../hooks/useElementSize';
import type { ViewOffset } from '../state/appState';
import type { PanZoomFrame } from './PanZoomCanvas';
import type { PanZoomOptions } from './usePanZoom';
import { usePanZoom } from './usePanZoom';
import type { Bounds, ViewTransform } from './view';
import { fitView } from './view';

/** What a canvas's pointers may grab and do (usePanZoom's options without the canvas, view and size). */
export type CanvasGestures<H> = Omit<PanZoomOptions<H>, 'canvasRef' | 'view' | 'onViewChange' | 'width' | 'height'>;

/** Options of useFittedCanvas: the canvas element and the view when the caller holds them (else held here). */
export interface FittedCanvasOptions {
  canvasRef?: RefObject<HTMLCanvasElement | null>;
  view?: ViewOffset;
  onViewChange?: (view: ViewOffset) => void;
}

/** A fitted pan-and-zoom canvas (useFittedCanvas): PanZoomCanvas's frame props, the size, the view and its transform. */
export interface FittedCanvas {
  /** PanZoomCanvas's frame: its wrapper and canvas refs and its pan and zoom. */
  frame: PanZoomFrame;
  /** The canvas (frame's), to draw into in an effect. */
  canvasRef: RefObject<HTMLCanvasElement | null>;
  /** The canvas's size in CSS pixels (the wrapper's). */
  width: number;
  height: number;
  view: ViewOffset;
  /** The view transform now: bounds fitted to the canvas, then the pan and zoom. */
  transform: () => ViewTransform;
}

/**
 * The wiring of a PanZoomCanvas that fits bounds (the synthesis modes', the mechanism's): the wrapper's and the
 * canvas's refs, the size, the view (the caller's, or held here from the fit), and usePanZoom with the gestures,
 * which get the transform as it is when they run.
 */
export function useFittedCanvas<H = never>(
  bounds: Bounds,
  gestures: (transform: () => ViewTransform) => CanvasGestures<H> = () => ({}),
  options: FittedCanvasOptions = {},
): FittedCanvas {
  const wrapRef = useRef<HTMLDivElement>(null);
  const ownCanvasRef = useRef<HTMLCanvasElement>(null);
  const canvasRef = options.canvasRef ?? ownCanvasRef;
  const { width, height } = useElementSize(wrapRef);
  const [ownView, setOwnView] = useState<ViewOffset>({ zoom: 1, panX: 0, panY: 0 });
  const view = options.view ?? ownView;
  const onViewChange = options.onViewChange ?? setOwnView;
  const transform = () => fitView(bounds, width, height, view);
  const panZoom = usePanZoom<H>({ canvasRef, view, onViewChange, width, height, ...gestures(transform) });
  return { frame: { wrapRef, canvasRef, panZoom }, canvasRef, width, height, view, transform };
}
