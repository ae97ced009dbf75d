import { useLayoutEffect, useRef, useState } from 'react';
import type { RefObject } from 'react';
import type { Point } from '../../../solver/kinematics';
import type { PlacedFourBar, PlacedJoints } from '../../../synthesis/types';
import type { DrawContext } from '../../../shared/canvas/drawContext';
import { placedJoints } from '../../../synthesis/placed';
import type { ScreenPoint } from '../../../shared/canvas/canvasGestures';
import { grabRadiusPx } from '../../../shared/canvas/canvasGestures';
import { useFittedCanvas } from '../../../shared/canvas/useFittedCanvas';
import { PanZoomCanvas } from '../../../shared/canvas/PanZoomCanvas';
import type { Bounds, ViewTransform } from '../../../shared/canvas/view';
import { gridLines, niceStep, toScreenX, toScreenY, toWorld } from '../../../shared/canvas/view';
import { formatNumber } from '../../../shared/format';
import { useAnimationFrame } from '../../../shared/hooks/useAnimationFrame';
import type { ViewOffset } from '../../../shared/state/appState';
import type { SynthesisMessages } from '../synthesisMessages';
import type { MotionRange } from './candidateFacts';
import { theta2AtPhase } from './candidateFacts';
import type { PathCurve, PathScene } from './drawPathScene';
import { drawPathScene } from './drawPathScene';
import { sizeCanvas } from '../../../shared/canvas/sizeCanvas';

/** Props of TargetCanvas: the targets and the selection, what else to draw, the view, and the edits. */
export interface TargetCanvasProps {
  targets: readonly Point[];
  selected: number | null;
  curves: readonly PathCurve[];
  /** The linkage to animate through its motion, or null. */
  moving: { design: PlacedFourBar; motion: MotionRange } | null;
  /** Draws more with the moving linkage at each frame (its pose given), e.g. its cognates. */
  drawMoving?: (ctx: DrawContext, v: ViewTransform, pose: PlacedJoints) => void;
  bounds: Bounds;
  view: ViewOffset;
  onViewChange: (view: ViewOffset) => void;
  onSelect: (index: number | null) => void;
  onMove: (index: number, p: Point) => void;
  onAdd: (p: Point) => void;
  onRemove: (index: number) => void;
  /** The canvas element, for the exports (its size in CSS pixels). */
  canvasRef: RefObject<HTMLCanvasElement | null>;
  st: SynthesisMessages;
}

/** Seconds one cycle of the animation takes. */
const CYCLE_SECONDS = 4;

/** x rounded to a tenth of the grid step at this zoom (so a click gives 1.3, not 1.2999871), without float dust. */
function snap(x: number, step: number): number {
  return Number((Math.round(x / step) * step).toPrecision(12));
}

/** The target under a pointer at p (CSS pixels), the nearest within the grab radius, or null. */
function targetAt(targets: readonly Point[], v: ViewTransform, p: ScreenPoint, radius: number): number | null {
  let best: number | null = null;
  let bestD = radius;
  targets.forEach((t, i) => {
    const d = Math.hypot(toScreenX(v, t.x) - p.x, toScreenY(v, t.y) - p.y);
    if (d <= bestD) {
      best = i;
      bestD = d;
    }
  });
  return best;
}

/** The world point under p, snapped to a tenth of the grid step. */
function worldAt(v: ViewTransform, p: ScreenPoint): Point {
  const w = toWorld(v, p.x, p.y);
  const step = niceStep(v.scale) / 10;
  return { x: snap(w.x, step), y: snap(w.y, step) };
}

/** One grid step of the view (length unit): the spacing drawGrid draws at (about 64 px). */
export function gridStep(v: ViewTransform): number {
  return gridLines(v)?.step ?? niceStep(v.scale, 64);
}

/** Arrow keys move the selected target by a tenth of the grid step (Shift: a whole step); null for other keys. */
function keyMove(e: { key: string; shiftKey: boolean }): [number, number] | null {
  const k = e.shiftKey ? 10 : 1;
  if (e.key === 'ArrowRight') return [k, 0];
  if (e.key === 'ArrowLeft') return [-k, 0];
  if (e.key === 'ArrowUp') return [0, k];
  if (e.key === 'ArrowDown') return [0, -k];
  return null;
}

/**
 * The Path mode's canvas: the targets on a pan-and-zoom plane (click or tap adds one, drag moves one, Delete or
 * Backspace removes the selected one, arrow keys move it) with the chosen linkage moving through its cycle. The
 * canvas's data-view holds the transform (scale, centre, pan, size) so tests can find a world point's pixel. A
 * corner reads the grid's step (the scale) and, under a mouse, the point it points at (as a click would add it).
 */
export function TargetCanvas(props: TargetCanvasProps) {
  const { targets, selected, curves, moving, bounds, view, onViewChange, canvasRef, st } = props;
  const phase = useRef(0);
  const [cursor, setCursor] = useState<Point | null>(null);
  const { frame, width, height, transform } = useFittedCanvas<number>(
    bounds,
    (at) => ({
      grab: (p, pointerType) => targetAt(targets, at(), p, grabRadiusPx(pointerType)),
      onGrab: (i) => {
        if (i !== null) props.onSelect(i);
      },
      onDrag: (i, p) => props.onMove(i, worldAt(at(), p)),
      onTap: (p) => {
        props.onAdd(worldAt(at(), p));
      },
    }),
    { canvasRef, view, onViewChange },
  );

  const names = targets.map((_, i) => st.targetName(i + 1));
  const draw = () => {
    const canvas = canvasRef.current;
    const sized = canvas && sizeCanvas(canvas, width, height);
    if (!sized) return;
    const ctx = sized.ctx;
    const v = transform();
    const pose = moving ? placedJoints(moving.design, theta2AtPhase(moving.motion, phase.current)) : null;
    const scene: PathScene = { targets, selected, names, curves, pose };
    drawPathScene(ctx, scene, v);
    if (pose && props.drawMoving) props.drawMoving(ctx, v, pose);
    canvas.dataset.view = JSON.stringify({
      scale: v.scale,
      centerX: v.centerX,
      centerY: v.centerY,
      panXPx: v.panXPx,
      panYPx: v.panYPx,
      width: v.width,
      height: v.height,
    });
  };
  useLayoutEffect(draw);
  useAnimationFrame(moving !== null, (dt) => {
    phase.current = (phase.current + dt / CYCLE_SECONDS) % 1;
    draw();
  });

  return (
    <PanZoomCanvas
      frame={frame}
      wrapClassName="syn-canvas-wrap"
      canvas={{
        className: 'syn-canvas',
        role: 'application',
        'aria-label': `${st.canvasLabel}: ${targets.length}`,
        'aria-keyshortcuts': 'Delete Backspace ArrowLeft ArrowRight ArrowUp ArrowDown + - 0',
        'data-testid': 'synthesis-canvas',
        'data-targets': targets.length,
      }}
      onKeyDown={(e) => {
        if ((e.key === 'Delete' || e.key === 'Backspace') && selected !== null) {
          props.onRemove(selected);
          e.preventDefault();
          return;
        }
        const move = keyMove(e);
        if (move && selected !== null && targets[selected]) {
          const step = niceStep(transform().scale) / 10;
          const t = targets[selected];
          props.onMove(selected, { x: snap(t.x + move[0] * step, step), y: snap(t.y + move[1] * step, step) });
          e.preventDefault();
        }
      }}
      onPointerMove={(e) => {
        if (e.pointerType !== 'mouse') return;
        const r = e.currentTarget.getBoundingClientRect();
        setCursor(worldAt(transform(), { x: e.clientX - r.left, y: e.clientY - r.top }));
      }}
      onPointerLeave={() => setCursor(null)}
      zoomLabels={st}
      hint={st.canvasHint}
      overlay={<CanvasReadout step={width > 0 && height > 0 ? gridStep(transform()) : null} cursor={cursor} st={st} />}
      beforeHint={targets.length === 0 ? <p className="syn-canvas-empty">{st.canvasEmpty}</p> : null}
    />
  );
}

/** The canvas's corner: the grid step, and the point under the mouse (both in the length unit; noise shown as 0). */
function CanvasReadout({ step, cursor, st }: { step: number | null; cursor: Point | null; st: SynthesisMessages }) {
  if (step === null) return null;
  const n = (x: number) => formatNumber(x, 6, step);
  return (
    <p className="syn-canvas-readout" data-testid="canvas-readout">
      <span>{st.gridScale(n(step))}</span>
      {cursor ? <span> · {st.cursorAt(n(cursor.x), n(cursor.y))}</span> : null}
    </p>
  );
}
