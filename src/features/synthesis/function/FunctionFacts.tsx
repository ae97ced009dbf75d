import type { Messages } from '../../../shared/i18n/messages';
import { formatNumber } from '../../../shared/format';
import type { FunctionMessages } from './functionMessages';
import type { FunctionDesign } from './functionSolve';

/** Props of FunctionFacts: the design and the texts. */
export interface FunctionFactsProps {
  fd: FunctionDesign;
  fm: FunctionMessages;
  t: Messages;
}

/** The design's lengths, type, branch, largest error and defects in words. */
export function FunctionFacts({ fd, fm, t }: FunctionFactsProps) {
  const { links, branch, maxError, defects } = fd.result;
  const f = (v: number) => formatNumber(v, 5);
  const percent = (100 * maxError) / Math.abs(fd.y1 - fd.y0);
  return (
    <div className="synmode-facts" data-testid="function-facts">
      <p className="synmode-links">{fm.links(f(links.r1), f(links.r2), f(links.r3), f(links.r4))}</p>
      <p>{fm.typeLine(t.types[fd.type])}</p>
      <p>{fm.branchLine(branch === 'open' ? t.branchOpen : t.branchCrossed)}</p>
      <p data-testid="function-max-error" data-value={maxError}>
        {fm.maxError(formatNumber(maxError, 3), formatNumber(percent, 3))}
      </p>
      <h4 className="synmode-subtitle">{fm.defectsTitle}</h4>
      {defects.length ? (
        <ul className="synmode-defects" data-testid="function-defects">
          {defects.map((d) => (
            <li key={d} data-defect={d}>
              {fm.defectWords[d]}
            </li>
          ))}
        </ul>
      ) : (
        <p className="synmode-ok" data-testid="function-defects">
          {fm.noDefects}
        </p>
      )}
    </div>
  );
}
