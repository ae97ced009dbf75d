import type { ReportMessages } from './reportMessages';

/** Props of PrintReportButton: its strings and what a press does. */
export interface PrintReportButtonProps {
  m: ReportMessages;
  onPrint: () => void;
}

/** The "Print report" button with its note: the PDF comes from the browser's print dialog (no PDF library). */
export function PrintReportButton({ m, onPrint }: PrintReportButtonProps) {
  return (
    <div className="report-button">
      <button type="button" className="btn" onClick={onPrint}>
        {m.printReport}
      </button>
      <p className="note">{m.pdfNote}</p>
    </div>
  );
}
