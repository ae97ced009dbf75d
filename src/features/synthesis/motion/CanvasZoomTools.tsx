import { Icon } from '../../../shared/ui/Icon';

/** Props of CanvasZoomTools: the zoom actions and their accessible names. */
export interface CanvasZoomToolsProps {
  zoomBy: (factor: number) => void;
  resetView: () => void;
  labels: { zoomIn: string; zoomOut: string; resetView: string };
}

/** The zoom in, zoom out and fit buttons over a synthesis canvas (the simulator's canvas-tools look). */
export function CanvasZoomTools({ zoomBy, resetView, labels }: CanvasZoomToolsProps) {
  return (
    <div className="synmode-canvas-tools">
      <button
        type="button"
        className="icon-btn"
        aria-label={labels.zoomIn}
        title={labels.zoomIn}
        onClick={() => zoomBy(1.25)}
      >
        <Icon name="plus" />
      </button>
      <button
        type="button"
        className="icon-btn"
        aria-label={labels.zoomOut}
        title={labels.zoomOut}
        onClick={() => zoomBy(0.8)}
      >
        <Icon name="minus" />
      </button>
      <button
        type="button"
        className="icon-btn"
        aria-label={labels.resetView}
        title={labels.resetView}
        onClick={resetView}
      >
        <Icon name="fit" />
      </button>
    </div>
  );
}
