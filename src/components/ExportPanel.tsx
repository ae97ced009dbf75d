import { memo, useState } from 'react';
import type { ExportSubject, PngSize } from '../state/fileNames';
import { useMessages } from './MessagesContext';
import { Segmented } from './Segmented';

/** Props of ExportPanel: handlers that build and download each file; they reject with a reason on failure. */
export interface ExportPanelProps {
  onPng: (subject: ExportSubject, size: PngSize) => Promise<void>;
  onCsv: () => Promise<void>;
  /** Hide the size choice and offer fewer buttons (embed). */
  compact?: boolean;
}

function ExportPanelImpl({ onPng, onCsv, compact = false }: ExportPanelProps) {
  const t = useMessages();
  const [size, setSize] = useState<PngSize>('2x');
  const [status, setStatus] = useState('');
  const run = (f: () => Promise<void>) => {
    setStatus('');
    f().catch((e: unknown) => setStatus(t.exportFailed(e instanceof Error ? e.message : String(e))));
  };
  const items: { subject: ExportSubject; label: string }[] = [
    { subject: 'linkage', label: t.exportLinkage },
    { subject: 'theta3', label: t.exportTheta3 },
    { subject: 'theta4', label: t.exportTheta4 },
    { subject: 'both', label: t.exportBoth },
    { subject: 'convergence', label: t.exportConvergence },
  ];
  const shown = compact ? items.filter((i) => i.subject === 'linkage' || i.subject === 'both') : items;
  return (
    <div className="export-panel">
      <Segmented<PngSize>
        legend={t.exportSize}
        value={size}
        options={[
          { value: 'screen', label: t.sizeScreen },
          { value: '2x', label: t.size2x },
          { value: 'print', label: t.sizePrint },
        ]}
        onChange={setSize}
      />
      <div className="export-buttons">
        {shown.map((i) => (
          <button
            key={i.subject}
            type="button"
            className="btn btn-small"
            onClick={() => run(() => onPng(i.subject, size))}
          >
            {i.label}
          </button>
        ))}
        <button type="button" className="btn btn-small" onClick={() => run(onCsv)}>
          {t.exportCsv}
        </button>
      </div>
      <p className="status-line" role="status" aria-live="polite">
        {status}
      </p>
    </div>
  );
}

/** Export buttons: PNG of the linkage view and of each plot at the chosen size, and the cycle as CSV. */
export const ExportPanel = memo(ExportPanelImpl);
