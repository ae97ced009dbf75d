import { radToDeg } from '../../../solver';
import { formatDeg, formatNumber, formatSci } from '../../../shared/format';
import type { FunctionMessages } from './functionMessages';
import type { FunctionDesign } from './functionSolve';

/** The precision points (精確點): x, the angles they prescribe and the structural error there (≈ 0 for three). */
export function PrecisionTable({ fd, fm }: { fd: FunctionDesign; fm: FunctionMessages }) {
  return (
    <table className="synmode-table" data-testid="precision-table">
      <caption className="sr-only">{fm.precisionCaption}</caption>
      <thead>
        <tr>
          <th scope="col">{fm.columnX}</th>
          <th scope="col">{fm.columnTheta2}</th>
          <th scope="col">{fm.columnTheta4}</th>
          <th scope="col">{fm.columnError}</th>
        </tr>
      </thead>
      <tbody>
        {fd.precision.map((p, i) => (
          <tr key={i} data-x={p.x} data-error={p.error}>
            <td>{formatNumber(p.x, 6)}</td>
            <td>{formatDeg(radToDeg(p.theta2), 3)}</td>
            <td>{formatDeg(radToDeg(p.theta4), 3)}</td>
            <td>{formatSci(p.error, 2)}</td>
          </tr>
        ))}
      </tbody>
    </table>
  );
}
