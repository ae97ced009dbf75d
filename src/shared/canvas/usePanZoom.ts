import { useEffect, useEffectEvent, useRef } from 'react';
import type { KeyboardEvent as ReactKeyboardEvent, PointerEvent as ReactPointerEvent, RefObject } from 'react';
import type { ViewOffset } from '../state/appState';
import type { ScreenPoint } from './canvasGestures';
import { pinchView } from './canvasGestures';
import { zoomAbout } from './view';

/** What the pointers on a pan-and-zoom canvas are doing. */
type Gesture<H> =
  | { kind: 'pan'; id: number; from: ScreenPoint; panX: number; panY: number; moved: boolean }
  | { kind: 'handle'; handle: H; id: number }
  | { kind: 'pinch'; ids: [number, number]; from: [ScreenPoint, ScreenPoint]; view: ViewOffset };

/** Options of usePanZoom: the canvas, its view and size (CSS pixels), and what its pointers may grab. */
export interface PanZoomOptions<H> {
  canvasRef: RefObject<HTMLCanvasElement | null>;
  view: ViewOffset;
  onViewChange: (view: ViewOffset) => void;
  width: number;
  height: number;
  /** The handle under a pointer at p (a joint, a target), or null to pan; pointerType sets the grab radius. */
  grab?: (p: ScreenPoint, pointerType: string) => H | null;
  /** A grabbed handle follows the pointer to p. */
  onDrag?: (handle: H, p: ScreenPoint) => void;
  /** A handle was grabbed (start) or let go (end). */
  onGrab?: (handle: H | null) => void;
  /** A press and release without panning (a click or a tap) at p, where nothing was grabbed. */
  onTap?: (p: ScreenPoint) => void;
}

/** Pointer, wheel and key handlers of a pan-and-zoom canvas, and the zoom buttons' actions. */
export interface PanZoom {
  pointerHandlers: {
    onPointerDown: (e: ReactPointerEvent<HTMLCanvasElement>) => void;
    onPointerMove: (e: ReactPointerEvent<HTMLCanvasElement>) => void;
    onPointerUp: (e: ReactPointerEvent<HTMLCanvasElement>) => void;
    onPointerCancel: (e: ReactPointerEvent<HTMLCanvasElement>) => void;
    onDoubleClick: () => void;
  };
  /** Zooms about the canvas centre by factor. */
  zoomBy: (factor: number) => void;
  /** Back to the fitted view. */
  resetView: () => void;
  /** Handles + (or =), - and 0; returns whether the key was one of them (the caller then prevents its default). */
  onZoomKey: (e: ReactKeyboardEvent) => boolean;
}

/** Pointer travel (CSS pixels) below which a press and release is a tap, not a pan. */
const TAP_SLOP_PX = 4;

/** Where a pointer event is, in CSS pixels from the canvas's top-left corner. */
export function canvasPoint(e: { clientX: number; clientY: number; currentTarget: Element }): ScreenPoint {
  const r = e.currentTarget.getBoundingClientRect();
  return { x: e.clientX - r.left, y: e.clientY - r.top };
}

/** Zooms a canvas about the pointer on the wheel, through a native non-passive listener so the page does not scroll. */
function useWheelZoom(
  canvasRef: RefObject<HTMLCanvasElement | null>,
  view: ViewOffset,
  onViewChange: (view: ViewOffset) => void,
): void {
  const onWheel = useEffectEvent((e: WheelEvent, canvas: HTMLCanvasElement) => {
    e.preventDefault();
    const r = canvas.getBoundingClientRect();
    const factor = Math.exp(-e.deltaY * (e.deltaMode === 1 ? 0.05 : 0.0015));
    onViewChange(zoomAbout(view, factor, e.clientX - r.left, e.clientY - r.top, r.width, r.height));
  });
  useEffect(() => {
    const canvas = canvasRef.current;
    if (!canvas) return;
    const listener = (e: WheelEvent) => onWheel(e, canvas);
    canvas.addEventListener('wheel', listener, { passive: false });
    return () => canvas.removeEventListener('wheel', listener);
  }, [canvasRef]);
}

/** The gesture a pointer going down starts: a pinch with a second pointer, else a drag of the handle under it, else a pan. */
function startGesture<H>(
  pointers: Map<number, ScreenPoint>,
  id: number,
  p: ScreenPoint,
  view: ViewOffset,
  handleAt: () => H | null,
): Gesture<H> {
  if (pointers.size >= 2) {
    const [[ia, a], [ib, b]] = [...pointers.entries()];
    return { kind: 'pinch', ids: [ia, ib], from: [a, b], view };
  }
  const handle = handleAt();
  if (handle !== null) return { kind: 'handle', handle, id };
  return { kind: 'pan', id, from: p, panX: view.panX, panY: view.panY, moved: false };
}

/** The view a pan has reached with its pointer at p; null until the pointer has moved past TAP_SLOP_PX (a tap). */
function pannedView(
  g: Extract<Gesture<unknown>, { kind: 'pan' }>,
  p: ScreenPoint,
  zoom: number,
  width: number,
  height: number,
): ViewOffset | null {
  if (width <= 0 || height <= 0) return null;
  if (Math.hypot(p.x - g.from.x, p.y - g.from.y) > TAP_SLOP_PX) g.moved = true;
  if (!g.moved) return null;
  return { zoom, panX: g.panX + (p.x - g.from.x) / width, panY: g.panY + (p.y - g.from.y) / height };
}

/**
 * Pan and zoom for a canvas (mafs calls its equivalent useCamera): drag on empty space pans, a second finger
 * pinches, the wheel zooms about the pointer (a native non-passive listener, so the page does not scroll),
 * double-click fits, + - 0 on the keyboard; a pointer that lands on a handle (options.grab) drags it instead.
 * The view is the caller's state: the hook only calls onViewChange.
 */
export function usePanZoom<H>(options: PanZoomOptions<H>): PanZoom {
  const { canvasRef, view, onViewChange, width, height, grab, onDrag, onGrab, onTap } = options;
  // Pointers down on the canvas and the gesture they make; touched in handlers only.
  const pointers = useRef(new Map<number, ScreenPoint>());
  const gesture = useRef<Gesture<H> | null>(null);

  useWheelZoom(canvasRef, view, onViewChange);

  const zoomBy = (factor: number) => onViewChange(zoomAbout(view, factor, width / 2, height / 2, width, height));
  const resetView = () => onViewChange({ zoom: 1, panX: 0, panY: 0 });
  const release = (e: ReactPointerEvent<HTMLCanvasElement>, tap: boolean) => {
    pointers.current.delete(e.pointerId);
    const g = gesture.current;
    gesture.current = null;
    if (g?.kind === 'handle') onGrab?.(null);
    if (tap && g?.kind === 'pan' && !g.moved && g.id === e.pointerId) onTap?.(canvasPoint(e));
  };

  return {
    pointerHandlers: {
      onPointerDown(e) {
        if (e.pointerType === 'mouse' && e.button !== 0) return;
        e.currentTarget.setPointerCapture(e.pointerId);
        const p = canvasPoint(e);
        pointers.current.set(e.pointerId, p);
        // A second finger turns any drag into a pinch.
        if (pointers.current.size >= 2 && gesture.current?.kind === 'handle') onGrab?.(null);
        const g = startGesture(pointers.current, e.pointerId, p, view, () => (grab ? grab(p, e.pointerType) : null));
        gesture.current = g;
        if (g.kind === 'handle') onGrab?.(g.handle);
      },
      onPointerMove(e) {
        const p = canvasPoint(e);
        const g = gesture.current;
        if (!g) {
          // Hovering: show that a handle can be grabbed.
          const over = grab ? grab(p, e.pointerType) !== null : false;
          e.currentTarget.classList.toggle('over-handle', over);
          return;
        }
        if (!pointers.current.has(e.pointerId)) return;
        pointers.current.set(e.pointerId, p);
        if (g.kind === 'pinch') {
          const a = pointers.current.get(g.ids[0]);
          const b = pointers.current.get(g.ids[1]);
          if (a && b) onViewChange(pinchView(g.view, g.from[0], g.from[1], a, b, width, height));
        } else if (g.id !== e.pointerId) {
          return;
        } else if (g.kind === 'pan') {
          const next = pannedView(g, p, view.zoom, width, height);
          if (next) onViewChange(next);
        } else {
          onDrag?.(g.handle, p);
        }
      },
      onPointerUp: (e) => release(e, true),
      onPointerCancel: (e) => release(e, false),
      onDoubleClick: resetView,
    },
    zoomBy,
    resetView,
    onZoomKey(e) {
      if (e.key === '+' || e.key === '=') zoomBy(1.25);
      else if (e.key === '-') zoomBy(0.8);
      else if (e.key === '0') resetView();
      else return false;
      return true;
    },
  };
}
