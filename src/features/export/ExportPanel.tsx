import { memo, useState } from 'react';
import type { AnimationExportResult } from './animation/types';
import type { ExportSubject, PngSize } from '../../shared/fileNames';
import type { AnimationRequest } from './animationExporter';
import { AnimationExportControls } from './AnimationExportControls';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { PngSizeChoice } from '../../shared/ui/PngSizeChoice';

/** Props of ExportPanel: handlers that build and download each file; they reject with a reason on failure. */
export interface ExportPanelProps {
  onPng: (subject: ExportSubject, size: PngSize) => Promise<void>;
  onSvg: (subject: ExportSubject) => Promise<void>;
  onCsv: () => Promise<void>;
  onAnimation: (request: AnimationRequest) => Promise<AnimationExportResult>;
  /** Hide the size choice and offer fewer buttons (embed). */
  compact?: boolean;
  /** Why nothing can be exported now (a linkage that assembles nowhere): every button disabled, the reason shown. */
  blocked?: string | null;
}

function ExportPanelImpl({ onPng, onSvg, onCsv, onAnimation, compact = false, blocked = null }: ExportPanelProps) {
  const t = useMessages();
  const [size, setSize] = useState<PngSize>('2x');
  const [status, setStatus] = useState('');
  const run = (f: () => Promise<void>) => {
    setStatus('');
    f().catch((e: unknown) => setStatus(t.exportFailed(e instanceof Error ? e.message : String(e))));
  };
  const items: { subject: ExportSubject; label: string; svgLabel: string }[] = [
    { subject: 'linkage', label: t.exportLinkage, svgLabel: t.exportLinkageSvg },
    { subject: 'theta3', label: t.exportTheta3, svgLabel: t.exportTheta3Svg },
    { subject: 'theta4', label: t.exportTheta4, svgLabel: t.exportTheta4Svg },
    { subject: 'both', label: t.exportBoth, svgLabel: t.exportBothSvg },
    { subject: 'omega', label: t.exportOmega, svgLabel: t.exportOmegaSvg },
    { subject: 'alpha', label: t.exportAlpha, svgLabel: t.exportAlphaSvg },
    { subject: 'convergence', label: t.exportConvergence, svgLabel: t.exportConvergenceSvg },
  ];
  const shown = compact ? items.filter((i) => i.subject === 'linkage' || i.subject === 'both') : items;
  return (
    <div className="export-panel">
      <PngSizeChoice value={size} onChange={setSize} />
      <div className="export-buttons">
        {shown.map((i) => (
          <button
            key={i.subject}
            type="button"
            className="btn btn-small"
            disabled={blocked !== null}
            onClick={() => run(() => onPng(i.subject, size))}
          >
            {i.label}
          </button>
        ))}
        <button type="button" className="btn btn-small" disabled={blocked !== null} onClick={() => run(onCsv)}>
          {t.exportCsv}
        </button>
      </div>
      <div className="export-buttons">
        {shown.map((i) => (
          <button
            key={i.subject}
            type="button"
            className="btn btn-small"
            disabled={blocked !== null}
            onClick={() => run(() => onSvg(i.subject))}
          >
            {i.svgLabel}
          </button>
        ))}
      </div>
      <p className="status-line" role="status" aria-live="polite">
        {blocked ?? status}
      </p>
      <AnimationExportControls onAnimation={onAnimation} blocked={blocked !== null} />
    </div>
  );
}

/** Export buttons: PNG (at the chosen size) and SVG of the linkage view and each plot, the cycle as CSV, and the animation. */
export const ExportPanel = memo(ExportPanelImpl);
