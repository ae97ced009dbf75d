import { memo, useEffect, useEffectEvent, useLayoutEffect, useRef } from 'react';
import { drawLinkage } from '../render/drawLinkage';
import type { LinkageScene } from '../render/scene';
import { fitView, zoomAbout } from '../render/view';
import type { ViewOffset } from '../state/appState';
import { useMessages } from './MessagesContext';
import { Icon } from './Icon';
import { benchMark } from './benchMark';
import { useElementSize } from './useElementSize';

/** Props of LinkageCanvas: the scene to draw, the user's pan and zoom, and a size report for exports. */
export interface LinkageCanvasProps {
  scene: LinkageScene;
  view: ViewOffset;
  onViewChange: (view: ViewOffset) => void;
  /** Called with the canvas size in CSS pixels whenever it changes. */
  onSize?: (width: number, height: number) => void;
  /** Accessible description of the pose, e.g. the angles. */
  description: string;
}

function LinkageCanvasImpl({ scene, view, onViewChange, onSize, description }: LinkageCanvasProps) {
  const t = useMessages();
  const wrapRef = useRef<HTMLDivElement>(null);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const { width, height } = useElementSize(wrapRef);
  const drag = useRef<{ id: number; x: number; y: number; panX: number; panY: number } | null>(null);

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
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    drawLinkage(ctx, scene, fitView(scene.bounds, width, height, view));
    benchMark('fourbar:canvas', { theta2Rad: scene.theta2 });
  }, [scene, view, width, height]);

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

  const zoomBy = (f: number) => onViewChange(zoomAbout(view, f, width / 2, height / 2, width, height));

  return (
    <div className="canvas-wrap" ref={wrapRef}>
      <canvas
        ref={canvasRef}
        className="linkage-canvas"
        role="img"
        aria-label={`${t.canvasLabel}. ${description}`}
        tabIndex={0}
        onPointerDown={(e) => {
          if (e.button !== 0) return;
          e.currentTarget.setPointerCapture(e.pointerId);
          drag.current = { id: e.pointerId, x: e.clientX, y: e.clientY, panX: view.panX, panY: view.panY };
        }}
        onPointerMove={(e) => {
          const d = drag.current;
          if (!d || d.id !== e.pointerId || width <= 0 || height <= 0) return;
          onViewChange({
            zoom: view.zoom,
            panX: d.panX + (e.clientX - d.x) / width,
            panY: d.panY + (e.clientY - d.y) / height,
          });
        }}
        onPointerUp={() => {
          drag.current = null;
        }}
        onPointerCancel={() => {
          drag.current = null;
        }}
        onDoubleClick={() => onViewChange({ zoom: 1, panX: 0, panY: 0 })}
        onKeyDown={(e) => {
          if (e.key === '+' || e.key === '=') zoomBy(1.25);
          else if (e.key === '-') zoomBy(0.8);
          else if (e.key === '0') onViewChange({ zoom: 1, panX: 0, panY: 0 });
        }}
      />
      <div className="canvas-tools">
        <button type="button" className="icon-btn" aria-label={t.zoomIn} title={t.zoomIn} onClick={() => zoomBy(1.25)}>
          <Icon name="plus" />
        </button>
        <button type="button" className="icon-btn" aria-label={t.zoomOut} title={t.zoomOut} onClick={() => zoomBy(0.8)}>
          <Icon name="minus" />
        </button>
        <button
          type="button"
          className="icon-btn"
          aria-label={t.resetView}
          title={t.resetView}
          onClick={() => onViewChange({ zoom: 1, panX: 0, panY: 0 })}
        >
          <Icon name="fit" />
        </button>
      </div>
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
 * The linkage view: a canvas sized for devicePixelRatio (sharp on HiDPI screens) that calls drawLinkage
 * whenever the scene, size or view changes. Drag to pan, wheel or the buttons to zoom, double-click to fit.
 */
export const LinkageCanvas = memo(LinkageCanvasImpl);
