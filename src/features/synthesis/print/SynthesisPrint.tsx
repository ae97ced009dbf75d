import '../../../shared/print/PrintSheet.css';
import './SynthesisPrint.css';
import { createPortal } from 'react-dom';
import { PrintFacts } from '../../../shared/print/PrintFacts';
import { usePrinting } from '../../../shared/print/usePrinting';
import type { SynthesisPrintMessages } from '../synthesisMessages';
import type { PrintTable, SynthesisPrintContent } from './synthesisPrint';

/** Rows of a printed table's part: a long list of targets is set in side-by-side parts. */
const ROWS_PER_PART = 14;

/** Props of SynthesisPrint: how to make the content (called only while printing) and the strings. */
export interface SynthesisPrintProps {
  build: () => SynthesisPrintContent;
  m: SynthesisPrintMessages;
}

function Table({ table }: { table: PrintTable }) {
  const parts: PrintTable['rows'][] = [];
  for (let i = 0; i < table.rows.length; i += ROWS_PER_PART) parts.push(table.rows.slice(i, i + ROWS_PER_PART));
  return (
    <div className={`syn-print-tables syn-print-tables-${Math.min(parts.length, 3)}`}>
      {parts.map((rows, k) => (
        <table key={k} className="report-table" data-print-table>
          {k === 0 ? <caption className="sr-only">{table.caption}</caption> : null}
          <thead>
            <tr>
              {table.columns.map((c) => (
                <th key={c} scope="col">
                  {c}
                </th>
              ))}
            </tr>
          </thead>
          <tbody>
            {rows.map((r) => (
              <tr key={r.key} data-print-row={r.key}>
                <th scope="row">{r.cells[0]}</th>
                {r.cells.slice(1).map((c, i) => (
                  <td key={i}>{c}</td>
                ))}
              </tr>
            ))}
          </tbody>
        </table>
      ))}
    </div>
  );
}

/**
 * The synthesis page's print view: while the page prints (Ctrl+P, the Print button, print media), one sheet set
 * into the page's body, the only thing printed (shared/print/PrintSheet.css): the mode's task, the chosen design
 * with its lengths and unit, coupler point, placement, defects and error at each target or pose, and the canvas's
 * picture. No buttons, fields or candidate list.
 */
export function SynthesisPrint({ build, m }: SynthesisPrintProps) {
  const printing = usePrinting();
  if (!printing) return null;
  const c = build();
  return createPortal(
    <article className="print-sheet syn-print" data-testid="synthesis-print" aria-label={c.title}>
      <header className="report-head">
        <h1>{c.title}</h1>
        {c.note ? <p data-print="note">{c.note}</p> : null}
      </header>
      <div className="syn-print-top">
        {c.figureSvg ? (
          <figure className="syn-print-figure" aria-label={m.figure}>
            <div className="report-svg" dangerouslySetInnerHTML={{ __html: c.figureSvg }} />
          </figure>
        ) : null}
        <section>
          <h2>{m.task}</h2>
          <PrintFacts facts={c.task} attr="data-print" />
        </section>
      </div>
      {c.design.length > 0 ? (
        <section>
          <h2>{m.result}</h2>
          <PrintFacts facts={c.design} attr="data-print" />
          <h3 className="syn-print-sub">{m.defects}</h3>
          <ul className="syn-print-defects" data-print="defects">
            {c.defects.map((d) => (
              <li key={d}>{d}</li>
            ))}
          </ul>
        </section>
      ) : null}
      {c.table ? (
        <section>
          <h2>{c.table.caption}</h2>
          <Table table={c.table} />
        </section>
      ) : null}
    </article>,
    document.body,
  );
}
