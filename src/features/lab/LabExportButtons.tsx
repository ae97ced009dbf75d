import { PngSizeChoice } from '../../shared/ui/PngSizeChoice';
import { useMessages } from '../../shared/i18n/MessagesContext';
import type { LabMessages } from './labMessages';
import type { LabExports } from './useLabExports';

/** Props of LabExportButtons: the lab's exports, whether there is a study to export, the lab's strings. */
export interface LabExportButtonsProps {
  exports: LabExports;
  disabled: boolean;
  lt: LabMessages;
}

/** The diagram's PNG size, its PNG and SVG downloads, the study's CSV, and the last export failure. */
export function LabExportButtons({ exports, disabled, lt }: LabExportButtonsProps) {
  const t = useMessages();
  return (
    <div className="export-buttons lab-export">
      <PngSizeChoice value={exports.pngSize} onChange={exports.setPngSize} />
      <button type="button" className="btn btn-small" onClick={() => void exports.onPng()} disabled={disabled}>
        {lt.exportLabPng}
      </button>
      <button type="button" className="btn btn-small" onClick={exports.onSvg} disabled={disabled}>
        {t.exportLabSvg}
      </button>
      <button type="button" className="btn btn-small" onClick={exports.onCsv} disabled={disabled}>
        {lt.exportLabCsv}
      </button>
      <span className="status-line" role="status">
        {exports.status}
      </span>
    </div>
  );
}
