import './LinkageCanvas.css';
import { memo, useEffect, useRef, useState } from 'react';
import type { RefObject } from 'react';
import { flushSync } from 'react-dom';
import { useTheta2Scrub } from './theta2Scrub';
import { radToDeg360, wrapDeg360 } from '../../solver/angles';
import type { LinkageScene } from '../../shared/linkage/scene';
import type { Bounds } from '../../shared/canvas/view';
import { fitScene } from '../../shared/linkage/scene';
import type { CouplerPoint, ViewOffset } from '../../shared/state/appState';
import type { ScreenPoint } from '../../shared/canvas/canvasGestures';
import { couplerAt, crankAngleAt, grabRadiusPx, hitHandle } from '../../shared/canvas/canvasGestures';
import { usePanZoom } from '../../shared/canvas/usePanZoom';
import { PanZoomCanvas } from '../../shared/canvas/PanZoomCanvas';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { useElementSize } from '../../shared/hooks/useElementSize';
import { useLinkageDrawing } from './useLinkageDrawing';
import type { LiveStage } from '../../shared/linkage/liveStage';
import { useStageShowing } from './useStageShowing';

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
  /** The live stage: its canvas lies over this one and shows while it draws Play (LiveStage). */
  stage?: LiveStage | null;
}

/** Degrees the arrow keys turn the crank (with Shift: ten times as far). */
const KEY_STEP_DEG = 1;

/** The crank turn (degrees) an arrow key asks for, ten times as far with Shift; null for any other key. */
function keyTurnDeg(e: { key: string; shiftKey: boolean }): number | null {
  const step = e.shiftKey ? 10 * KEY_STEP_DEG : KEY_STEP_DEG;
  if (e.key === 'ArrowRight' || e.key === 'ArrowUp') return step;
  if (e.key === 'ArrowLeft' || e.key === 'ArrowDown') return -step;
  return null;
}

/**
 * Pan and zoom of the canvas with grab-and-drag of the crank pin A and the coupler point P; returns the bounds to
 * fit (held while a handle is dragged) with usePanZoom's handlers.
 */
function useCanvasHandles(
  { scene, view, onViewChange, onTheta2, onCoupler }: LinkageCanvasProps,
  canvasRef: RefObject<HTMLCanvasElement | null>,
  width: number,
  height: number,
) {
  // While A or P is dragged the fit stays put: a new cycle (P moved) would otherwise rescale the view under
  // the pointer and the joint would drift away from it.
  const [heldBounds, setHeldBounds] = useState<Bounds | null>(null);
  const bounds = heldBounds ?? scene.bounds;
  const transform = () => fitScene(scene, bounds, width, height, view);
  const movable = { A: Boolean(onTheta2), P: Boolean(onCoupler) };
  // The crank moves the playhead (the θ2 drag, which stops Play) where a simulator provides one, else it commits.
  // Either way the pose under the finger is drawn in the same frame as the move.
  const scrub = useTheta2Scrub();
  const dragTo = (kind: 'A' | 'P', p: ScreenPoint) => {
    if (kind === 'A') {
      const deg = crankAngleAt(transform(), p);
      if (deg === null || !onTheta2) return;
      if (scrub) scrub.move(deg, true);
      else flushSync(() => onTheta2(deg));
    } else {
      const c = couplerAt(scene, transform(), p);
      if (c && onCoupler) flushSync(() => onCoupler(c));
    }
  };
  const panZoom = usePanZoom<'A' | 'P'>({
    canvasRef,
    view,
    onViewChange,
    width,
    height,
    grab: (p, pointerType) => hitHandle(scene, transform(), p, grabRadiusPx(pointerType), movable),
    onDrag: dragTo,
    // While A or P is dragged the fit holds (see heldBounds).
    onGrab: (handle) => {
      setHeldBounds(handle ? scene.bounds : null);
      if (!handle) scrub?.end();
    },
  });
  return { bounds, panZoom };
}

/**
 * The live stage's canvas over the linkage canvas (pointer events go through to the one under it): shown while the
 * stage draws Play; handed to the stage's worker when Play first starts.
 */
function StageCanvas({ stage, width, height }: { stage: LiveStage; width: number; height: number }) {
  const showing = useStageShowing(stage);
  const ref = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    if (ref.current) stage.attach(ref.current);
  }, [stage]);
  useEffect(() => {
    if (width > 0 && height > 0) stage.setSize(width, height);
  }, [stage, width, height]);
  return <canvas ref={ref} className="linkage-live" aria-hidden="true" hidden={!showing} />;
}

function LinkageCanvasImpl(props: LinkageCanvasProps) {
  const { scene, view, onTheta2, onSize, description, hint, stage } = props;
  const t = useMessages();
  const wrapRef = useRef<HTMLDivElement>(null);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const { width, height } = useElementSize(wrapRef);
  useEffect(() => {
    if (width > 0 && height > 0) onSize?.(width, height);
  }, [width, height, onSize]);
  const { bounds, panZoom } = useCanvasHandles(props, canvasRef, width, height);
  const covered = useStageShowing(stage);
  useLinkageDrawing(canvasRef, scene, bounds, view, width, height, stage?.notePageDraw, covered);
  const turnBy = (deltaDeg: number) => {
    if (!onTheta2) return;
    const next = wrapDeg360(Math.round((radToDeg360(scene.theta2) + deltaDeg) * 100) / 100);
    onTheta2(next);
  };

  return (
    <PanZoomCanvas
      frame={{ wrapRef, canvasRef, panZoom }}
      wrapClassName="canvas-wrap"
      canvas={{
        className: 'linkage-canvas',
        role: 'img',
        'aria-label': `${t.canvasLabel}. ${description}`,
        'aria-keyshortcuts': onTheta2 ? 'ArrowLeft ArrowRight + - 0' : '+ - 0',
      }}
      onKeyDown={(e) => {
        const turn = keyTurnDeg(e);
        if (!onTheta2 || turn === null) return;
        turnBy(turn);
        e.preventDefault();
      }}
      zoomLabels={t}
      hint={hint}
      overlay={stage ? <StageCanvas stage={stage} width={width} height={height} /> : null}
    >
      {scene.text.warning ? (
        <p className="sr-only" role="status">
          {scene.text.warning}
          {scene.text.warningDetail ? `. ${scene.text.warningDetail}` : ''}
        </p>
      ) : null}
    </PanZoomCanvas>
  );
}

/**
 * The linkage view: a canvas sized for devicePixelRatio that calls drawLinkage whenever the scene, size or
 * view changes. Drag the crank pin A to turn the crank and P to move the coupler point (mouse, pen or
 * touch); drag elsewhere to pan; wheel, pinch or the buttons zoom; double-click fits; arrow keys turn.
 */
export const LinkageCanvas = memo(LinkageCanvasImpl);
