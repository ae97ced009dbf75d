import '../../shared/print/PrintSheet.css';
import './PrintReport.css';
import { PrintFacts } from '../../shared/print/PrintFacts';
import type { ReportContent } from './reportContent';
import type { ReportMessages } from './reportMessages';

/** Props of PrintReport: what it shows and its strings. */
export interface PrintReportProps {
  content: ReportContent;
  m: ReportMessages;
}

/**
 * The printable report (with Forces on it runs onto a second page): one page with the title, the linkage figure and its lengths, the Grashof and type facts,
 * the design metrics, a table of the values at the current θ2 and the chosen plots; with Forces on, the forces'
 * numbers beside the chosen force plot. Hidden on screen (PrintReport.css);
 * the SVGs are the app's own drawings (the canvas's scene and the chart kit), set as markup.
 */
export function PrintReport({ content: c, m }: PrintReportProps) {
  return (
    <article
      className={c.forces.length > 0 ? 'print-sheet print-report print-sheet-long' : 'print-sheet print-report'}
      data-testid="print-report"
      aria-label={m.title}
    >
      <header className="report-head">
        <h1>{c.title}</h1>
        <p>{c.subtitle}</p>
      </header>
      <div className="report-top">
        <figure className="report-figure">
          <div className="report-svg" dangerouslySetInnerHTML={{ __html: c.figureSvg }} />
          <figcaption data-report="lengths">{c.figureCaption}</figcaption>
        </figure>
        <div className="report-side">
          <section>
            <h2>{m.classification}</h2>
            <PrintFacts facts={c.classification} />
          </section>
          <section>
            <h2>{c.atTheta2Title}</h2>
            <table className="report-table">
              <thead>
                <tr>
                  <th scope="col">{m.quantity}</th>
                  <th scope="col">{m.value}</th>
                </tr>
              </thead>
              <tbody>
                {c.atTheta2.map((f) => (
                  <tr key={f.key}>
                    <th scope="row">{f.label}</th>
                    <td data-report={f.key}>{f.value}</td>
                  </tr>
                ))}
              </tbody>
            </table>
          </section>
        </div>
      </div>
      <section>
        <h2>{m.setup}</h2>
        <PrintFacts facts={c.setup} />
      </section>
      <section>
        <h2>{m.metrics}</h2>
        <PrintFacts facts={c.metrics} />
      </section>
      {c.forces.length > 0 ? (
        <section>
          <h2>{m.forces}</h2>
          <div className={c.forcePlot ? 'report-forces' : undefined}>
            <PrintFacts facts={c.forces} />
            {c.forcePlot ? (
              <figure className="report-plot report-force-plot" data-report-plot={c.forcePlot.kind}>
                <div className="report-svg" dangerouslySetInnerHTML={{ __html: c.forcePlot.svg }} />
              </figure>
            ) : null}
          </div>
        </section>
      ) : null}
      <section>
        <h2>{m.plots}</h2>
        <div className={`report-plots report-plots-${c.plots.length}`}>
          {c.plots.map((p) => (
            <figure key={p.title} className="report-plot">
              <div className="report-svg" dangerouslySetInnerHTML={{ __html: p.svg }} />
            </figure>
          ))}
        </div>
      </section>
    </article>
  );
}
