import { useEffect, useLayoutEffect, useRef } from 'react';
import type { KeyboardEvent } from 'react';
import type { ViewOffset } from '../../shared/state/appState';
import type { Bounds, ViewTransform } from '../../shared/canvas/view';
import { fitView, toScreenX, toScreenY, toWorld } from '../../shared/canvas/view';
import type { ScreenPoint } from '../../shared/canvas/canvasGestures';
import { PanZoomCanvas } from '../../shared/canvas/PanZoomCanvas';
import { sizeCanvas } from '../../shared/canvas/sizeCanvas';
import { useFittedCanvas } from '../../shared/canvas/useFittedCanvas';
import type { MechPicture } from './drawMechanism';
import { drawMechanism } from './drawMechanism';
import type { Pt } from './mechPose';
import type { MechLiveStage } from './stage/mechLiveStage';

/** Grab radius of a joint, CSS pixels: a finger covers more than a mouse pointer. */
const GRAB_PX = { mouse: 14, touch: 26 };

/** Props of MechCanvas: the picture and the box it fits, and what a drag, a tap and the arrow keys do. */
export interface MechCanvasProps {
  picture: MechPicture;
  bounds: Bounds;
  label: string;
  labels: { zoomIn: string; zoomOut: string; resetView: string };
  /** A joint or tracer was taken (start) or let go (null). */
  onGrab: (id: string | null) => void;
  /** The taken joint follows the pointer to p (length unit, the view's world). */
  onDrag: (id: string, p: Pt) => void;
  /** A tap where nothing was taken (world point; snapped to the joint under it, if any, while a tool is armed). */
  onTap: (p: Pt) => void;
  /** A tool is armed: a press on a joint does not take it (the tap places the new part there). */
  placing: boolean;
  /** Arrow keys on the canvas: move the chosen joint by (dx, dy) CSS pixels' worth of length. */
  onNudge: (dx: number, dy: number) => void;
  /** Lets the page draw the same picture into an export: the view as on screen. */
  viewRef?: { current: { width: number; height: number; offset: ViewOffset } | null };
  /** The live stage, whose canvas lies over this one and is told where this one looks; default none. */
  live?: MechLiveStage | null;
  /** The live stage's canvas shows: this one keeps what it drew (no redraw per frame under it); default false. */
  hold?: boolean;
}

/**
 * The live stage's canvas over the mechanism canvas (pointer events go through to the one under it), shown while the
 * stage draws; handed to the stage (its worker) when it mounts.
 */
function LiveCanvas({ live, showing }: { live: MechLiveStage; showing: boolean }) {
  const ref = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    if (ref.current) live.attach(ref.current);
  }, [live]);
  return <canvas ref={ref} className="mech-live" aria-hidden="true" hidden={!showing} data-testid="mech-live" />;
}

/**
 * The linkage on a pan-and-zoom canvas (the canvas kit): a joint or a tracer under the pointer is dragged, else
 * the view pans; wheel and pinch zoom; the arrow keys move the chosen joint, + − 0 zoom.
 */
export function MechCanvas({
  picture,
  bounds,
  label,
  labels,
  onGrab,
  onDrag,
  onTap,
  onNudge,
  placing,
  viewRef,
  live = null,
  hold = false,
}: MechCanvasProps) {
  const nearest = (transform: ViewTransform, p: ScreenPoint, pointerType: string): string | null => {
    const r = pointerType === 'touch' || pointerType === 'pen' ? GRAB_PX.touch : GRAB_PX.mouse;
    let best: string | null = null;
    let bestD = r;
    const all: [string, Pt][] = [...Object.entries(picture.pose.points), ...Object.entries(picture.pose.joints)];
    for (const [id, q] of all) {
      const d = Math.hypot(toScreenX(transform, q.x) - p.x, toScreenY(transform, q.y) - p.y);
      if (d < bestD) {
        bestD = d;
        best = id;
      }
    }
    return best;
  };
  const fitted = useFittedCanvas<string>(bounds, (at) => ({
    grab: (p, pointerType) => (placing ? null : nearest(at(), p, pointerType)),
    onGrab,
    onDrag: (id, p) => onDrag(id, toWorld(at(), p.x, p.y)),
    onTap: (p) => {
      const id = placing ? nearest(at(), p, 'touch') : null;
      onTap(id ? (picture.pose.joints[id] ?? picture.pose.points[id]) : toWorld(at(), p.x, p.y));
    },
  }));
  const { frame, canvasRef, width, height, view } = fitted;
  const transform = fitted.transform();
  useLayoutEffect(() => {
    const canvas = canvasRef.current;
    if (viewRef) viewRef.current = { width, height, offset: view };
    live?.setView({ bounds, offset: view, width, height });
    if (hold) return;
    const sized = canvas && sizeCanvas(canvas, width, height);
    if (sized) drawMechanism(sized.ctx, picture, fitView(bounds, width, height, view));
  }, [canvasRef, picture, bounds, view, width, height, viewRef, live, hold]);
  const onKeyDown = (e: KeyboardEvent<HTMLCanvasElement>) => {
    const step = e.shiftKey ? 10 : 1;
    const d: Record<string, [number, number]> = {
      ArrowLeft: [-step, 0],
      ArrowRight: [step, 0],
      ArrowUp: [0, step],
      ArrowDown: [0, -step],
    };
    const move = d[e.key];
    if (move) {
      e.preventDefault();
      onNudge(move[0] / transform.scale, move[1] / transform.scale);
    }
  };
  return (
    <PanZoomCanvas
      frame={frame}
      wrapClassName="mech-canvas-wrap"
      canvas={{
        className: 'mech-canvas',
        role: 'img',
        'aria-label': label,
        'aria-keyshortcuts': 'ArrowLeft ArrowRight ArrowUp ArrowDown + - 0',
        'data-testid': 'mech-canvas',
        'data-view': `${transform.scale} ${transform.centerX} ${transform.centerY} ${transform.panXPx} ${transform.panYPx}`,
      }}
      onKeyDown={onKeyDown}
      zoomLabels={labels}
      overlay={live && <LiveCanvas live={live} showing={hold} />}
    />
  );
}
