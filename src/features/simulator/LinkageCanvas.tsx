import './LinkageCanvas.css';
import { memo, useEffect, useEffectEvent, useId, useLayoutEffect, useRef, useState } from 'react';
import type { PointerEvent as ReactPointerEvent } from 'react';
import { flushSync } from 'react-dom';
import { radToDeg360, wrapDeg360 } from '../../solver/angles';
import { canvasToolsRect } from '../../shared/canvas/canvasTools';
import { drawLinkageBackground, drawLinkageForeground, sameBackground } from '../../shared/linkage/drawLinkage';
import type { LinkageScene } from '../../shared/linkage/scene';
import type { Bounds, ViewTransform } from '../../shared/canvas/view';
import { fitView, toScreenX, toScreenY, zoomAbout } from '../../shared/canvas/view';
import type { CouplerPoint, ViewOffset } from '../../shared/state/appState';
import { benchMark } from '../../shared/jobs/benchMarks';
import type { ScreenPoint } from '../../shared/canvas/canvasGestures';
import { couplerAt, crankAngleAt, grabRadiusPx, hitHandle, pinchView } from '../../shared/canvas/canvasGestures';
import { Icon } from '../../shared/ui/Icon';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { useElementSize } from '../../shared/hooks/useElementSize';

/** Props of LinkageCanvas: the scene, the user's pan and zoom, what can be dragged, and a size report for exports. */
export interface LinkageCanvasProps {
  scene: LinkageScene;
  view: ViewOffset;
  onViewChange: (view: ViewOffset) => void;
  /** Sets theta2 (degrees) when the crank pin A is dragged or turned with the arrow keys; omit when locked. */
  onTheta2?: (theta2Deg: number) => void;
  /** Moves the coupler point P (distance from A, angle from AB in degrees) when it is dragged; omit when locked. */
  onCoupler?: (coupler: CouplerPoint) => void;
  /** Called with the canvas size in CSS pixels whenever it changes. */
  onSize?: (width: number, height: number) => void;
  /** Accessible description of the pose, e.g. the angles. */
  description: string;
  /** The visible hint for the pointer and keyboard controls (shown while the canvas has focus). */
  hint: string;
}

/** What the pointers on the canvas are doing. */
type Gesture =
  | { kind: 'pan'; id: number; from: ScreenPoint; panX: number; panY: number }
  | { kind: 'A' | 'P'; id: number }
  | { kind: 'pinch'; ids: [number, number]; from: [ScreenPoint, ScreenPoint]; view: ViewOffset };

/** Degrees the arrow keys turn the crank (with Shift: ten times as far). */
const KEY_STEP_DEG = 1;

/** The background bitmap for scene in this transform: the last one when it still holds, else redrawn. */
function backgroundFor(
  last: { canvas: HTMLCanvasElement; scene: LinkageScene; key: string } | null,
  scene: LinkageScene,
  transform: ViewTransform,
  pw: number,
  ph: number,
  dpr: number,
): { canvas: HTMLCanvasElement; scene: LinkageScene; key: string } {
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

function LinkageCanvasImpl({
  scene,
  view,
  onViewChange,
  onTheta2,
  onCoupler,
  onSize,
  description,
  hint,
}: LinkageCanvasProps) {
  const t = useMessages();
  const hintId = useId();
  const wrapRef = useRef<HTMLDivElement>(null);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const { width, height } = useElementSize(wrapRef);
  // Pointers down on the canvas (CSS pixels from its corner) and the gesture they make; touched in handlers only.
  const pointers = useRef(new Map<number, ScreenPoint>());
  const gesture = useRef<Gesture | null>(null);
  // While A or P is dragged the fit stays put: a new cycle (P moved) would otherwise rescale the view under
  // the pointer and the joint would drift away from it.
  const [heldBounds, setHeldBounds] = useState<Bounds | null>(null);
  const bounds = heldBounds ?? scene.bounds;
  // The background (grid, curves, ground) as last drawn, device pixels, and what it was drawn for: touched
  // in the drawing effect only. Play redraws only the linkage over a copy of it.
  const background = useRef<{ canvas: HTMLCanvasElement; scene: LinkageScene; key: string } | null>(null);

  useEffect(() => {
    if (width > 0 && height > 0) onSize?.(width, height);
  }, [width, height, onSize]);

  useLayoutEffect(() => {
    const canvas = canvasRef.current;
    if (!canvas || width <= 0 || height <= 0) return;
    const dpr = Math.max(1, Math.min(4, window.devicePixelRatio || 1));
    const pw = Math.round(width * dpr);
    const ph = Math.round(height * dpr);
    if (canvas.width !== pw || canvas.height !== ph) {
      canvas.width = pw;
      canvas.height = ph;
    }
    const ctx = canvas.getContext('2d');
    if (!ctx) return;
    const transform = fitView(bounds, width, height, view);
    const back = backgroundFor(background.current, scene, transform, pw, ph, dpr);
    background.current = back;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(back.canvas, 0, 0);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    drawLinkageForeground(ctx, scene, transform, [canvasToolsRect(width)]);
    // Where the draggable joints are drawn (CSS pixels), for tests and tools that drive the canvas.
    const at = (p: { x: number; y: number } | undefined) =>
      p ? `${toScreenX(transform, p.x).toFixed(1)},${toScreenY(transform, p.y).toFixed(1)}` : '';
    canvas.dataset.o2 = at({ x: 0, y: 0 });
    canvas.dataset.a = at(scene.pose?.A);
    canvas.dataset.p = at(scene.pose?.P);
    benchMark('fourbar:canvas', { theta2Rad: scene.theta2 });
  }, [scene, bounds, view, width, height]);

  // A native listener: React's wheel listener is passive, and the page must not scroll while zooming.
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
  }, []);

  const transform = () => fitView(bounds, width, height, view);
  const at = (e: ReactPointerEvent<HTMLCanvasElement>): ScreenPoint => {
    const r = e.currentTarget.getBoundingClientRect();
    return { x: e.clientX - r.left, y: e.clientY - r.top };
  };
  const movable = { A: Boolean(onTheta2), P: Boolean(onCoupler) };
  // Drags commit synchronously: the pose under the finger is drawn in the same frame as the move.
  const dragTo = (kind: 'A' | 'P', p: ScreenPoint) => {
    if (kind === 'A') {
      const deg = crankAngleAt(transform(), p);
      if (deg !== null && onTheta2) flushSync(() => onTheta2(deg));
    } else {
      const c = couplerAt(scene, transform(), p);
      if (c && onCoupler) flushSync(() => onCoupler(c));
    }
  };
  const zoomBy = (f: number) => onViewChange(zoomAbout(view, f, width / 2, height / 2, width, height));
  const resetView = () => onViewChange({ zoom: 1, panX: 0, panY: 0 });
  const turnBy = (deltaDeg: number) => {
    if (!onTheta2) return;
    const next = wrapDeg360(Math.round((radToDeg360(scene.theta2) + deltaDeg) * 100) / 100);
    onTheta2(next);
  };

  return (
    <div className="canvas-wrap" ref={wrapRef}>
      <canvas
        ref={canvasRef}
        className="linkage-canvas"
        role="img"
        aria-label={`${t.canvasLabel}. ${description}`}
        aria-describedby={hintId}
        title={hint}
        aria-keyshortcuts={onTheta2 ? 'ArrowLeft ArrowRight + - 0' : '+ - 0'}
        tabIndex={0}
        onPointerDown={(e) => {
          if (e.pointerType === 'mouse' && e.button !== 0) return;
          e.currentTarget.setPointerCapture(e.pointerId);
          const p = at(e);
          pointers.current.set(e.pointerId, p);
          if (pointers.current.size >= 2) {
            // A second finger turns any drag into a pinch.
            const [[ia, a], [ib, b]] = [...pointers.current.entries()];
            gesture.current = { kind: 'pinch', ids: [ia, ib], from: [a, b], view };
            return;
          }
          const handle = hitHandle(scene, transform(), p, grabRadiusPx(e.pointerType), movable);
          gesture.current = handle
            ? { kind: handle, id: e.pointerId }
            : { kind: 'pan', id: e.pointerId, from: p, panX: view.panX, panY: view.panY };
          if (handle) setHeldBounds(scene.bounds);
        }}
        onPointerMove={(e) => {
          const p = at(e);
          const g = gesture.current;
          if (!g) {
            // Hovering: show that A and P can be grabbed.
            const over = hitHandle(scene, transform(), p, grabRadiusPx(e.pointerType), movable) !== null;
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
            if (width <= 0 || height <= 0) return;
            onViewChange({
              zoom: view.zoom,
              panX: g.panX + (p.x - g.from.x) / width,
              panY: g.panY + (p.y - g.from.y) / height,
            });
          } else {
            dragTo(g.kind, p);
          }
        }}
        onPointerUp={(e) => {
          pointers.current.delete(e.pointerId);
          gesture.current = null;
          setHeldBounds(null);
        }}
        onPointerCancel={(e) => {
          pointers.current.delete(e.pointerId);
          gesture.current = null;
          setHeldBounds(null);
        }}
        onDoubleClick={resetView}
        onKeyDown={(e) => {
          const step = e.shiftKey ? 10 * KEY_STEP_DEG : KEY_STEP_DEG;
          if (e.key === '+' || e.key === '=') zoomBy(1.25);
          else if (e.key === '-') zoomBy(0.8);
          else if (e.key === '0') resetView();
          else if (onTheta2 && (e.key === 'ArrowRight' || e.key === 'ArrowUp')) turnBy(step);
          else if (onTheta2 && (e.key === 'ArrowLeft' || e.key === 'ArrowDown')) turnBy(-step);
          else return;
          e.preventDefault();
        }}
      />
      <div className="canvas-tools">
        <button type="button" className="icon-btn" aria-label={t.zoomIn} title={t.zoomIn} onClick={() => zoomBy(1.25)}>
          <Icon name="plus" />
        </button>
        <button type="button" className="icon-btn" aria-label={t.zoomOut} title={t.zoomOut} onClick={() => zoomBy(0.8)}>
          <Icon name="minus" />
        </button>
        <button type="button" className="icon-btn" aria-label={t.resetView} title={t.resetView} onClick={resetView}>
          <Icon name="fit" />
        </button>
      </div>
      <p id={hintId} className="canvas-hint">
        {hint}
      </p>
      {scene.text.warning ? (
        <p className="sr-only" role="status">
          {scene.text.warning}
          {scene.text.warningDetail ? `. ${scene.text.warningDetail}` : ''}
        </p>
      ) : null}
    </div>
  );
}

/**
 * The linkage view: a canvas sized for devicePixelRatio that calls drawLinkage whenever the scene, size or
 * view changes. Drag the crank pin A to turn the crank and P to move the coupler point (mouse, pen or
 * touch); drag elsewhere to pan; wheel, pinch or the buttons zoom; double-click fits; arrow keys turn.
 */
export const LinkageCanvas = memo(LinkageCanvasImpl);
