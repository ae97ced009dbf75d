import type { LabPoint, LabSeries } from '../../study/workPrecision';
import type { SweepMethod } from '../../solver/types';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { ColumnTable } from '../../shared/ui/ColumnTable';
import type { LabMessages } from './labMessages';
import { formatMaxError, shownTol } from './workPrecisionChart';

/** Props of LabTable: the study's series, the chosen method and tolerance, the lab's strings. */
export interface LabTableProps {
  series: readonly LabSeries[];
  method: SweepMethod;
  tol: number | null;
  lt: LabMessages;
}

/** The rows of one method: its default point, and the chosen tolerance's point when that method is chosen. */
function rowsOf(s: LabSeries, method: SweepMethod, tol: number | null): Array<{ p: LabPoint; chosen: boolean }> {
  const rows: Array<{ p: LabPoint; chosen: boolean }> = [];
  const d = s.points.find((p) => p.tol === null);
  if (d) rows.push({ p: d, chosen: s.method === method && tol === null });
  const chosenPoint = s.method === method && tol !== null ? s.points.find((p) => p.tol === tol) : undefined;
  if (chosenPoint) rows.push({ p: chosenPoint, chosen: true });
  return rows;
}

/** Per method: time and iterations per point, the max error, and the failed, wrong-branch and falsely converged counts. */
export function LabTable({ series, method, tol, lt }: LabTableProps) {
  const t = useMessages();
  const h = lt.labTableHeaders;
  return (
    <ColumnTable
      className="lab-table"
      columns={[h.method, h.nsPerPoint, h.itersPerPoint, h.maxError, h.failed, h.wrongBranch, h.falseConvergence]}
    >
      {series.flatMap((s) =>
        rowsOf(s, method, tol).map(({ p, chosen }) => (
          <tr key={`${s.method}-${p.tol}`} className={chosen ? 'chosen' : undefined}>
            <th scope="row">
              {t.methodNames[s.method]}
              {p.tol !== null ? `, tol ${shownTol(p.tol)}` : ''}
            </th>
            <td className="mono">{p.nsPerPoint.toFixed(0)}</td>
            <td className="mono">{p.itersPerPoint.toFixed(2)}</td>
            <td className="mono">{formatMaxError(p.maxError)}</td>
            <td className={`mono${p.failures ? ' bad' : ''}`}>{p.failures}</td>
            <td className={`mono${p.wrongBranch ? ' bad' : ''}`}>{p.wrongBranch}</td>
            <td className={`mono${p.falseConvergence ? ' bad' : ''}`}>{p.falseConvergence}</td>
          </tr>
        )),
      )}
    </ColumnTable>
  );
}
