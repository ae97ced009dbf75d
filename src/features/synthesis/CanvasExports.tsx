import type { DrawPicture } from '../../shared/canvas/exportDrawing';
import { exportDrawingPng, exportDrawingSvg } from '../../shared/canvas/exportDrawing';
import { useMessages } from '../../shared/i18n/MessagesContext';

/** Props of CanvasExports: the drawing as on screen (CSS pixels), its size and the file name without extension. */
export interface CanvasExportsProps {
  draw: DrawPicture;
  width: number;
  height: number;
  fileBase: string;
}

/** "Export SVG" and "Export PNG" of a synthesis canvas: the same drawing, into an SVG or a 2x canvas. */
export function CanvasExports({ draw, width, height, fileBase }: CanvasExportsProps) {
  const t = useMessages();
  const ready = width > 0 && height > 0;
  return (
    <div className="synmode-exports">
      <button
        type="button"
        className="btn btn-small"
        disabled={!ready}
        onClick={() => exportDrawingSvg(draw, width, height, fileBase)}
      >
        {t.exportPictureSvg}
      </button>
      <button
        type="button"
        className="btn btn-small"
        disabled={!ready}
        onClick={() => void exportDrawingPng(draw, width, height, fileBase)}
      >
        {t.exportPicturePng}
      </button>
    </div>
  );
}
