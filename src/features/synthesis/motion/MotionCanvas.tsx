import { useLayoutEffect, useState } from 'react';
import type { KeyboardEvent } from 'react';
import { flushSync } from 'react-dom';
import { radToDeg } from '../../../solver';
import type { Point } from '../../../solver';
import type { Bounds } from '../../../shared/canvas/view';
import { fitView, toScreenX, toScreenY, toWorld } from '../../../shared/canvas/view';
import { grabRadiusPx } from '../../../shared/canvas/canvasGestures';
import { useFittedCanvas } from '../../../shared/canvas/useFittedCanvas';
import type { PoseDeg } from '../../../shared/state/slices/synMotionSlice';
import type { MotionHandle, MotionPicture } from './motionPicture';
import { drawMotion, handleAt, motionBounds, turnHandlePx } from './motionPicture';
import { PanZoomCanvas } from '../../../shared/canvas/PanZoomCanvas';
import { sizeCanvas } from '../../../shared/canvas/sizeCanvas';
import { CanvasExports } from '../CanvasExports';

/** Props of MotionCanvas: the picture, what dragging, typing and tapping change, and the texts. */
export interface MotionCanvasProps {
  picture: MotionPicture;
  onPose: (index: number, pose: PoseDeg) => void;
  /** A placed pivot (three poses) dragged to a point of the plane. */
  onPivot: (index: 0 | 1, at: Point) => void;
  onSelect: (index: number) => void;
  /** A tap where nothing was grabbed: the point (world) and the world length of a fingertip there. */
  onTap: (at: Point, reach: number) => void;
  labels: { canvas: string; hint: string; selected: string; zoomIn: string; zoomOut: string; resetView: string };
}

/** A length rounded to the pixel grid of the view (1 px or finer, a power of ten), so drags leave short numbers. */
export function roundToPixel(v: number, scale: number): number {
  const step = 10 ** Math.floor(Math.log10(1 / scale));
  const r = Math.round(v / step) * step;
  // Through the decimal text, so 0.30000000000000004 reads 0.3.
  return Number(r.toPrecision(12));
}

/** An angle in degrees rounded to 0.1°. */
const roundDeg = (deg: number) => Math.round(deg * 10) / 10;

/** What a key does to the selected pose: a move (CSS pixels, y up) or a turn (degrees); null for other keys. */
export function poseKey(e: {
  key: string;
  shiftKey: boolean;
}): { dx: number; dy: number } | { turnDeg: number } | null {
  const step = e.shiftKey ? 1 : 10;
  switch (e.key) {
    case 'ArrowLeft':
      return { dx: -step, dy: 0 };
    case 'ArrowRight':
      return { dx: step, dy: 0 };
    case 'ArrowUp':
      return { dx: 0, dy: step };
    case 'ArrowDown':
      return { dx: 0, dy: -step };
    case '[':
      return { turnDeg: e.shiftKey ? 1 : 5 };
    case ']':
      return { turnDeg: e.shiftKey ? -1 : -5 };
    default:
      return null;
  }
}

/** The new pose when a handle is dragged to a world point (rounded to the pixel grid and to 0.1°). */
function draggedPose(pose: PoseDeg, handle: MotionHandle, at: Point, scale: number): PoseDeg {
  if (handle.kind === 'turn') {
    return { ...pose, angleDeg: roundDeg(radToDeg(Math.atan2(at.y - pose.y, at.x - pose.x))) };
  }
  return { ...pose, x: roundToPixel(at.x, scale), y: roundToPixel(at.y, scale) };
}

/** Pointer, wheel and key handling of the Motion canvas; the fit holds while a handle is dragged. */
function useMotionGestures(props: MotionCanvasProps) {
  const { picture, onPose, onPivot, onSelect, onTap } = props;
  const [heldBounds, setHeldBounds] = useState<Bounds | null>(null);
  const bounds = heldBounds ?? motionBounds(picture);
  const fitted = useFittedCanvas<MotionHandle>(bounds, (transform) => ({
    grab: (p, pointerType) => handleAt(picture, transform(), p, grabRadiusPx(pointerType)),
    onDrag: (handle, p) => {
      const v = transform();
      const at = toWorld(v, p.x, p.y);
      // Drags commit synchronously: the pose under the finger is drawn in the same frame as the move.
      if (handle.kind === 'pivot') {
        flushSync(() => onPivot(handle.index, { x: roundToPixel(at.x, v.scale), y: roundToPixel(at.y, v.scale) }));
      } else {
        const pose = picture.poses[handle.index];
        const deg = { x: pose.x, y: pose.y, angleDeg: radToDeg(pose.angle) };
        flushSync(() => onPose(handle.index, draggedPose(deg, handle, at, v.scale)));
      }
    },
    onGrab: (handle) => {
      setHeldBounds(handle ? motionBounds(picture) : null);
      if (handle && handle.kind !== 'pivot') onSelect(handle.index);
    },
    onTap: (p) => {
      const v = transform();
      onTap(toWorld(v, p.x, p.y), 20 / v.scale);
    },
  }));
  const transform = fitted.transform;
  const onKeyDown = (e: KeyboardEvent<HTMLCanvasElement>) => {
    const n = Number(e.key);
    if (Number.isInteger(n) && n >= 1 && n <= picture.poses.length) {
      onSelect(n - 1);
      return e.preventDefault();
    }
    const k = poseKey(e);
    const pose = picture.poses[picture.selected];
    if (!k || !pose) return;
    e.preventDefault();
    const v = transform();
    const deg = radToDeg(pose.angle);
    if ('turnDeg' in k) onPose(picture.selected, { x: pose.x, y: pose.y, angleDeg: roundDeg(deg + k.turnDeg) });
    else {
      const x = roundToPixel(pose.x + k.dx / v.scale, v.scale);
      const y = roundToPixel(pose.y + k.dy / v.scale, v.scale);
      onPose(picture.selected, { x, y, angleDeg: deg });
    }
  };
  return { ...fitted, bounds, onKeyDown };
}

/**
 * The Motion mode's canvas: poses as points with turning handles (mouse, pen or touch; keys 1–9, arrows, [ ]),
 * the method's construction and the linkage, pan and zoom (usePanZoom). data-poses gives each pose's point and
 * handle in CSS pixels, for tests that drag them as a person would.
 */
export function MotionCanvas(props: MotionCanvasProps) {
  const { picture, labels } = props;
  const { frame, canvasRef, width, height, view, bounds, onKeyDown } = useMotionGestures(props);
  useLayoutEffect(() => {
    const canvas = canvasRef.current;
    const sized = canvas && sizeCanvas(canvas, width, height);
    if (!canvas || !sized) return;
    const v = fitView(bounds, width, height, view);
    drawMotion(sized.ctx, picture, v);
    const at = (x: number, y: number) => `${x.toFixed(1)},${y.toFixed(1)}`;
    canvas.dataset.poses = picture.poses
      .map((p) => {
        const h = turnHandlePx(v, p);
        return `${at(toScreenX(v, p.x), toScreenY(v, p.y))},${at(h.x, h.y)}`;
      })
      .join(';');
    // Where the curve slider's dyad is drawn (four poses), for tests that click the curve.
    const c = picture.cursor?.center;
    if (c) canvas.dataset.cursor = at(toScreenX(v, c.x), toScreenY(v, c.y));
    else delete canvas.dataset.cursor;
  }, [canvasRef, picture, bounds, view, width, height]);

  return (
    <PanZoomCanvas
      frame={frame}
      wrapClassName="syn-canvas-wrap"
      canvas={{
        className: 'synmode-canvas',
        role: 'img',
        'aria-label': `${labels.canvas}. ${labels.selected}`,
        'aria-keyshortcuts': '1 2 3 4 5 6 7 8 9 ArrowLeft ArrowRight ArrowUp ArrowDown [ ] + - 0',
        'data-testid': 'motion-canvas',
      }}
      onKeyDown={onKeyDown}
      zoomLabels={labels}
      hint={labels.hint}
    >
      <CanvasExports
        draw={(ctx) => drawMotion(ctx, picture, fitView(bounds, width, height, view))}
        width={width}
        height={height}
        fileBase="synthesis-motion"
      />
    </PanZoomCanvas>
  );
}
