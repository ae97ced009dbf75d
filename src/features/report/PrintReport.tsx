import './PrintReport.css';
import type { ReportContent, ReportFact } from './reportContent';
import type { ReportMessages } from './reportMessages';

/** Props of PrintReport: what it shows and its strings. */
export interface PrintReportProps {
  content: ReportContent;
  m: ReportMessages;
}

function FactList({ facts }: { facts: readonly ReportFact[] }) {
  return (
    <dl className="report-facts">
      {facts.map((f) => (
        <div key={f.key} className={f.wide ? 'report-fact report-fact-wide' : 'report-fact'}>
          <dt>{f.label}</dt>
          <dd data-report={f.key}>{f.value}</dd>
        </div>
      ))}
    </dl>
  );
}

/**
 * The printable report (with Forces on it runs onto a second page): one page with the title, the linkage figure and its lengths, the Grashof and type facts,
 * the design metrics, a table of the values at the current θ2 and the chosen plots. Hidden on screen (PrintReport.css);
 * the SVGs are the app's own drawings (the canvas's scene and the chart kit), set as markup.
 */
export function PrintReport({ content: c, m }: PrintReportProps) {
  return (
    <article
      className={c.forces.length > 0 ? 'print-report print-report-long' : 'print-report'}
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
            <FactList facts={c.classification} />
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
        <FactList facts={c.setup} />
      </section>
      <section>
        <h2>{m.metrics}</h2>
        <FactList facts={c.metrics} />
      </section>
      {c.forces.length > 0 ? (
        <section>
          <h2>{m.forces}</h2>
          <FactList facts={c.forces} />
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
