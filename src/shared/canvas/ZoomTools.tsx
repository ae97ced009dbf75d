import { Icon } from '../ui/Icon';
import './ZoomTools.css';

/** Props of ZoomTools: the zoom actions (usePanZoom's) and the buttons' accessible names in the page's language. */
export interface ZoomToolsProps {
  zoomBy: (factor: number) => void;
  resetView: () => void;
  labels: { zoomIn: string; zoomOut: string; resetView: string };
}

/** The zoom in (×1.25), zoom out (×0.8) and fit buttons in the top right corner of every pan-and-zoom canvas. */
export function ZoomTools({ zoomBy, resetView, labels }: ZoomToolsProps) {
  const button = (label: string, icon: 'plus' | 'minus' | 'fit', onClick: () => void) => (
    <button type="button" className="icon-btn" aria-label={label} title={label} onClick={onClick}>
      <Icon name={icon} />
    </button>
  );
  return (
    <div className="canvas-tools">
      {button(labels.zoomIn, 'plus', () => zoomBy(1.25))}
      {button(labels.zoomOut, 'minus', () => zoomBy(0.8))}
      {button(labels.resetView, 'fit', resetView)}
    </div>
  );
}
