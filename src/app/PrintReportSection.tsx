import { useCallback, useEffect, useState } from 'react';
import { flushSync, createPortal } from 'react-dom';
import { PrintReport } from '../features/report/PrintReport';
import { PrintReportButton } from '../features/report/PrintReportButton';
import type { ReportContent } from '../features/report/reportContent';
import { reportMessages } from '../features/report/reportMessages';
import { useLatest } from '../shared/hooks/useLatest';
import { PanelSection } from '../shared/ui/PanelSection';
import { onPrinting } from '../shared/print/usePrinting';
import type { ReportSources } from './reportContentOf';
import type { SimulatorSession } from './useSimulatorSession';

/** The report's builder (it draws with the exporters): loaded after the first load, not in it. */
let builder: ((sources: ReportSources) => ReportContent) | null = null;
const loadBuilder = () =>
  import('./reportContentOf').then((mod) => {
    builder = mod.reportContentOf;
  });

/** Milliseconds after mounting before the builder loads, so it stays out of the first load's work. */
const BUILDER_DELAY_MS = 3000;

/**
 * The report's section of the results column (the "Print report" button and its PDF note) and the report itself,
 * made when printing starts (Ctrl+P or the button: beforeprint; print media emulated: the print media query) from
 * the frame on screen, and set straight into the page's body (PrintReport.css shows only it in print).
 */
export function PrintReportSection({ session }: { session: SimulatorSession }) {
  const m = reportMessages(session.state.shell.locale);
  const [content, setContent] = useState<ReportContent | null>(null);
  const latest = useLatest(session);
  // Built in event handlers from the latest committed session, never during render; null until the builder loaded.
  const buildNow = useCallback((): ReportContent | null => {
    const s = latest.current;
    const frame = s.shown();
    if (!frame || !builder) return null;
    const m2 = reportMessages(s.state.shell.locale);
    return builder({ frame, cycle: s.cycle, design: s.design, deg: s.deg, point: s.point, t: s.t, m: m2 });
  }, [latest]);
  // Synchronous when the builder is in (Ctrl+P prints what beforeprint rendered), else as soon as it loads.
  const build = useCallback(() => {
    if (builder) flushSync(() => setContent(buildNow()));
    else void loadBuilder().then(() => setContent(buildNow()));
  }, [buildNow]);
  useEffect(() => {
    const id = window.setTimeout(() => void loadBuilder(), BUILDER_DELAY_MS);
    return () => window.clearTimeout(id);
  }, []);
  useEffect(() => onPrinting(build, () => setContent(null)), [build]);
  return (
    <PanelSection className="card" id="sec-report" title={m.section}>
      <PrintReportButton
        m={m}
        onPrint={() => {
          if (builder) {
            build();
            window.print();
          } else
            void loadBuilder().then(() => {
              build();
              window.print();
            });
        }}
      />
      {content ? createPortal(<PrintReport content={content} m={m} />, document.body) : null}
    </PanelSection>
  );
}
